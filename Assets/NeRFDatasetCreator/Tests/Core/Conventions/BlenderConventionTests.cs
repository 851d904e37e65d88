using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class BlenderConventionTests
    {
        [Test]
        public void UnityPointsMapToBlenderByTheYZSwap()
        {
            var output = BlenderConvention.FromUnity(new Vector3d(1, 2, 3));
            Assert.That(output, Is.EqualTo(new Vector3d(1, 3, 2)));
            Assert.That(BlenderConvention.ToUnity(output), Is.EqualTo(new Vector3d(1, 2, 3)));
        }

        [Test]
        public void AnUnrotatedUnityCameraBehindTheOriginHasTheHandDerivedMatrix()
        {
            // Unity camera at (0, 0, −4) with identity rotation looks along +Z at the origin, up +Y.
            // In Blender's world it sits at (0, −4, 0), looks along +Y with up +Z, so its OpenGL axes are
            // x = (1, 0, 0), y = (0, 0, 1), z = −forward = (0, −1, 0).
            var matrix = BlenderConvention.CameraToWorld(new UnityPose(new Vector3d(0, 0, -4), Quaterniond.Identity));
            var expected = new[]
            {
                new[] { 1.0, 0, 0, 0 },
                new[] { 0.0, 0, -1, -4 },
                new[] { 0.0, 1, 0, 0 },
                new[] { 0.0, 0, 0, 1 },
            };
            AssertMatrix(matrix, expected, 1e-15);
        }

        [Test]
        public void AUnityCameraTurnedToLookDownWorldXHasTheHandDerivedMatrix()
        {
            // Rotating +90° about Unity's +Y turns +Z (forward) into +X and +X (right) into −Z (left-handed frame).
            // Output: forward (1, 0, 0), right (0, −1, 0), up (0, 0, 1) ⇒ columns x = (0, −1, 0), y = (0, 0, 1), z = (−1, 0, 0).
            var pose = new UnityPose(new Vector3d(-3, 1, 0), Quaterniond.AngleAxis(90, Vector3d.UnitY));
            var expected = new[]
            {
                new[] { 0.0, 0, -1, -3 },
                new[] { -1.0, 0, 0, 0 },
                new[] { 0.0, 1, 0, 1 },
                new[] { 0.0, 0, 0, 1 },
            };
            AssertMatrix(BlenderConvention.CameraToWorld(pose), expected, 1e-15);
        }

        [Test]
        public void UnitysCameraToWorldIsMirroredAndTheOutputIsAProperRotation()
        {
            var random = new SeededRandom(7);
            for (var i = 0; i < 1000; i++)
            {
                var pose = LookAt.FromPositions(
                    new Vector3d(random.NextDouble() * 10 - 5, random.NextDouble() * 10 - 5, random.NextDouble() * 10 - 5),
                    new Vector3d(random.NextDouble(), random.NextDouble(), random.NextDouble()));
                Assert.That(pose.CameraToWorld.Determinant3x3, Is.EqualTo(-1).Within(1e-12), "Unity's world is left-handed");
                Assert.That(BlenderConvention.CameraToWorld(pose).Determinant3x3, Is.EqualTo(1).Within(1e-12));
            }
        }

        [Test]
        public void TheOutputMatrixIsThePermutationTimesUnitysCameraToWorld()
        {
            // M = P₄·C: rows 0, 2, 1, 3 of Unity's cameraToWorldMatrix (reference §1.6).
            var pose = LookAt.FromPositions(new Vector3d(2, 3, -1), new Vector3d(0.5, 0, 0.25));
            var unity = pose.CameraToWorld;
            var output = BlenderConvention.CameraToWorld(pose);
            var rowOrder = new[] { 0, 2, 1, 3 };
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++)
                    Assert.That(output[r, c], Is.EqualTo(unity[rowOrder[r], c]).Within(1e-15));
        }

        [Test]
        public void ToUnityPoseInvertsCameraToWorld()
        {
            var pose = new UnityPose(new Vector3d(1, -2, 3), Quaterniond.AngleAxis(37, new Vector3d(1, 2, -0.5)));
            var back = BlenderConvention.ToUnityPose(BlenderConvention.CameraToWorld(pose));
            Assert.That(Vector3d.Distance(back.Position, pose.Position), Is.LessThan(1e-12));
            Assert.That(Vector3d.Distance(back.Rotation.Forward, pose.Rotation.Forward), Is.LessThan(1e-12));
            Assert.That(Vector3d.Distance(back.Rotation.Up, pose.Rotation.Up), Is.LessThan(1e-12));
        }

        static void AssertMatrix(Matrix4x4d actual, double[][] expected, double tolerance)
        {
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++)
                    Assert.That(actual[r, c], Is.EqualTo(expected[r][c]).Within(tolerance), $"[{r}][{c}]");
        }
    }
}
