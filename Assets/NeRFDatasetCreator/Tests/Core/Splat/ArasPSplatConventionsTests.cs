using System;
using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class ArasPSplatConventionsTests
    {
        [Test]
        public void AnImportedCameraLooksAwayFromWhereTheTrainingCameraLookedInThePlysFrame()
        {
            // A 3DGS camera at (0, 0, −4) looking at the origin: COLMAP axes right (1,0,0), down (0,1,0), forward (0,0,1),
            // so camera_to_JSON's rotation (camera-to-world) is the identity.
            var cam = ArasPSplatConventions.Import(new double[] { 0, 0, -4 }, new[] { new double[] { 1, 0, 0 }, new double[] { 0, 1, 0 }, new double[] { 0, 0, 1 } });
            Assert.That(cam.AxisX, Is.EqualTo(new Vector3d(1, 0, 0)));
            Assert.That(cam.AxisY, Is.EqualTo(new Vector3d(0, -1, 0)));
            Assert.That(cam.AxisZ, Is.EqualTo(new Vector3d(0, 0, -1)));
            Assert.That(cam.Fov, Is.EqualTo(25));
            var q = ArasPSplatConventions.ActivatedLocalRotation(cam);
            Assert.That(Vector3d.Distance(q.Forward, new Vector3d(0, 0, -1)), Is.LessThan(1e-12), "away from the origin, in the PLY's own frame");
            Assert.That(Vector3d.Distance(q.Right, new Vector3d(1, 0, 0)), Is.LessThan(1e-12));
        }

        [Test]
        public void UnderOurReflectingPlacementTheCameraIsExactOnlyIfTheReflectionIsTakenOutOfItsZ()
        {
            // A Unity camera, its dataset c2w (s = 1, c = 0: output = B·unity), 3DGS's camera_to_JSON of it, aras-p's import.
            var pose = new UnityPose(new Vector3d(0.3, 1.2, -2.5), Quaterniond.LookRotation(new Vector3d(-0.1, -0.4, 1), new Vector3d(0.2, 1, 0)));
            var c2w = BlenderConvention.CameraToWorld(pose);
            // COLMAP axes: right = c2w x, down = −c2w y, forward = −c2w z; rotation[row][column].
            Vector3d r = c2w.Column(0), d = -c2w.Column(1), f = -c2w.Column(2);
            var rotation = new[] { new[] { r.X, d.X, f.X }, new[] { r.Y, d.Y, f.Y }, new[] { r.Z, d.Z, f.Z } };
            var cam = ArasPSplatConventions.Import(new[] { c2w[0, 3], c2w[1, 3], c2w[2, 3] }, rotation);
            var local = ArasPSplatConventions.ActivatedLocalRotation(cam);
            // The splat object: Euler(90, 0, 0), scale (1, 1, −1): linear part B.
            Func<Vector3d, Vector3d> b = BlenderConvention.ToUnity;
            Assert.That(Vector3d.Distance(b(cam.Position), pose.Position), Is.LessThan(1e-12), "the position lands exactly");
            // World matrix of the parented camera: B·L (det −1). Negating its local z gives a rotation: exactly the camera.
            var right = b(local.Right);
            var up = b(local.Up);
            var forward = -b(local.Forward);
            Assert.That(Vector3d.Distance(right, pose.Rotation.Right), Is.LessThan(1e-12));
            Assert.That(Vector3d.Distance(up, pose.Rotation.Up), Is.LessThan(1e-12));
            Assert.That(Vector3d.Distance(forward, pose.Rotation.Forward), Is.LessThan(1e-12));
            // Taking only the rotations (Rx(90°)·L, the quaternion chain) gives another direction.
            var chain = Quaterniond.AngleAxis(90, new Vector3d(1, 0, 0)) * local;
            Assert.That(Vector3d.Distance(chain.Forward, pose.Rotation.Forward), Is.GreaterThan(0.1));
        }

        [TestCase("/data/out/bicycle/point_cloud/iteration_30000/point_cloud.ply", "bicycle-point_cloud-iteration_30000-point_cloud")]
        [TestCase("/r/lego/x/splat.ply", "r-lego-x-splat")]
        [TestCase("/x/y/lego.ply", "lego")]
        [TestCase("a/splat.ply", "a-splat")]
        public void TheAssetNameIsTheCreators(string ply, string name)
        {
            Assert.That(ArasPSplatConventions.AssetName(ply), Is.EqualTo(name));
        }

        [Test]
        public void TheCamerasJsonIsTheFirstOneWalkingUpFromThePly()
        {
            var root = Path.Combine(Path.GetTempPath(), "aras-cameras-" + Guid.NewGuid().ToString("N"));
            try
            {
                var iteration = Path.Combine(root, "model", "point_cloud", "iteration_7000");
                Directory.CreateDirectory(iteration);
                var ply = Path.Combine(iteration, "point_cloud.ply");
                File.WriteAllText(ply, "ply");
                Assert.That(ArasPSplatConventions.CamerasJsonFor(ply), Is.Null.Or.Not.StartWith(root), "none inside the model yet");
                File.WriteAllText(Path.Combine(root, "model", "cameras.json"), "[]");
                Assert.That(ArasPSplatConventions.CamerasJsonFor(ply), Is.EqualTo(Path.Combine(root, "model") + "/cameras.json"));
                File.WriteAllText(Path.Combine(iteration, "cameras.json"), "[]");
                Assert.That(ArasPSplatConventions.CamerasJsonFor(ply), Is.EqualTo(iteration + "/cameras.json"), "the nearest wins");
            }
            finally { Directory.Delete(root, true); }
        }
    }
}
