using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// convert --to nerfies read back through re-implementations of the readers' code: google/nerfies 1a38512
    /// nerfies/camera.py (Camera.from_json 140–160, project 284–315, get_pixel_centers 317–321, scale 323–340),
    /// nerfies/datasets/core.py load_camera (78–107), nerfies/datasets/nerfies.py (load_scene_info 29–54,
    /// _load_dataset_ids 66–78, the rgb/&lt;k&gt;x path 105, 131–135) and hustvl/4DGaussians 843d5ac
    /// scene/hyper_loader.py (Load_hyper_data 47–98, load_raw 151–164), from an analytic multi-view capture.
    /// </summary>
    public class NerfiesTests
    {
        TempFolder _temp;
        string _dataset;
        readonly List<(PlannedView View, AnalyticScene Scene, AnalyticDataset.RayOf Rays)> _traced = new List<(PlannedView, AnalyticScene, AnalyticDataset.RayOf)>();

        internal static AnalyticDataset.Options Options() => new AnalyticDataset.Options
        {
            Width = 24, Height = 16, Supersampling = 1, Train = 2, Val = 1, Test = 1, TimeSteps = 3, PointCloud = 50,
        };

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            var options = Options();
            options.OutputRays = (view, scene, rays) => _traced.Add((view, scene, rays));
            _dataset = AnalyticDataset.Write(_temp.Path, "moving", options);
        }

        [OneTimeTearDown]
        public void Clean() => _temp.Dispose();

        /// <summary>camera.py:279–315 without distortion: local = orientation·(p − position); pixel = (f·x + skew·y + cx, f·aspect·y + cy).</summary>
        internal static double[] Project(JObject camera, Vector3d p)
        {
            var o = camera["orientation"].Select(r => r.Select(v => (double)v).ToArray()).ToArray();
            var c = camera["position"].Select(v => (double)v).ToArray();
            var q = new[] { p.X - c[0], p.Y - c[1], p.Z - c[2] };
            var local = o.Select(r => r[0] * q[0] + r[1] * q[1] + r[2] * q[2]).ToArray();
            double x = local[0] / local[2], y = local[1] / local[2];
            double f = (double)camera["focal_length"], skew = (double)camera["skew"], aspect = (double)camera["pixel_aspect_ratio"];
            return new[] { f * x + skew * y + (double)camera["principal_point"][0], f * aspect * y + (double)camera["principal_point"][1] };
        }

        [Test]
        public void TheCameraIsTheOpenCvWorldToCameraRotationAndTheCentre()
        {
            // Blender world, OpenGL axes: at (0, −4, 0) looking along +Y, up +Z. Its columns: x (1, 0, 0), y (0, 0, 1), z (0, −1, 0).
            var c2w = Matrix4x4d.FromRowMajor(
                1, 0, 0, 0,
                0, 0, -1, -4,
                0, 1, 0, 0,
                0, 0, 0, 1);
            var intrinsics = CameraIntrinsics.FromVerticalFov(60, 40, 30);
            var camera = NerfiesCamera.Json(c2w, intrinsics);
            // OpenCV rows: right (1, 0, 0), down = −up = (0, 0, −1), forward (0, 1, 0).
            Assert.That(camera["orientation"].Select(r => r.Select(v => (double)v)), Is.EqualTo(new[] { new[] { 1.0, 0, 0 }, new[] { 0.0, 0, -1 }, new[] { 0.0, 1, 0 } }));
            Assert.That(camera["position"].Select(v => (double)v), Is.EqualTo(new[] { 0.0, -4, 0 }));
            var f = 15 / Math.Tan(Math.PI / 6);
            Assert.That((double)camera["focal_length"], Is.EqualTo(f).Within(1e-12));
            Assert.That(camera["principal_point"].Select(v => (double)v), Is.EqualTo(new[] { 20.0, 15 }));
            Assert.That(camera["image_size"].Select(v => (int)v), Is.EqualTo(new[] { 40, 30 }));
            Assert.That((double)camera["pixel_aspect_ratio"], Is.EqualTo(1));
            // The origin lands on the principal point; the point 0.5 above it, 0.5·f/4 rows higher (y grows downwards).
            Assert.That(Project(camera, Vector3d.Zero), Is.EqualTo(new[] { 20.0, 15 }).Within(1e-12));
            Assert.That(Project(camera, new Vector3d(0, 0, 0.5)), Is.EqualTo(new[] { 20.0, 15 - f * 0.5 / 4 }).Within(1e-12));
        }

        [Test]
        public void EveryDistinctTimeGetsTheCoarsestWholeNumberGrid()
        {
            Assert.That(NerfiesViews.Grid(new[] { 0, 0.5, 1 }), Is.EqualTo(2));
            Assert.That(NerfiesViews.Grid(new[] { 0, 1 / 3.0, 2 / 3.0, 1 }), Is.EqualTo(3));
            // A monocular capture of 5 train steps: test views at (k + ½)/4 sit on the grid of 8.
            Assert.That(NerfiesViews.Grid(new[] { 0, 0.25, 0.5, 0.75, 1, 0.125, 0.625 }), Is.EqualTo(8));
            // 1/π is within 1e-7 of no k/L for L ≤ 100 000 (its convergent 113/355 is 1e-5 off): no grid.
            Assert.That(NerfiesViews.Grid(new[] { 0, 1 / Math.PI, 1 }), Is.Null);
        }

        [Test]
        public void LevelsAreTheRoundedBoxMeanOfTheCompositedCodes()
        {
            // 4 × 2 RGB: the 2x level is two pixels, each the mean of a 2 × 2 block, rounded half up.
            var rgb = new byte[]
            {
                0, 10, 255, 1, 10, 255, /**/ 100, 0, 0, 101, 0, 0,
                1, 11, 254, 2, 11, 254, /**/ 100, 0, 0, 100, 0, 1,
            };
            // Block 1: r (0 + 1 + 1 + 2)/4 = 1, g (10 + 10 + 11 + 11)/4 = 10.5 → 11, b (255·2 + 254·2)/4 = 254.5 → 255.
            // Block 2: r 401/4 = 100.25 → 100, g 0, b 1/4 → 0.
            Assert.That(NerfiesImages.Downscale(rgb, 4, 2, 2), Is.EqualTo(new byte[] { 1, 11, 255, 100, 0, 0 }));
            Assert.That(NerfiesImages.Fits(2, 4, 2), Is.True);
            Assert.That(NerfiesImages.Fits(4, 4, 2), Is.False, "2 rows have no 4x level");
        }

        [Test]
        public void AMultiViewCaptureReadsBackThroughNerfiesAnd4DGaussians()
        {
            var output = _temp.Combine("nerfies-out");
            var result = DatasetConverter.Convert(_dataset, ExportTarget.Nerfies, output);
            Assert.That(result.MainFile, Is.EqualTo(Path.Combine(output, "dataset.json")));
            Assert.That(result.Warnings.Select(w => w.Field), Has.Member("val"), "the val split is not in the layout");

            // nerfies.py:66–78 and hyper_loader.py:59–77: ids, train_ids, val_ids (train = our train split, val = our test).
            var ds = JObject.Parse(File.ReadAllText(Path.Combine(output, "dataset.json")));
            var trainIds = ds["train_ids"].Select(v => (string)v).ToList();
            var valIds = ds["val_ids"].Select(v => (string)v).ToList();
            Assert.That(trainIds, Is.EquivalentTo(new[] { "0_00000", "1_00000", "0_00001", "1_00001", "0_00002", "1_00002" }));
            Assert.That(valIds, Is.EquivalentTo(new[] { "2_00000", "2_00001", "2_00002" }), "the test camera numbered after the two train cameras");
            Assert.That(ds["ids"].Select(v => (string)v), Is.EqualTo(trainIds.Concat(valIds)));

            // nerfies.py:29–54: center, scale, near, far; core.py:102–105 moves the camera to (position − center)·scale.
            var sceneJson = JObject.Parse(File.ReadAllText(Path.Combine(output, "scene.json")));
            var center = sceneJson["center"].Select(v => (double)v).ToArray();
            var scale = (double)sceneJson["scale"];
            var meta = JObject.Parse(File.ReadAllText(Path.Combine(output, "metadata.json")));
            var maxWarp = trainIds.Concat(valIds).Max(id => (int)meta[id]["warp_id"]);
            var background = ProtocolBackground.For(_dataset);
            var sources = new Dictionary<string, JObject>();
            foreach (var (split, offset) in new[] { ("train", 0), ("test", 2) })
                foreach (JObject frame in JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "transforms_" + split + ".json")))["frames"])
                    sources[((int)frame["camera_id"] + offset) + "_" + ((int)frame["time_step"]).ToString("D5")] = frame;
            var angleX = (double)JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "transforms_train.json")))["camera_angle_x"];

            foreach (var id in trainIds.Concat(valIds))
            {
                var frame = sources[id];
                var c2w = Matrix4x4d.FromRows(frame["transform_matrix"].Select(r => r.Select(v => (double)v).ToArray()).ToArray());
                // 4DGaussians: time = warp_id / max warp_id (hyper_loader.py:79–81) — the frame's own time.
                Assert.That((int)meta[id]["warp_id"] / (double)maxWarp, Is.EqualTo((double)frame["time"]).Within(1e-12), id);
                Assert.That((int)meta[id]["warp_id"], Is.EqualTo((int)frame["time_step"]), id + ": multi-view ids are the steps");
                Assert.That((int)meta[id]["appearance_id"], Is.EqualTo((int)meta[id]["warp_id"]));

                var camera = JObject.Parse(File.ReadAllText(Path.Combine(output, "camera", id + ".json")));
                // Poses: orientationᵀ (hyper_loader.py:161 R = orientation.T) is the OpenCV camera-to-world rotation, position the centre.
                var o = camera["orientation"].Select(r => r.Select(v => (double)v).ToArray()).ToArray();
                var position = camera["position"].Select(v => (double)v).ToArray();
                for (var r = 0; r < 3; r++)
                {
                    Assert.That(o[0][r], Is.EqualTo(c2w[r, 0]).Within(1e-6), id + " x axis");
                    Assert.That(o[1][r], Is.EqualTo(-c2w[r, 1]).Within(1e-6), id + " y axis (down)");
                    Assert.That(o[2][r], Is.EqualTo(-c2w[r, 2]).Within(1e-6), id + " optical axis");
                    Assert.That(position[r], Is.EqualTo(c2w[r, 3]).Within(1e-6), id + " centre");
                }
                // Intrinsics: NeRF's focal from camera_angle_x, pixel centres at i + ½ (camera.py:317–321).
                Assert.That((double)camera["focal_length"], Is.EqualTo(0.5 * 24 / Math.Tan(0.5 * angleX)).Within(1e-9));
                Assert.That(camera["principal_point"].Select(v => (double)v), Is.EqualTo(new[] { 12.0, 8 }));
                Assert.That(camera["image_size"].Select(v => (int)v), Is.EqualTo(new[] { 24, 16 }));
                // 4DGaussians: FovX = focal2fov(focal_length, w) (hyper_loader.py:98, 163–164) is camera_angle_x.
                Assert.That(2 * Math.Atan(24 / (2 * (double)camera["focal_length"])), Is.EqualTo(angleX).Within(1e-12));
                // NeRF's ray through pixel centres projects back onto them through camera.py's project, scaled or not.
                foreach (var (i, j) in new[] { (0.5, 0.5), (23.5, 3.5), (7.5, 15.5) })
                {
                    NerfRays.Ray(c2w.ToRows(), angleX, 24, 16, i, j, out var ro, out var rd);
                    var p = new Vector3d(ro[0] + 2.5 * rd[0], ro[1] + 2.5 * rd[1], ro[2] + 2.5 * rd[2]);
                    Assert.That(Project(camera, p), Is.EqualTo(new[] { i, j }).Within(1e-6), id);
                    // core.py:99–105 at image_scale 2: focal and principal point halved, position moved and scaled; the
                    // point moved the same way lands on the half-size pixel centre.
                    var scaled = (JObject)camera.DeepClone();
                    scaled["focal_length"] = (double)camera["focal_length"] / 2;
                    scaled["principal_point"] = new JArray(6.0, 4.0);
                    scaled["position"] = new JArray(Enumerable.Range(0, 3).Select(k => (object)((position[k] - center[k]) * scale)).ToArray());
                    var q = new Vector3d((p.X - center[0]) * scale, (p.Y - center[1]) * scale, (p.Z - center[2]) * scale);
                    Assert.That(Project(scaled, q), Is.EqualTo(new[] { i / 2, j / 2 }).Within(1e-6), id + " at 2x");
                }

                // Images: RGB over the protocol background, bit-exact, and 2x = the box mean (nerfies.py:57–63 drops alpha).
                var source = PngReader.Read(Path.Combine(_dataset, ((string)frame["file_path"]).Substring(2) + ".png"));
                var expected = new byte[24 * 16 * 3];
                for (var k = 0; k < 24 * 16; k++)
                    for (var c = 0; c < 3; c++)
                    {
                        var bg = c == 0 ? background.R : c == 1 ? background.G : background.B;
                        int a = source.Samples[4 * k + 3];
                        expected[3 * k + c] = (byte)((source.Samples[4 * k + c] * a + bg * (255 - a) + 127) / 255);
                    }
                var one = PngReader.Read(Path.Combine(output, "rgb", "1x", id + ".png"));
                Assert.That(one.ColorType, Is.EqualTo(PngInfo.ColorTypeRgb));
                Assert.That(one.Samples, Is.EqualTo(expected), id + " rgb/1x");
                var two = PngReader.Read(Path.Combine(output, "rgb", "2x", id + ".png"));
                Assert.That((two.Width, two.Height), Is.EqualTo((12, 8)), "hyper_loader.py:96 loads rgb/2x");
                for (var y = 0; y < 8; y++)
                    for (var x = 0; x < 12; x++)
                        for (var c = 0; c < 3; c++)
                        {
                            var sum = expected[((2 * y) * 24 + 2 * x) * 3 + c] + expected[((2 * y) * 24 + 2 * x + 1) * 3 + c] +
                                      expected[((2 * y + 1) * 24 + 2 * x) * 3 + c] + expected[((2 * y + 1) * 24 + 2 * x + 1) * 3 + c];
                            Assert.That(two.Samples[(y * 12 + x) * 3 + c], Is.EqualTo((sum + 2) / 4), id + " rgb/2x");
                        }
                Assert.That(Directory.Exists(Path.Combine(output, "rgb", "16x")), Is.False);
            }
            Assert.That(Directory.GetFiles(Path.Combine(output, "rgb", "8x")).Length, Is.EqualTo(9), "24 × 16 has a 1/8 level");

            // near and far: the nearest and farthest hit along any pixel-centre ray, within one depth step of the
            // analytic scene traced at those pixel centres (rays with camera-space z = −1: the parameter is z).
            double near = double.PositiveInfinity, far = 0;
            foreach (var (view, analytic, rays) in _traced.Where(t => t.View.Split != DatasetSplit.Val))
                for (var j = 0; j < 16; j++)
                    for (var i = 0; i < 24; i++)
                    {
                        rays(i + 0.5, j + 0.5, out var ro, out var rd);
                        if (!analytic.Trace(ro, rd, 0, out var z, out _, out _, out _)) continue;
                        var x = (i + 0.5 - 12) * Math.Tan(0.5 * angleX) / 12;
                        var y = (j + 0.5 - 8) * Math.Tan(0.5 * angleX) / 12;
                        var distance = z * Math.Sqrt(1 + x * x + y * y);
                        near = Math.Min(near, distance);
                        far = Math.Max(far, distance);
                    }
            var step = 0.001 * Math.Sqrt(1 + 2 * Math.Pow(Math.Tan(0.5 * angleX), 2)); // one depth PNG step along the most oblique ray
            Assert.That((double)sceneJson["near"] / scale, Is.EqualTo(near).Within(step));
            Assert.That((double)sceneJson["far"] / scale, Is.EqualTo(far).Within(step));

            // 4DGaussians' initial cloud (dataset_readers.py:384–385): the dataset's points3d.ply as it is.
            Assert.That(File.ReadAllBytes(Path.Combine(output, "points3D_downsample2.ply")), Is.EqualTo(File.ReadAllBytes(Path.Combine(_dataset, "points3d.ply"))));
            Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_dataset, ExportTarget.Nerfies, output), "never overwrites");
        }

        static DatasetSettings Planned(TimeMode mode)
        {
            var s = new DatasetSettings { Seed = 3, Width = 16, Height = 12 };
            s.Train.Count = 3;
            s.Val.Count = 1;
            s.Test.Count = 2;
            s.Time.Mode = mode;
            s.Time.StartSeconds = 0;
            s.Time.EndSeconds = 2;
            s.Time.Steps = mode == TimeMode.Monocular ? 3 : 2;
            return s;
        }

        [Test]
        public void MonocularTestViewsBetweenTrainStepsGetIdsOfTheirOwnAndAWarning()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("mono");
                var plan = CapturePlan.Build(Planned(TimeMode.Monocular), new PlanTarget(Vector3d.Zero, 0.5, 1));
                TestDatasets.FromPlan(folder, plan);
                var result = DatasetConverter.Convert(folder, ExportTarget.Nerfies);
                var meta = JObject.Parse(File.ReadAllText(Path.Combine(folder, "nerfies", "metadata.json")));
                // Train at 0, ½, 1; test view 0 at 0 and view 1 halfway between train steps 1 and 2, at (1 + ½)/2 = ¾
                // (TimePlanning): the grid of 4, so train 0, 2, 4 and test 0, 3 (camera 1).
                Assert.That(meta.Properties().Select(p => p.Name), Is.EquivalentTo(new[] { "0_00000", "0_00002", "0_00004", "1_00000", "1_00003" }));
                Assert.That((int)meta["1_00003"]["warp_id"], Is.EqualTo(3));
                var warning = result.Warnings.Single(w => w.Field == "val_ids");
                Assert.That(warning.Value, Is.EqualTo("1 views"));
                Assert.That(warning.Reason, Does.Contain("core.py:601"));
            }
        }

        [Test]
        public void AnOddSideHasNoHalfSizeLevelAndTheWarningNames4DGaussians()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("odd");
                var settings = Planned(TimeMode.MultiView);
                settings.Width = 15;
                TestDatasets.FromPlan(folder, CapturePlan.Build(settings, new PlanTarget(Vector3d.Zero, 0.5)));
                var result = DatasetConverter.Convert(folder, ExportTarget.Nerfies);
                Assert.That(Directory.GetDirectories(Path.Combine(folder, "nerfies", "rgb")).Select(Path.GetFileName), Is.EqualTo(new[] { "1x" }));
                var warning = result.Warnings.Single(w => w.Field == "rgb/2x");
                Assert.That(warning.Value, Is.EqualTo("15 × 12"));
                Assert.That(warning.Reason, Does.Contain("4DGaussians loads only rgb/2x"));
            }
        }

        [Test]
        public void ALensIsRefusedByBothTargets()
        {
            using (var temp = new TempFolder())
            {
                var options = new AnalyticDataset.Options { Width = 8, Height = 8, Supersampling = 1, Train = 2, Val = 1, Test = 1, TimeSteps = 2, PointCloud = 0 };
                options.Lens = new LensSettings { Model = "opencv", K1 = -0.1 };
                var folder = AnalyticDataset.Write(temp.Path, "lens", options);
                foreach (var target in new[] { ExportTarget.Nerfies, ExportTarget.Dycheck })
                {
                    var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, target));
                    Assert.That(e.Problems.Count, Is.EqualTo(1));
                    Assert.That(e.Problems[0].Field, Is.EqualTo("--to"));
                    Assert.That(e.Problems[0].Reason, Does.StartWith("cannot hold this dataset's lens"));
                    Assert.That(Directory.Exists(DatasetConverter.OutputFolder(folder, target)), Is.False);
                }
            }
        }

        [Test]
        public void ASixteenBitImageIsRefusedNamingItsFormatByNerfiesAndTheSlamTargets()
        {
            using (var temp = new TempFolder())
            {
                var options = new AnalyticDataset.Options { Width = 8, Height = 8, Supersampling = 1, Train = 2, Val = 1, Test = 1, TimeSteps = 2, Monocular = true, PointCloud = 0 };
                var folder = AnalyticDataset.Write(temp.Path, "grey16", options);
                File.WriteAllBytes(Path.Combine(folder, "train", "r_0.png"), PngWriter.EncodeGray16(new ushort[64], 8, 8));
                foreach (var target in new[] { ExportTarget.Nerfies, ExportTarget.Tum })
                {
                    var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, target));
                    Assert.That(e.Problems[0].Value, Is.EqualTo("train/r_0.png"), target.ToString());
                    Assert.That(e.Problems[0].Reason, Is.EqualTo("is not an 8-bit RGB or RGBA PNG (colour type 0, 16 bits)."), "the one wording of ExportRgb.Decode");
                }
            }
        }

        [Test]
        public void AStaticDatasetIsRefusedInOneLineAndNothingIsWritten()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("still");
                TestDatasets.FromPlan(folder, CapturePlan.Build(Planned(TimeMode.Static), new PlanTarget(Vector3d.Zero, 0.5)));
                foreach (var target in new[] { ExportTarget.Nerfies, ExportTarget.Dycheck })
                {
                    var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, target));
                    Assert.That(e.Problems.Count, Is.EqualTo(1));
                    Assert.That(e.Problems[0].Field, Is.EqualTo("time"));
                    Assert.That(e.Problems[0].Value, Is.EqualTo("none (a static dataset)"));
                    Assert.That(e.Problems[0].Fix, Does.Contain("time.mode"));
                    Assert.That(Directory.Exists(DatasetConverter.OutputFolder(folder, target)), Is.False, "nothing written");
                }
            }
        }
    }
}
