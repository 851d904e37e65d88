using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class PoseInterpolationTests
    {
        [Test]
        public void HalfWayFromIdentityToAQuarterTurnIsAnEighthTurnAboutTheSameAxis()
        {
            // By hand: a rotation of θ about Y is (0, sin θ/2, 0, cos θ/2); half of 90° is 45°.
            var quarter = new Quaterniond(0, Math.Sin(Math.PI / 4), 0, Math.Cos(Math.PI / 4));
            var half = PoseInterpolation.Slerp(Quaterniond.Identity, quarter, 0.5);
            Assert.That(half.X, Is.EqualTo(0).Within(1e-15));
            Assert.That(half.Y, Is.EqualTo(Math.Sin(Math.PI / 8)).Within(1e-15));
            Assert.That(half.Z, Is.EqualTo(0).Within(1e-15));
            Assert.That(half.W, Is.EqualTo(Math.Cos(Math.PI / 8)).Within(1e-15));
            // A quarter of the way: 22.5°, so +Z turns to (sin 22.5°, 0, cos 22.5°).
            var forward = PoseInterpolation.Slerp(Quaterniond.Identity, quarter, 0.25).Forward;
            Assert.That(Vector3d.Distance(forward, new Vector3d(Math.Sin(Math.PI / 8), 0, Math.Cos(Math.PI / 8))), Is.LessThan(1e-15));
        }

        [Test]
        public void TheShorterArcIsTakenWhateverTheQuaternionsSign()
        {
            var quarter = new Quaterniond(0, Math.Sin(Math.PI / 4), 0, Math.Cos(Math.PI / 4));
            var negated = new Quaterniond(0, -quarter.Y, 0, -quarter.W); // the same rotation
            var a = PoseInterpolation.Slerp(Quaterniond.Identity, quarter, 0.5).Forward;
            var b = PoseInterpolation.Slerp(Quaterniond.Identity, negated, 0.5).Forward;
            Assert.That(Vector3d.Distance(a, b), Is.LessThan(1e-15));
        }

        [Test]
        public void PositionsAreLinearAndTheEndsAreExact()
        {
            var a = new UnityPose(new Vector3d(1, 2, 3), Quaterniond.AngleAxis(10, new Vector3d(1, 1, 0)));
            var b = new UnityPose(new Vector3d(5, -2, 3), Quaterniond.AngleAxis(70, new Vector3d(0, 1, 1)));
            Assert.That(PoseInterpolation.Lerp(a, b, 0.25).Position, Is.EqualTo(new Vector3d(2, 1, 3)));
            Assert.That(Vector3d.Distance(PoseInterpolation.Lerp(a, b, 0).Rotation.Forward, a.Rotation.Forward), Is.LessThan(1e-15));
            Assert.That(Vector3d.Distance(PoseInterpolation.Lerp(a, b, 1).Rotation.Forward, b.Rotation.Forward), Is.LessThan(1e-15));
        }

        [Test]
        public void RotationVectorsRoundTripAndTheWrittenMatricesKeepDeterminantPlusOne()
        {
            var random = new SeededRandom(11);
            for (var i = 0; i < 200; i++)
            {
                var w = new Vector3d(random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1) * 1.8; // |ω| < π: the rotation vector of angle in [0, π]
                var back = PoseInterpolation.ToRotationVector(PoseInterpolation.FromRotationVector(w));
                Assert.That(Vector3d.Distance(back, w), Is.LessThan(1e-12));
                var a = new UnityPose(Vector3d.Zero, PoseInterpolation.FromRotationVector(w));
                var b = new UnityPose(Vector3d.UnitX, PoseInterpolation.FromRotationVector(w * -0.3));
                var m = BlenderConvention.CameraToWorld(PoseInterpolation.Lerp(a, b, random.NextDouble()));
                Assert.That(m.Determinant3x3, Is.EqualTo(1).Within(1e-12));
            }
        }

        [Test]
        public void ACentredIntervalHasThePlannedPoseInTheMiddle()
        {
            var mid = new UnityPose(new Vector3d(0, 1, -4), Quaterniond.AngleAxis(30, Vector3d.UnitY));
            var motion = ShutterMotion.Centred(mid, new Vector3d(0.2, 0, 0), new Vector3d(0, 0.1, 0), SceneNormalisation.Identity, 1.0, 1.5);
            var half = motion.At(0.5);
            Assert.That(Vector3d.Distance(half.Position, mid.Position), Is.LessThan(1e-15));
            Assert.That(Vector3d.Distance(half.Rotation.Forward, mid.Rotation.Forward), Is.LessThan(1e-15));
            Assert.That(motion.Start.Position, Is.EqualTo(new Vector3d(-0.1, 1, -4)));
            Assert.That(motion.End.Position, Is.EqualTo(new Vector3d(0.1, 1, -4)));
            // The start and end are 0.1 rad apart about Y: 30° ∓ 0.05 rad.
            Assert.That(Vector3d.AngleBetween(motion.Start.Rotation.Forward, motion.End.Rotation.Forward), Is.EqualTo(0.1).Within(1e-14));
            Assert.That(motion.SecondsAt(0.5), Is.EqualTo(1.25));
        }
    }
}
