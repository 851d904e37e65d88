using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class RigPreviewPlyTests
    {
        static CapturePlan Plan()
        {
            var s = new DatasetSettings();
            s.Train.Count = 3;
            s.Val.Count = 2;
            s.Test.Count = 1;
            return CapturePlan.Build(s, PlanTarget.AtOrigin);
        }

        /// <summary>The file read back as the PLY spec says (header lines to "end_header\n", then little-endian records), independently of the writer.</summary>
        sealed class Parsed
        {
            public List<string> Header = new List<string>();
            public List<(Vector3d p, string rgb)> Vertices = new List<(Vector3d, string)>();
            public List<(int a, int b, string rgb)> Edges = new List<(int, int, string)>();
            public long Trailing;

            public static Parsed Of(byte[] bytes)
            {
                var parsed = new Parsed();
                var text = Encoding.ASCII.GetString(bytes, 0, System.Math.Min(bytes.Length, 4096));
                var end = text.IndexOf("end_header\n", System.StringComparison.Ordinal) + "end_header\n".Length;
                parsed.Header = text.Substring(0, end - 1).Split('\n').ToList();
                int Count(string element) => int.Parse(parsed.Header.Single(l => l.StartsWith("element " + element + " ")).Split(' ')[2]);
                using (var reader = new BinaryReader(new MemoryStream(bytes, end, bytes.Length - end)))
                {
                    for (var i = 0; i < Count("vertex"); i++)
                        parsed.Vertices.Add((new Vector3d(reader.ReadSingle(), reader.ReadSingle(), reader.ReadSingle()), reader.ReadByte() + " " + reader.ReadByte() + " " + reader.ReadByte()));
                    for (var i = 0; i < Count("edge"); i++)
                        parsed.Edges.Add((reader.ReadInt32(), reader.ReadInt32(), reader.ReadByte() + " " + reader.ReadByte() + " " + reader.ReadByte()));
                    parsed.Trailing = reader.BaseStream.Length - reader.BaseStream.Position;
                }
                return parsed;
            }
        }

        [Test]
        public void HeaderDeclaresBinaryLittleEndianVerticesWithColoursAndEdges()
        {
            var bytes = RigPreviewPly.Encode(Plan());
            var ply = Parsed.Of(bytes);
            Assert.That(ply.Header[0], Is.EqualTo("ply"));
            Assert.That(ply.Header[1], Is.EqualTo("format binary_little_endian 1.0"));
            // 1 target vertex + 5 per camera (centre and 4 image corners); 8 edges per camera (4 sides, 4 rays).
            Assert.That(ply.Header, Does.Contain("element vertex " + (1 + 5 * 6)));
            Assert.That(ply.Header, Does.Contain("element edge " + 8 * 6));
            Assert.That(ply.Header, Is.SupersetOf(new[] { "property float x", "property float y", "property float z", "property uchar red", "property uchar green", "property uchar blue", "property int vertex1", "property int vertex2" }));
            Assert.That(ply.Trailing, Is.EqualTo(0), "the body is exactly the declared records");
            var headerLength = bytes.Length - (31 * RigPreviewPly.BytesPerVertex + 48 * RigPreviewPly.BytesPerEdge);
            Assert.That(Encoding.ASCII.GetString(bytes, headerLength - 11, 11), Is.EqualTo("end_header\n"));
            // The first vertex (the target at the origin): three little-endian float zeros, then white.
            Assert.That(bytes.Skip(headerLength).Take(15).ToArray(), Is.EqualTo(new byte[] { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 255, 255, 255 }));
        }

        [Test]
        public void BodyMatchesTheHeaderAndTheCameraCentres()
        {
            var plan = Plan();
            var ply = Parsed.Of(RigPreviewPly.Encode(plan));
            Assert.That(ply.Vertices, Has.Count.EqualTo(31));
            Assert.That(ply.Edges, Has.Count.EqualTo(48));
            Assert.That(ply.Vertices[0].rgb, Is.EqualTo("255 255 255"));
            // Vertex 1 is train camera 0's centre, vertex 16 (1 + 5·3) val camera 0's centre.
            var t = plan.Views[0].TransformMatrix.Translation;
            Assert.That(ply.Vertices[1].p.X, Is.EqualTo(t.X).Within(1e-6));
            Assert.That(ply.Vertices[1].p.Y, Is.EqualTo(t.Y).Within(1e-6));
            Assert.That(ply.Vertices[1].p.Z, Is.EqualTo(t.Z).Within(1e-6));
            Assert.That(ply.Vertices[1].rgb, Is.EqualTo("86 180 233"), "train: Okabe–Ito sky blue, as the Scene-view preview");
            Assert.That(ply.Vertices[16].rgb, Is.EqualTo("230 159 0"), "val: orange");
            Assert.That(ply.Vertices[26].rgb, Is.EqualTo("204 121 167"), "test: reddish purple");
            // The first edge joins train camera 0's centre to its first image corner.
            Assert.That(ply.Edges[0], Is.EqualTo((1, 2, "86 180 233")));
            foreach (var edge in ply.Edges)
                Assert.That(edge.a >= 0 && edge.a < 31 && edge.b >= 0 && edge.b < 31, Is.True, edge.ToString());
        }

        [Test]
        public void FrustumCornersLieInFrontOfTheCamera()
        {
            var plan = Plan();
            var ply = Parsed.Of(RigPreviewPly.Encode(plan));
            var m = plan.Views[0].TransformMatrix;
            var forward = -m.Column(2);
            for (var k = 2; k <= 5; k++)
                Assert.That(Vector3d.Dot(ply.Vertices[k].p - m.Translation, forward), Is.EqualTo(RigPreviewPly.FrustumDepthFraction * 4).Within(1e-5));
        }

        [Test]
        public void ANormalisedRigIsDrawnInOutputUnits()
        {
            // Distance 10 with the nerf_synthetic preset: s = 0.4, cameras at 4, frusta 0.15·4 deep; without
            // recentring the target marker sits at the target's own output position.
            var s = new DatasetSettings { Distance = 10, Normalisation = NormalisationMode.NerfSyntheticScale };
            s.Train.Count = 1;
            var plan = CapturePlan.Build(s, new PlanTarget(new Vector3d(3, 1, 2), 1));
            var ply = Parsed.Of(RigPreviewPly.Encode(plan));
            Assert.That(ply.Vertices[0].p, Is.EqualTo(new Vector3d(0, 0, 0)));
            var m = plan.Views[0].TransformMatrix;
            Assert.That(Vector3d.Dot(ply.Vertices[2].p - m.Translation, -m.Column(2)), Is.EqualTo(0.6).Within(1e-5));

            s.Normalisation = NormalisationMode.None;
            var raw = Parsed.Of(RigPreviewPly.Encode(CapturePlan.Build(s, new PlanTarget(new Vector3d(3, 1, 2), 1))));
            Assert.That(raw.Vertices[0].p, Is.EqualTo(new Vector3d(3, 2, 1)), "Unity (3, 1, 2) → (3, 2, 1)");
        }

        [Test]
        public void StreamingWritesTheSameBytesAsEncoding()
        {
            var plan = Plan();
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("rig_preview.ply");
                FileOps.WriteStream(path, stream => RigPreviewPly.Write(plan, stream));
                Assert.That(File.ReadAllBytes(path), Is.EqualTo(RigPreviewPly.Encode(plan)));
            }
        }
    }
}
