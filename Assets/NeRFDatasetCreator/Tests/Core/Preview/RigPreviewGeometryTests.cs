using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class RigPreviewGeometryTests
    {
        [Test]
        public void MarkersListTrainThenValThenTestWithTheirSplitIndices()
        {
            var train = CameraRig.Place(new HaloFormation(), 3, Vector3d.Zero, 4);
            var test = CameraRig.Place(new HaloFormation(30), 2, Vector3d.Zero, 4);
            var geometry = RigPreviewGeometry.Build(train, null, test, 40, 1, 0.5);

            Assert.That(geometry.Markers, Has.Count.EqualTo(5));
            Assert.That(geometry.Markers[2].Split, Is.EqualTo(PreviewSplit.Train));
            Assert.That(geometry.Markers[2].Index, Is.EqualTo(2));
            Assert.That(geometry.Markers[3].Split, Is.EqualTo(PreviewSplit.Test));
            Assert.That(geometry.Markers[3].Index, Is.EqualTo(0));
            Assert.That(geometry.Markers[4].Label, Is.EqualTo("test r_1"));
            // Halo camera 1 of 3 at azimuth 120°: (4 cos 120°, 0, 4 sin 120°) = (−2, 0, 2√3).
            Assert.That(geometry.Markers[1].Position.X, Is.EqualTo(-2).Within(1e-12));
            Assert.That(geometry.Markers[1].Position.Z, Is.EqualTo(2 * System.Math.Sqrt(3)).Within(1e-12));
        }

        [Test]
        public void EachSplitHasTwentyPointsPerCameraStartingAtItsPosition()
        {
            var train = CameraRig.Place(new SphereFormation(), 7, new Vector3d(1, 1, 1), 3);
            var geometry = RigPreviewGeometry.Build(train, null, null, 40, 1.5, 0.3);

            Assert.That(geometry.Segments(PreviewSplit.Train), Has.Count.EqualTo(7 * 20));
            Assert.That(geometry.Segments(PreviewSplit.Val), Is.Empty);
            Assert.That(geometry.Segments(PreviewSplit.Test), Is.Empty);
            for (var i = 0; i < 7; i++)
                Assert.That(geometry.Segments(PreviewSplit.Train)[i * 20], Is.EqualTo(train[i].Position), "camera " + i);
        }

        [Test]
        public void EveryRectangleCornerIsAtTheDisplayLengthOverTheCosineOfItsOffAxisAngle()
        {
            // The corner is at (±w, ±h, L) in camera space, so its distance from the apex is √(w² + h² + L²).
            var poses = CameraRig.Place(new RandomFormation(7), 5, Vector3d.Zero, 2);
            double fov = 50, aspect = 4.0 / 3.0, length = 0.25;
            var h = length * System.Math.Tan(fov * System.Math.PI / 360);
            var expected = System.Math.Sqrt(h * h + h * aspect * h * aspect + length * length);
            var segments = RigPreviewGeometry.Build(null, poses, null, fov, aspect, length).Segments(PreviewSplit.Val);
            for (var c = 0; c < 5; c++)
                for (var k = 0; k < 4; k++)
                    Assert.That(Vector3d.Distance(segments[c * 20 + 2 * k], segments[c * 20 + 2 * k + 1]), Is.EqualTo(expected).Within(1e-12));
        }
    }
}
