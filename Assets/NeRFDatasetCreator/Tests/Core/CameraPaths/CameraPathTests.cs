using System;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class CameraPathTests
    {
        static CapturePlan Plan()
        {
            var s = new DatasetSettings { Seed = 5, Width = 320, Height = 240 };
            s.Train.Count = 3;
            s.Val.Count = 2;
            s.Test.Count = 6;
            return CapturePlan.Build(s, new PlanTarget(new Vector3d(0.5, 1, -2), 0.7));
        }

        /// <summary>
        /// nerfstudio's reading, written here from camera_paths.py get_path_from_json: c2w = tensor(camera_to_world).view(4, 4),
        /// fx = fy = (H/2)/tan(fov·π/360), cx = W/2, cy = H/2; rays as NeRF's (OpenGL camera axes).
        /// </summary>
        static void NerfstudioRay(JObject path, int frame, double i, double j, out double[] origin, out double[] direction)
        {
            var flat = ((JArray)path["camera_path"][frame]["camera_to_world"]).Select(v => (double)v).ToArray();
            var rows = Enumerable.Range(0, 4).Select(r => flat.Skip(4 * r).Take(4).ToArray()).ToArray();
            var h = (int)path["render_height"];
            var w = (int)path["render_width"];
            var focal = h / 2.0 / Math.Tan((double)path["camera_path"][frame]["fov"] * Math.PI / 360);
            var angleX = 2 * Math.Atan(w / (2 * focal)); // NerfRays takes NeRF's camera_angle_x
            NerfRays.Ray(rows, angleX, w, h, i, j, out origin, out direction);
        }

        [Test]
        public void NerfstudioReadsBackTheSplitsViews()
        {
            var plan = Plan();
            var views = plan.ViewsOf(DatasetSplit.Test).ToList();
            var path = JObject.Parse(ExportJson.Serialise(NerfstudioCameraPath.Build(views.Select(v => v.TransformMatrix).ToList(), plan.Intrinsics, framesPerSecond: 3)));
            Assert.That((string)path["camera_type"], Is.EqualTo("perspective"));
            Assert.That((double)path["seconds"], Is.EqualTo(2.0), "6 frames at 3 fps: render.py renders len(cameras)/seconds fps");
            Assert.That(path["camera_path"], Has.Count.EqualTo(6));
            for (var f = 0; f < views.Count; f++)
                foreach (var (i, j) in new[] { (0.5, 0.5), (160.0, 120.0), (319.5, 17.25) })
                {
                    NerfstudioRay(path, f, i, j, out var o, out var d);
                    var m = views[f].TransformMatrix.ToRows();
                    NerfRays.Ray(m, plan.Intrinsics.CameraAngleX, 320, 240, i, j, out var o2, out var d2);
                    PoseAssert.Close(o, o2, 1e-12, "origin");
                    PoseAssert.Close(PoseAssert.Normalised(d), PoseAssert.Normalised(d2), 1e-12, "direction of pixel " + i + "," + j);
                }
            Assert.That(NerfstudioCameraPath.Warnings(plan.Intrinsics), Is.Empty);
        }

        [Test]
        public void DataparserTransformMovesThePathIntoTheModelsFrame()
        {
            // transform: a quarter turn about z and a shift, scale 0.5 — c2w_model = [T·c2w] with translation × 0.5.
            var json = JObject.Parse("{\"transform\": [[0, -1, 0, 1], [1, 0, 0, 2], [0, 0, 1, 3]], \"scale\": 0.5}");
            var dataparser = NerfstudioDataparserTransform.FromJson(json);
            var c2w = Matrix4x4d.FromColumns(Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ, new Vector3d(4, 0, 0));
            var path = NerfstudioCameraPath.Build(new[] { c2w }, CameraIntrinsics.FromVerticalFov(50, 100, 100), dataparser);
            var flat = ((JArray)path["camera_path"][0]["camera_to_world"]).Select(v => (double)v).ToArray();
            // Centre: T·(4, 0, 0, 1) = (1, 6, 3), × 0.5 = (0.5, 3, 1.5); x axis → (0, 1, 0).
            Assert.That(flat, Is.EqualTo(new double[] { 0, -1, 0, 0.5, 1, 0, 0, 3, 0, 0, 1, 1.5, 0, 0, 0, 1 }));
            Assert.Throws<InvalidParameterException>(() => NerfstudioDataparserTransform.FromJson(JObject.Parse("{\"scale\": 1}")));
        }

        [Test]
        public void OffCentrePrincipalPointIsReported()
        {
            var shifted = CameraIntrinsics.FromVerticalFov(50, 100, 100, 0.1, 0);
            Assert.That(NerfstudioCameraPath.Warnings(shifted).Single().Reason, Does.Contain("cx = W/2"));
        }

        [Test]
        public void NgpPathHoldsTheTestbedsCameraOfEachView()
        {
            var plan = Plan();
            var views = plan.ViewsOf(DatasetSplit.Test).ToList();
            var path = JObject.Parse(ExportJson.Serialise(NgpCameraPath.Build(views.Select(v => v.TransformMatrix).ToList(), plan.Intrinsics)));
            Assert.That((int)path["spline_order"], Is.EqualTo(0));
            Assert.That((double)path["path"][0]["fov"], Is.EqualTo(plan.Settings.Camera.VerticalFovDegrees).Within(1e-9));
            for (var f = 0; f < views.Count; f++)
            {
                // nerf_matrix_to_ngp by hand: ngp (x, y, z) = (y, z, x) of the transforms world, scaled by 0.33 about 0.5; the camera
                // looks along its +z (the OpenGL −z) with +y down.
                var m = views[f].TransformMatrix;
                var kf = path["path"][f];
                var q = new Quaterniond((double)kf["R"][0], (double)kf["R"][1], (double)kf["R"][2], (double)kf["R"][3]);
                var t = new Vector3d((double)kf["T"][0], (double)kf["T"][1], (double)kf["T"][2]);
                var c = m.Translation;
                Assert.That(Vector3d.Distance(t, new Vector3d(c.Y * 0.33 + 0.5, c.Z * 0.33 + 0.5, c.X * 0.33 + 0.5)), Is.LessThan(1e-12));
                var view = -m.Column(2);
                var down = -m.Column(1);
                Assert.That(Vector3d.Distance(q.Rotate(Vector3d.UnitZ), new Vector3d(view.Y, view.Z, view.X)), Is.LessThan(1e-12));
                Assert.That(Vector3d.Distance(q.Rotate(Vector3d.UnitY), new Vector3d(down.Y, down.Z, down.X)), Is.LessThan(1e-12));
                Assert.That((double)kf["timestamp"], Is.EqualTo(f / NerfstudioCameraPath.DefaultFramesPerSecond).Within(1e-12));
            }
        }
    }
}
