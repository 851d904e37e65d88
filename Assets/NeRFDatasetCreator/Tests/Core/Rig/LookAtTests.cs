using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class LookAtTests
    {
        [Test]
        public void MatchesUnitysLookRotationBasisAwayFromThePoles()
        {
            // Quaternion.LookRotation(forward, up) (Unity docs): +Z → forward, right = normalise(up × forward),
            // up' = forward × right. Checked on the basis vectors, independently of the quaternion maths.
            var random = new SeededRandom(3);
            for (var i = 0; i < 500; i++)
            {
                var target = new Vector3d(random.NextDouble() * 4 - 2, random.NextDouble() * 4 - 2, random.NextDouble() * 4 - 2);
                var position = new Vector3d(random.NextDouble() * 20 - 10, random.NextDouble() * 20 - 10, random.NextDouble() * 20 - 10);
                var pose = LookAt.FromPositions(position, target);

                var forward = (target - position).Normalized();
                var right = Vector3d.Cross(Vector3d.UnitY, forward).Normalized();
                var up = Vector3d.Cross(forward, right);
                Assert.That(Vector3d.Distance(pose.Rotation.Forward, forward), Is.LessThan(1e-12));
                Assert.That(Vector3d.Distance(pose.Rotation.Right, right), Is.LessThan(1e-12));
                Assert.That(Vector3d.Distance(pose.Rotation.Up, up), Is.LessThan(1e-12));
                Assert.That(pose.Position, Is.EqualTo(position));
            }
        }

        [TestCase(90.0)]
        [TestCase(-90.0)]
        public void AtAPoleTheRollIsTheLimitAlongTheDirectionsAzimuth(double elevation)
        {
            foreach (var azimuth in new[] { 0.0, 37.0, 135.0, 270.0 })
            {
                var onPole = LookAt.FromDirection(Vector3d.Zero, SphericalDirection.FromDegrees(azimuth, elevation), 3);
                var nearPole = LookAt.FromDirection(Vector3d.Zero, SphericalDirection.FromDegrees(azimuth, elevation - Math.Sign(elevation) * 1e-6), 3);
                Assert.That(Vector3d.Distance(onPole.Rotation.Up, nearPole.Rotation.Up), Is.LessThan(1e-6), "continuous with its neighbour");
                Assert.That(Vector3d.Distance(onPole.Rotation.Forward, new Vector3d(0, -Math.Sign(elevation), 0)), Is.LessThan(1e-15));
                Assert.That(onPole.Rotation.Forward.IsFinite && onPole.Rotation.Up.IsFinite, Is.True);
            }
        }

        [Test]
        public void ACameraStraightAboveItsTargetGetsTheRollOfAzimuthZero()
        {
            var pose = LookAt.FromPositions(new Vector3d(1, 5, 1), new Vector3d(1, 0, 1));
            // Limit of up = (−sin e·cos a, cos e, −sin e·sin a) at e = 90°, a = 0: (−1, 0, 0).
            Assert.That(Vector3d.Distance(pose.Rotation.Up, new Vector3d(-1, 0, 0)), Is.LessThan(1e-15));
            Assert.That(Vector3d.Distance(pose.Rotation.Forward, new Vector3d(0, -1, 0)), Is.LessThan(1e-15));
            Assert.That(BlenderConvention.CameraToWorld(pose).Determinant3x3, Is.EqualTo(1).Within(1e-12));
        }

        [Test]
        public void ACameraAtItsTargetIsAnError()
        {
            Assert.Throws<ArgumentException>(() => LookAt.FromPositions(new Vector3d(1, 2, 3), new Vector3d(1, 2, 3)));
        }

        [Test]
        public void SphericalDirectionsRoundTripThroughVectors()
        {
            var direction = SphericalDirection.FromDegrees(123, -40);
            var back = SphericalDirection.FromUnityVector(direction.ToUnityVector() * 7);
            Assert.That(back.AzimuthRadians, Is.EqualTo(direction.AzimuthRadians).Within(1e-12));
            Assert.That(back.ElevationRadians, Is.EqualTo(direction.ElevationRadians).Within(1e-12));
        }

        [Test]
        public void AzimuthRunsCounterClockwiseSeenFromAboveInTheOutputWorld()
        {
            // Azimuth 90° is Unity +Z, which is Blender +Y: a quarter turn counter-clockwise from +X about +Z.
            var output = BlenderConvention.FromUnity(SphericalDirection.FromDegrees(90, 0).ToUnityVector());
            Assert.That(Vector3d.Distance(output, new Vector3d(0, 1, 0)), Is.LessThan(1e-15));
        }
    }
}
