using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class SurfaceSamplerTests
    {
        // Two triangles in the z = 0 plane with areas 0.5 and 1.5 (ratio 1:3), and a third, separate mesh.
        static readonly Vector3d[] Vertices =
        {
            new Vector3d(0, 0, 0), new Vector3d(1, 0, 0), new Vector3d(0, 1, 0),      // area 0.5
            new Vector3d(2, 0, 0), new Vector3d(5, 0, 0), new Vector3d(2, 1, 0),      // area 1.5
        };

        static SurfaceMesh TwoTriangles(Vector3d[] triangleColors = null, Vector3d[] normals = null, Vector3d[] colors = null) =>
            new SurfaceMesh(Vertices, new[] { 0, 1, 2, 3, 4, 5 }, normals, colors, triangleColors);

        [Test]
        public void AreaWeighting_GivesOneToThreeWithinFiveBinomialSigmas()
        {
            const int n = 40000;
            var points = SurfaceSampler.Sample(new[] { TwoTriangles() }, n, 11);

            var onSmall = points.Count(p => p.Position.X < 1.5);
            // Binomial(n, 1/4): mean 10000, σ = √(n·p·(1−p)) = √7500 ≈ 86.6.
            var sigma = Math.Sqrt(n * 0.25 * 0.75);
            Assert.That(onSmall, Is.EqualTo(n / 4).Within(5 * sigma));
        }

        [Test]
        public void PointsAreUniformInsideATriangle()
        {
            // The midpoint triangle of the unit right triangle holds a quarter of its area.
            const int n = 20000;
            var mesh = new SurfaceMesh(Vertices.Take(3).ToArray(), new[] { 0, 1, 2 });
            var points = SurfaceSampler.Sample(new[] { mesh }, n, 5);

            var inMiddle = points.Count(p => p.Position.X < 0.5 && p.Position.Y < 0.5 && p.Position.X + p.Position.Y > 0.5);
            Assert.That(inMiddle, Is.EqualTo(n / 4).Within(5 * Math.Sqrt(n * 0.25 * 0.75)));
        }

        [Test]
        public void EveryPointLiesOnATriangle()
        {
            foreach (var p in SurfaceSampler.Sample(new[] { TwoTriangles() }, 5000, 1))
            {
                Assert.That(p.Position.Z, Is.EqualTo(0.0));
                var x = p.Position.X;
                var y = p.Position.Y;
                var onSmall = x >= 0 && y >= 0 && x + y <= 1 + 1e-12;
                var onLarge = x >= 2 && y >= 0 && (x - 2) / 3 + y <= 1 + 1e-12;
                Assert.That(onSmall || onLarge, Is.True, p.Position.ToString());
            }
        }

        [Test]
        public void CountAndSeed_AreHonoured()
        {
            var meshes = new[] { TwoTriangles() };
            var a = SurfaceSampler.Sample(meshes, 1234, 42);
            var b = SurfaceSampler.Sample(meshes, 1234, 42);
            var c = SurfaceSampler.Sample(meshes, 1234, 43);

            Assert.That(a.Count, Is.EqualTo(1234));
            Assert.That(a.Select(p => p.Position), Is.EqualTo(b.Select(p => p.Position)));
            Assert.That(a.Select(p => p.Position), Is.Not.EqualTo(c.Select(p => p.Position)));
            Assert.That(SurfaceSampler.Sample(meshes, 0, 42), Is.Empty);
        }

        [Test]
        public void TriangleColours_AndDefaultNormals()
        {
            var mesh = TwoTriangles(triangleColors: new[] { new Vector3d(1, 0, 0), new Vector3d(0, 0, 1) });

            foreach (var p in SurfaceSampler.Sample(new[] { mesh }, 500, 2))
            {
                var small = p.Position.X < 1.5;
                Assert.That(new[] { p.Red, p.Green, p.Blue }, Is.EqualTo(small ? new byte[] { 255, 0, 0 } : new byte[] { 0, 0, 255 }));
                Assert.That(p.Normal, Is.EqualTo(Vector3d.Zero), "unknown normals are zero, as in 3DGS's own file");
            }
        }

        [Test]
        public void VertexNormalsAndColours_AreInterpolated()
        {
            var normals = new[] { Vector3d.UnitZ, Vector3d.UnitZ, Vector3d.UnitZ, Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ };
            var colors = new[] { new Vector3d(0, 0, 0), new Vector3d(1, 0, 0), new Vector3d(0, 1, 0), Vector3d.Zero, Vector3d.Zero, Vector3d.Zero };
            var mesh = TwoTriangles(normals: normals, colors: colors);

            foreach (var p in SurfaceSampler.Sample(new[] { mesh }, 500, 3))
            {
                Assert.That(p.Normal.Length, Is.EqualTo(1.0).Within(1e-12));
                if (p.Position.X >= 1.5) continue;
                // On the unit triangle the barycentric weights of vertices 1 and 2 are x and y themselves.
                Assert.That(p.Normal, Is.EqualTo(Vector3d.UnitZ));
                Assert.That((int)p.Red, Is.EqualTo((int)CloudPoint.ToByte(p.Position.X)));
                Assert.That((int)p.Green, Is.EqualTo((int)CloudPoint.ToByte(p.Position.Y)));
            }
        }

        [Test]
        public void SeveralMeshes_ShareOneAreaBudget()
        {
            var small = new SurfaceMesh(Vertices.Take(3).ToArray(), new[] { 0, 1, 2 }, name: "small");
            var large = new SurfaceMesh(Vertices.Skip(3).ToArray(), new[] { 0, 1, 2 }, name: "large");
            const int n = 40000;

            var onSmall = SurfaceSampler.Sample(new[] { small, large }, n, 9).Count(p => p.Position.X < 1.5);

            Assert.That(onSmall, Is.EqualTo(n / 4).Within(5 * Math.Sqrt(n * 0.25 * 0.75)));
        }

        [Test]
        public void BadMeshes_NameTheField()
        {
            var e = Assert.Throws<InvalidParameterException>(() => new SurfaceMesh(Vertices, new[] { 0, 1, 6 }, name: "Body"));
            Assert.That(e.Problems[0].Field, Is.EqualTo("Body.triangles[2]"));

            e = Assert.Throws<InvalidParameterException>(() => new SurfaceMesh(Vertices, new[] { 0, 1 }));
            Assert.That(e.Problems[0].Field, Is.EqualTo("mesh.triangles"));

            var flat = new SurfaceMesh(new[] { Vector3d.Zero, Vector3d.UnitX, 2 * Vector3d.UnitX }, new[] { 0, 1, 2 });
            e = Assert.Throws<InvalidParameterException>(() => SurfaceSampler.Sample(new[] { flat }, 10, 1));
            Assert.That(e.Problems[0].Field, Is.EqualTo("pointCloud.meshes"));

            e = Assert.Throws<InvalidParameterException>(() => SurfaceSampler.Sample(new[] { TwoTriangles() }, -1, 1));
            Assert.That(e.Problems[0].Field, Is.EqualTo("pointCloud.count"));
        }

        [Test]
        public void FromUnityWorld_MovesPointsIntoTheNormalisedOutputFrame()
        {
            var n = new SceneNormalisation(new Vector3d(1, 2, 3), 2);
            var p = new CloudPoint(new Vector3d(1, 3, 2), new Vector3d(0, 1, 0), 1, 2, 3);

            var moved = p.FromUnityWorld(n);

            Assert.That(moved.Position, Is.EqualTo(Vector3d.Zero), "Unity (1, 3, 2) is Blender (1, 2, 3), the centre");
            Assert.That(moved.Normal, Is.EqualTo(new Vector3d(0, 0, 1)), "Unity up is Blender +Z");
            Assert.That(new[] { moved.Red, moved.Green, moved.Blue }, Is.EqualTo(new byte[] { 1, 2, 3 }));
        }
    }
}
