using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class FrustumGeometryTests
    {
        const double Tolerance = 1e-12;

        static void AssertPoint(Vector3d actual, double x, double y, double z, string what)
        {
            Assert.That(actual.X, Is.EqualTo(x).Within(Tolerance), what + ".x");
            Assert.That(actual.Y, Is.EqualTo(y).Within(Tolerance), what + ".y");
            Assert.That(actual.Z, Is.EqualTo(z).Within(Tolerance), what + ".z");
        }

        [Test]
        public void IdentityCameraLooksAlongPlusZWithTheImageProportions()
        {
            // vfov 90° → half-height = length·tan 45° = 1; aspect 2 → half-width 2; rectangle at z = 1.
            var pose = new UnityPose(Vector3d.Zero, Quaterniond.Identity);
            var c = FrustumGeometry.FarCorners(pose, 90, 2, 1);
            AssertPoint(c[0], -2, 1, 1, "top-left");
            AssertPoint(c[1], 2, 1, 1, "top-right");
            AssertPoint(c[2], 2, -1, 1, "bottom-right");
            AssertPoint(c[3], -2, -1, 1, "bottom-left");
        }

        [Test]
        public void CameraOnPlusXLookingAtTheOriginHasItsRectangleTowardsTheOrigin()
        {
            // LookAt at azimuth 0, elevation 0, distance 4: position (4, 0, 0), forward −X, up +Y,
            // right = (−sin a, 0, cos a) = +Z. vfov 60°, aspect 1, length 0.5: half-size 0.5·tan 30° = 0.5/√3.
            var pose = LookAt.FromDirection(Vector3d.Zero, new SphericalDirection(0, 0), 4);
            var h = 0.5 / Math.Sqrt(3);
            var c = FrustumGeometry.FarCorners(pose, 60, 1, 0.5);
            AssertPoint(c[0], 3.5, h, -h, "top-left");
            AssertPoint(c[1], 3.5, h, h, "top-right");
            AssertPoint(c[2], 3.5, -h, h, "bottom-right");
            AssertPoint(c[3], 3.5, -h, -h, "bottom-left");
        }

        [Test]
        public void SegmentsJoinTheApexToEachCornerThenRingTheRectangleThenMarkUp()
        {
            var pose = new UnityPose(new Vector3d(1, 2, 3), Quaterniond.Identity);
            var points = new Vector3d[FrustumGeometry.PointsPerCamera + 3];
            FrustumGeometry.WriteSegments(pose, 90, 1, 2, points, 3);
            // vfov 90°, length 2 → half-size 2; rectangle at z = 3 + 2 = 5 around (1, 2).
            Assert.That(points[0], Is.EqualTo(default(Vector3d)), "nothing written before the offset");
            AssertPoint(points[3], 1, 2, 3, "apex");
            AssertPoint(points[4], -1, 4, 5, "top-left");
            AssertPoint(points[3 + 8], -1, 4, 5, "top edge starts top-left");
            AssertPoint(points[3 + 9], 3, 4, 5, "top edge ends top-right");
            AssertPoint(points[3 + 15], -1, 4, 5, "left edge closes at top-left");
            // Up triangle: quarter points of the top edge (x = 0 and 2) to a tip 0.5·half-height = 1 above its middle.
            AssertPoint(points[3 + 16], 0, 4, 5, "triangle left");
            AssertPoint(points[3 + 17], 1, 5, 5, "triangle tip");
            AssertPoint(points[3 + 18], 1, 5, 5, "triangle tip again");
            AssertPoint(points[3 + 19], 2, 4, 5, "triangle right");
        }

        [TestCase(0, 1, 1, "verticalFovDegrees")]
        [TestCase(180, 1, 1, "verticalFovDegrees")]
        [TestCase(double.NaN, 1, 1, "verticalFovDegrees")]
        [TestCase(60, 0, 1, "aspect")]
        [TestCase(60, double.PositiveInfinity, 1, "aspect")]
        [TestCase(60, 1, -1, "length")]
        public void OutOfRangeInputsNameTheField(double fov, double aspect, double length, string field)
        {
            var pose = new UnityPose(Vector3d.Zero, Quaterniond.Identity);
            var e = Assert.Throws<InvalidParameterException>(() => FrustumGeometry.FarCorners(pose, fov, aspect, length));
            Assert.That(e.Problems, Has.Count.EqualTo(1));
            Assert.That(e.Problems[0].Field, Is.EqualTo(field));
        }

        [Test]
        public void WritingPastTheEndOfTheDestinationIsRefused()
        {
            var pose = new UnityPose(Vector3d.Zero, Quaterniond.Identity);
            Assert.Throws<ArgumentOutOfRangeException>(() =>
                FrustumGeometry.WriteSegments(pose, 60, 1, 1, new Vector3d[FrustumGeometry.PointsPerCamera], 1));
        }

        [TestCase(4.0, 0.5)]
        [TestCase(0.0, 1.0)]
        [TestCase(double.NaN, 1.0)]
        public void SuggestedLengthIsAnEighthOfTheDistance(double distance, double expected)
        {
            Assert.That(FrustumGeometry.SuggestedLength(distance), Is.EqualTo(expected));
        }
    }
}
