using System.Globalization;
using System.Linq;
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

        [Test]
        public void HeaderDeclaresAsciiVerticesWithColoursAndEdges()
        {
            var lines = RigPreviewPly.Write(Plan()).Split('\n');
            Assert.That(lines[0], Is.EqualTo("ply"));
            Assert.That(lines[1], Is.EqualTo("format ascii 1.0"));
            // 1 target vertex + 5 per camera (centre and 4 image corners); 8 edges per camera (4 sides, 4 rays).
            Assert.That(lines, Does.Contain("element vertex " + (1 + 5 * 6)));
            Assert.That(lines, Does.Contain("element edge " + 8 * 6));
            Assert.That(lines, Does.Contain("property uchar red"));
            Assert.That(lines, Does.Contain("property int vertex1"));
        }

        [Test]
        public void BodyMatchesTheHeaderAndTheCameraCentres()
        {
            var plan = Plan();
            var lines = RigPreviewPly.Write(plan).Split('\n').ToList();
            var body = lines.Skip(lines.IndexOf("end_header") + 1).Where(l => l.Length > 0).ToList();
            Assert.That(body, Has.Count.EqualTo(31 + 48));
            Assert.That(body[0], Is.EqualTo("0 0 0 255 255 255"));
            // Vertex 1 is train camera 0's centre, vertex 16 (1 + 5·3) val camera 0's centre.
            var v1 = body[1].Split(' ');
            var t = plan.Views[0].TransformMatrix.Translation;
            Assert.That(double.Parse(v1[0], CultureInfo.InvariantCulture), Is.EqualTo(t.X).Within(1e-6));
            Assert.That(double.Parse(v1[1], CultureInfo.InvariantCulture), Is.EqualTo(t.Y).Within(1e-6));
            Assert.That(double.Parse(v1[2], CultureInfo.InvariantCulture), Is.EqualTo(t.Z).Within(1e-6));
            Assert.That(string.Join(" ", v1.Skip(3)), Is.EqualTo("86 180 233"), "train: Okabe–Ito sky blue, as the Scene-view preview");
            Assert.That(string.Join(" ", body[16].Split(' ').Skip(3)), Is.EqualTo("230 159 0"), "val: orange");
            Assert.That(string.Join(" ", body[26].Split(' ').Skip(3)), Is.EqualTo("204 121 167"), "test: reddish purple");
            // The first edge joins train camera 0's centre to its first image corner.
            Assert.That(body[31], Is.EqualTo("1 2 86 180 233"));
            foreach (var edge in body.Skip(31))
                Assert.That(edge.Split(' ').Take(2).Select(int.Parse).All(i => i >= 0 && i < 31), Is.True, edge);
        }

        [Test]
        public void FrustumCornersLieInFrontOfTheCamera()
        {
            var plan = Plan();
            var lines = RigPreviewPly.Write(plan).Split('\n').ToList();
            var body = lines.Skip(lines.IndexOf("end_header") + 1).ToList();
            var m = plan.Views[0].TransformMatrix;
            var forward = -m.Column(2);
            for (var k = 2; k <= 5; k++)
            {
                var p = body[k].Split(' ').Take(3).Select(x => double.Parse(x, CultureInfo.InvariantCulture)).ToArray();
                var offset = new Vector3d(p[0], p[1], p[2]) - m.Translation;
                Assert.That(Vector3d.Dot(offset, forward), Is.EqualTo(RigPreviewPly.FrustumDepthFraction * 4).Within(1e-5));
            }
        }

        [Test]
        public void ANormalisedRigIsDrawnInOutputUnits()
        {
            // Distance 10 with the nerf_synthetic preset: s = 0.4, cameras at 4, frusta 0.15·4 deep; without
            // recentring the target marker sits at the target's own output position.
            var s = new DatasetSettings { Distance = 10, Normalisation = NormalisationMode.NerfSyntheticScale };
            s.Train.Count = 1;
            var plan = CapturePlan.Build(s, new PlanTarget(new Vector3d(3, 1, 2), 1));
            var lines = RigPreviewPly.Write(plan).Split('\n').ToList();
            var body = lines.Skip(lines.IndexOf("end_header") + 1).ToList();
            Assert.That(body[0], Is.EqualTo("0 0 0 255 255 255"));
            var m = plan.Views[0].TransformMatrix;
            var corner = body[2].Split(' ').Take(3).Select(x => double.Parse(x, CultureInfo.InvariantCulture)).ToArray();
            Assert.That(Vector3d.Dot(new Vector3d(corner[0], corner[1], corner[2]) - m.Translation, -m.Column(2)), Is.EqualTo(0.6).Within(1e-5));

            s.Normalisation = NormalisationMode.None;
            var raw = RigPreviewPly.Write(CapturePlan.Build(s, new PlanTarget(new Vector3d(3, 1, 2), 1))).Split('\n').ToList();
            Assert.That(raw[raw.IndexOf("end_header") + 1], Is.EqualTo("3 2 1 255 255 255"), "Unity (3, 1, 2) → (3, 2, 1)");
        }
    }
}
