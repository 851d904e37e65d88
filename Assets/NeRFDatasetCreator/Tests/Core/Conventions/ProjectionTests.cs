using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The arbiter of the conventions: a world point projected by a Unity-convention camera lands on a pixel whose
    /// NeRF ray — built by NeRF's own formula from the written matrix and camera_angle_x — passes through the point.
    /// </summary>
    [TestFixture]
    public class ProjectionTests
    {
        const double Near = 0.05, Far = 1000;

        [Test]
        public void PointsSeenByRandomUnityCamerasLieOnNerfRaysFromTheWrittenMatrix()
        {
            var random = new SeededRandom(20261122);
            var checkedPoints = 0;
            for (var camera = 0; camera < 300; camera++)
            {
                var width = 16 + (int)(random.NextDouble() * 1900);
                var height = 16 + (int)(random.NextDouble() * 1900);
                var vfov = 10 + random.NextDouble() * 110;
                var position = RandomVector(random, 20);
                // Any Unity rotation, roll included — not only look-at poses.
                var rotation = RandomRotation(random);
                var pose = new UnityPose(position, rotation);

                var matrix = BlenderConvention.CameraToWorld(pose).ToRows();
                var cameraAngleX = CameraIntrinsics.FromVerticalFov(vfov, width, height).CameraAngleX;

                for (var p = 0; p < 60; p++)
                {
                    var world = position + RandomVector(random, 30);
                    if (!UnityProjection.TryProject(position, rotation, vfov, width, height, Near, Far, world, out var u, out var v))
                        continue;
                    NerfRays.Ray(matrix, cameraAngleX, width, height, u, v, out var origin, out var direction);
                    var worldOut = BlenderConvention.FromUnity(world);
                    var distance = NerfRays.DistanceToRay(origin, direction, new[] { worldOut.X, worldOut.Y, worldOut.Z }, out var t);
                    var pointDistance = Vector3d.Distance(world, position);
                    Assert.That(t, Is.GreaterThan(0), "the point must be in front of the camera, not behind");
                    Assert.That(distance, Is.LessThan(1e-4 * pointDistance),
                        $"camera {camera}: {width}x{height}, vfov {vfov}, pixel ({u}, {v})");
                    checkedPoints++;
                }
            }
            Assert.That(checkedPoints, Is.GreaterThan(1000), "enough random points must fall inside the views");
        }

        [Test]
        public void TheTargetOfALookAtCameraProjectsToTheImageCentre()
        {
            var target = new Vector3d(1, 2, 3);
            var pose = LookAt.FromPositions(new Vector3d(5, 4, -2), target);
            Assert.That(UnityProjection.TryProject(pose.Position, pose.Rotation, 45, 640, 480, Near, Far, target, out var u, out var v), Is.True);
            Assert.That(u, Is.EqualTo(320).Within(1e-9));
            Assert.That(v, Is.EqualTo(240).Within(1e-9));
        }

        [Test]
        public void APointAboveTheTargetAppearsAboveTheImageCentre()
        {
            // Unity: camera up is world +Y; image rows grow downwards, so "above" means a smaller row.
            var pose = LookAt.FromPositions(new Vector3d(0, 0, -5), Vector3d.Zero);
            Assert.That(UnityProjection.TryProject(pose.Position, pose.Rotation, 60, 100, 100, Near, Far, new Vector3d(0, 1, 0), out _, out var v), Is.True);
            Assert.That(v, Is.LessThan(50));
            // And the NeRF ray through a pixel above the centre points up in the output world (+Z).
            var matrix = BlenderConvention.CameraToWorld(pose).ToRows();
            NerfRays.Ray(matrix, CameraIntrinsics.FromVerticalFov(60, 100, 100).CameraAngleX, 100, 100, 50, 10, out _, out var direction);
            Assert.That(direction[2], Is.GreaterThan(0));
        }

        static Vector3d RandomVector(SeededRandom random, double scale) =>
            new Vector3d((random.NextDouble() * 2 - 1) * scale, (random.NextDouble() * 2 - 1) * scale, (random.NextDouble() * 2 - 1) * scale);

        static Quaterniond RandomRotation(SeededRandom random)
        {
            // Shoemake's uniform random unit quaternion.
            double u1 = random.NextDouble(), u2 = random.NextDouble() * 2 * Math.PI, u3 = random.NextDouble() * 2 * Math.PI;
            double a = Math.Sqrt(1 - u1), b = Math.Sqrt(u1);
            return new Quaterniond(a * Math.Sin(u2), a * Math.Cos(u2), b * Math.Sin(u3), b * Math.Cos(u3));
        }
    }
}
