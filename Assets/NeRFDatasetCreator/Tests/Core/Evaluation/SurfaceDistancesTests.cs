using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The k-d tree, Chamfer and F-score against brute-force nearest neighbours on small clouds.</summary>
    public class SurfaceDistancesTests
    {
        static float[] Cloud(int n, int seed, double scale = 1, double offset = 0)
        {
            var random = new Random(seed);
            var xyz = new float[3 * n];
            for (var i = 0; i < xyz.Length; i++) xyz[i] = (float)(offset + scale * random.NextDouble());
            return xyz;
        }

        static double BruteNearest(float[] cloud, double x, double y, double z)
        {
            var best = double.MaxValue;
            for (var i = 0; i < cloud.Length; i += 3)
            {
                double dx = cloud[i] - x, dy = cloud[i + 1] - y, dz = cloud[i + 2] - z;
                best = Math.Min(best, dx * dx + dy * dy + dz * dz);
            }
            return Math.Sqrt(best);
        }

        [Test]
        public void KdTreeFindsTheSameNearestDistanceAsBruteForce()
        {
            var points = Cloud(3000, 1);
            // Duplicates and a flat sheet stress the median split.
            for (var i = 0; i < 300; i++) { points[3 * i] = 0.5f; points[3 * i + 1] = 0.5f; points[3 * i + 2] = 0.5f; }
            for (var i = 300; i < 900; i++) points[3 * i + 2] = 0.25f;
            var tree = new PointKdTree(points);
            var queries = Cloud(500, 2, 1.4, -0.2);
            for (var q = 0; q < queries.Length; q += 3)
            {
                var d2 = tree.Nearest(queries[q], queries[q + 1], queries[q + 2], out var index);
                Assert.That(Math.Sqrt(d2), Is.EqualTo(BruteNearest(points, queries[q], queries[q + 1], queries[q + 2])).Within(1e-12));
                double dx = (double)points[3 * index] - queries[q], dy = (double)points[3 * index + 1] - queries[q + 1], dz = (double)points[3 * index + 2] - queries[q + 2];
                Assert.That(dx * dx + dy * dy + dz * dz, Is.EqualTo(d2).Within(1e-15), "the index names the nearest point");
            }
        }

        [Test]
        public void ChamferAndFScoreMatchBruteForce()
        {
            var reconstruction = Cloud(700, 3);
            var truth = Cloud(500, 4, 1.1, -0.05);
            var observed = new bool[500];
            for (var i = 0; i < observed.Length; i++) observed[i] = i % 3 != 0;
            const double tau = 0.05;
            var result = SurfaceDistances.Compute(reconstruction, truth, observed, tau);

            var acc = new List<double>();
            for (var i = 0; i < reconstruction.Length; i += 3) acc.Add(BruteNearest(truth, reconstruction[i], reconstruction[i + 1], reconstruction[i + 2]));
            var comp = new List<double>();
            for (var p = 0; p < observed.Length; p++)
                if (observed[p]) comp.Add(BruteNearest(reconstruction, truth[3 * p], truth[3 * p + 1], truth[3 * p + 2]));
            Assert.That(result.Accuracy, Is.EqualTo(acc.Average()).Within(1e-12));
            Assert.That(result.Completeness, Is.EqualTo(comp.Average()).Within(1e-12));
            Assert.That(result.Chamfer, Is.EqualTo((acc.Average() + comp.Average()) / 2).Within(1e-12));
            var precision = acc.Count(d => d < tau) / (double)acc.Count;
            var recall = comp.Count(d => d < tau) / (double)comp.Count;
            Assert.That(result.Precision, Is.EqualTo(precision));
            Assert.That(result.Recall, Is.EqualTo(recall));
            Assert.That(result.FScore, Is.EqualTo(2 * precision * recall / (precision + recall)).Within(1e-15));
            Assert.That(result.ObservedTruthPoints, Is.EqualTo(comp.Count));
            Assert.That(precision, Is.GreaterThan(0).And.LessThan(1), "the threshold cuts through the distances");
        }

        [Test]
        public void ASphereTwoPercentTooLargeIsTwoPercentOff()
        {
            // Analytic: points on radius 1.02 against points on radius 1 — every nearest distance is ≥ 0.02.
            var truth = GeometryEvaluation.ToFloats(SurfaceSampler.Sample(new[] { AnalyticSphereDataset.UvSphere(1, 64, 128) }, 200000, 1));
            var reconstruction = GeometryEvaluation.ToFloats(SurfaceSampler.Sample(new[] { AnalyticSphereDataset.UvSphere(1.02, 64, 128) }, 20000, 2));
            var result = SurfaceDistances.Compute(reconstruction, truth, null, 0.015);
            Assert.That(result.Accuracy, Is.EqualTo(0.02).Within(0.003));
            Assert.That(result.Precision, Is.EqualTo(0), "no point is within 0.015 of the smaller sphere");
            var loose = SurfaceDistances.Compute(reconstruction, truth, null, 0.03);
            Assert.That(loose.Precision, Is.GreaterThan(0.99));
        }
    }

    /// <summary>The geometry pack's mesh PLY and the general PLY / OBJ reader (the NumPy reader: NpyReaderTests).</summary>
    public class GeometryFileTests
    {
        [Test]
        public void TargetMeshPlyRoundTrips()
        {
            using (var temp = new TempFolder())
            {
                var sphere = AnalyticSphereDataset.UvSphere(0.5, 4, 6, "Sphere A");
                var quad = new SurfaceMesh(new[] { new Vector3d(0, 0, 0), new Vector3d(1, 0, 0), new Vector3d(1, 1, 0), new Vector3d(0, 1, 0) }, new[] { 0, 1, 2, 0, 2, 3 }, name: "quad");
                var path = temp.Combine("target_mesh.ply");
                TargetMeshPly.Write(path, new[] { sphere, quad });
                var header = Encoding.ASCII.GetString(File.ReadAllBytes(path).Take(600).ToArray());
                Assert.That(header, Does.Contain("format binary_little_endian 1.0\n"));
                Assert.That(header, Does.Contain("comment object Sphere_A 0 " + sphere.TriangleCount + "\n"));
                Assert.That(header, Does.Contain("comment object quad " + sphere.TriangleCount + " 2\n"));
                Assert.That(header, Does.Contain("property list uchar int vertex_indices\n"));

                var back = GeometryFile.Read(path);
                Assert.That(back.Vertices.Count, Is.EqualTo(sphere.Vertices.Count + 4));
                Assert.That(back.TriangleCount, Is.EqualTo(sphere.TriangleCount + 2));
                for (var i = 0; i < sphere.Vertices.Count; i++)
                {
                    Assert.That((back.Vertices[i] - sphere.Vertices[i]).Length, Is.LessThan(1e-7));
                    Assert.That((back.VertexNormals[i] - sphere.VertexNormals[i]).Length, Is.LessThan(1e-7));
                }
                for (var t = 0; t < sphere.Triangles.Count; t++) Assert.That(back.Triangles[t], Is.EqualTo(sphere.Triangles[t]));
                var offset = sphere.Vertices.Count;
                Assert.That(back.Triangles.Skip(sphere.Triangles.Count), Is.EqualTo(new[] { 0, 1, 2, 0, 2, 3 }.Select(i => i + offset)));
                // The quad had no normals: the writer gives the right-hand-rule normal, +Z for these counter-clockwise faces.
                Assert.That((back.VertexNormals[offset] - Vector3d.UnitZ).Length, Is.LessThan(1e-7));
            }
        }

        [Test]
        public void UnityMeshesKeepTheirFrontFacesInTheOutputFrame()
        {
            // Unity's built-in Quad: faces the −Z camera, triangles 0 3 1 and 3 0 2, normals (0, 0, −1) (clockwise front faces).
            var unity = new SurfaceMesh(
                new[] { new Vector3d(-0.5, -0.5, 0), new Vector3d(0.5, -0.5, 0), new Vector3d(-0.5, 0.5, 0), new Vector3d(0.5, 0.5, 0) },
                new[] { 0, 3, 1, 3, 0, 2 },
                new[] { new Vector3d(0, 0, -1), new Vector3d(0, 0, -1), new Vector3d(0, 0, -1), new Vector3d(0, 0, -1) }, name: "Quad");
            var normalisation = new SceneNormalisation(new Vector3d(1, 2, 3), 2);
            var output = TargetMeshPly.FromUnityWorld(new[] { unity }, normalisation)[0];
            // Normal relabelled: Unity −Z is output −Y.
            Assert.That(output.VertexNormals[0], Is.EqualTo(new Vector3d(0, -1, 0)));
            Assert.That(output.Vertices[3], Is.EqualTo(normalisation.ApplyToUnityPoint(unity.Vertices[3])));
            // The right-hand rule of each output triangle agrees with the relabelled normal.
            for (var t = 0; t < output.Triangles.Count; t += 3)
            {
                var a = output.Vertices[output.Triangles[t]];
                var n = Vector3d.Cross(output.Vertices[output.Triangles[t + 1]] - a, output.Vertices[output.Triangles[t + 2]] - a);
                Assert.That(Vector3d.Dot(n, output.VertexNormals[0]), Is.GreaterThan(0));
            }
        }

        [Test]
        public void PlyReaderReadsAsciiAndBigEndianPointClouds()
        {
            using (var temp = new TempFolder())
            {
                var ascii = temp.Combine("points.ply");
                File.WriteAllText(ascii, "ply\nformat ascii 1.0\ncomment hello\nelement vertex 2\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\nelement camera 1\nproperty float f\nend_header\n1 2 3 255\n-4.5 5e-1 6 0\n7\n");
                var cloud = GeometryFile.Read(ascii);
                Assert.That(cloud.TriangleCount, Is.EqualTo(0));
                Assert.That(cloud.Vertices, Is.EqualTo(new[] { new Vector3d(1, 2, 3), new Vector3d(-4.5, 0.5, 6) }));

                var big = temp.Combine("big.ply");
                var bytes = new List<byte>(Encoding.ASCII.GetBytes("ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n"));
                foreach (var v in new[] { 1.5f, -2f, 0.25f })
                {
                    var b = BitConverter.GetBytes(v);
                    Array.Reverse(b);
                    bytes.AddRange(b);
                }
                File.WriteAllBytes(big, bytes.ToArray());
                Assert.That(GeometryFile.Read(big).Vertices[0], Is.EqualTo(new Vector3d(1.5, -2, 0.25)));
            }
        }

        [Test]
        public void ObjReaderFansPolygonsAndResolvesNegativeIndices()
        {
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("recon.obj");
                File.WriteAllText(path, "# a quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1 4/1\nf -4 -2 -1\n");
                var mesh = GeometryFile.Read(path);
                Assert.That(mesh.Triangles, Is.EqualTo(new[] { 0, 1, 2, 0, 2, 3, 0, 2, 3 }));
                File.WriteAllText(path, "v 0 0 0\nf 1 2 3\n");
                Assert.That(() => GeometryFile.Read(path), Throws.TypeOf<InvalidParameterException>().With.Message.Contains("not defined"));
            }
        }
    }
}
