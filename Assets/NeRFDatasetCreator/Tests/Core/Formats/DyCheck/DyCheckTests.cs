using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// convert --to dycheck read back through re-implementations of KAIR-BAIR/dycheck ddf77a4's iPhone reader —
    /// datasets/nerfies.py _load_scene_info (64–72), _load_metadata_info (75–95), load_split (348–358);
    /// datasets/iphone.py load_depth (968–982), _load_extra_info (1003–1010); geometry/camera.py fromjson (306–326),
    /// pixels_to_viewdirs (450–494), pixels_to_cosa (504–506), pixels_to_points (508–533), get_pixels (557–566),
    /// rescale/translate (568–580) — and Shape of Motion's split reading (vye16/shape-of-motion 697d462
    /// flow3d/data/iphone_dataset.py:96–103), from an analytic multi-view capture.
    /// </summary>
    public class DyCheckTests
    {
        TempFolder _temp;
        string _dataset;

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _dataset = AnalyticDataset.Write(_temp.Path, "moving", NerfiesTests.Options());
        }

        [OneTimeTearDown]
        public void Clean() => _temp.Dispose();

        static double[] Vector(JToken t) => t.Select(v => (double)v).ToArray();

        [Test]
        public void AMultiViewCaptureReadsBackThroughDyCheckWithExactDepth()
        {
            var output = _temp.Combine("dycheck-out");
            var result = DatasetConverter.Convert(_dataset, ExportTarget.Dycheck, output);
            Assert.That(result.MainFile, Is.EqualTo(Path.Combine(output, "dataset.json")));

            // load_split: frame_names, time_ids, camera_ids; train's time and camera ids consecutive (base.py:71–75).
            var train = JObject.Parse(File.ReadAllText(Path.Combine(output, "splits", "train.json")));
            var val = JObject.Parse(File.ReadAllText(Path.Combine(output, "splits", "val.json")));
            Assert.That(train["time_ids"].Select(v => (int)v).Distinct().OrderBy(v => v), Is.EqualTo(new[] { 0, 1, 2 }));
            Assert.That(train["camera_ids"].Select(v => (int)v).Distinct().OrderBy(v => v), Is.EqualTo(new[] { 0, 1 }));
            Assert.That(val["camera_ids"].Select(v => (int)v), Is.All.EqualTo(2));
            foreach (var split in new[] { train, val })
            {
                // Shape of Motion keeps time ids below the split's frame count (iphone_dataset.py:98–102): all of them here.
                var count = split["frame_names"].Count();
                Assert.That(split["time_ids"].Count(t => (int)t < count), Is.EqualTo(count));
            }

            var extra = JObject.Parse(File.ReadAllText(Path.Combine(output, "extra.json")));
            Assert.That((int)extra["factor"], Is.EqualTo(1));
            Assert.That((double)extra["fps"], Is.EqualTo(2), "3 steps over 1 s: 2 time ids a second");
            Assert.That(Vector(extra["up"]), Is.EqualTo(new[] { 0.0, 0, 1 }));

            var scene = JObject.Parse(File.ReadAllText(Path.Combine(output, "scene.json")));
            var center = Vector(scene["center"]);
            var scale = (double)scene["scale"];
            var meta = JObject.Parse(File.ReadAllText(Path.Combine(output, "metadata.json")));
            var angleX = (double)JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "transforms_train.json")))["camera_angle_x"];
            var background = ProtocolBackground.For(_dataset);
            var frames = 0;
            foreach (var (splitName, offset, split) in new[] { ("train", 0, train), ("test", 2, val) })
                foreach (JObject frame in JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "transforms_" + splitName + ".json")))["frames"])
                {
                    var name = ((int)frame["camera_id"] + offset) + "_" + ((int)frame["time_step"]).ToString("D5");
                    Assert.That(split["frame_names"].Select(v => (string)v), Has.Member(name));
                    Assert.That((int)meta[name]["warp_id"], Is.EqualTo((int)frame["time_step"]), "_load_metadata_info reads time ids from warp_id");
                    Assert.That((int)meta[name]["camera_id"], Is.EqualTo((int)frame["camera_id"] + offset));
                    var c2w = Matrix4x4d.FromRows(frame["transform_matrix"].Select(r => r.Select(v => (double)v).ToArray()).ToArray());

                    // fromjson → rescale_image_domain(1/factor) → translate(−center) → rescale(scale).
                    var camera = JObject.Parse(File.ReadAllText(Path.Combine(output, "camera", name + ".json")));
                    var o = camera["orientation"].Select(Vector).ToArray();
                    var position = Vector(camera["position"]).Select((p, k) => (p - center[k]) * scale).ToArray();
                    double f = (double)camera["focal_length"], cx = (double)camera["principal_point"][0], cy = (double)camera["principal_point"][1];
                    Assert.That(f, Is.EqualTo(0.5 * 24 / Math.Tan(0.5 * angleX)).Within(1e-9));
                    Assert.That((cx, cy), Is.EqualTo((12.0, 8.0)));

                    // depth: (H, W, 1) float32 of the depth PNG's z exactly; load_depth multiplies by scale and divides by cos.
                    var npy = File.ReadAllBytes(Path.Combine(output, "depth", "1x", name + ".npy"));
                    var (header, depth) = NumpyFilesTests.ParseNpy(npy);
                    Assert.That(header, Does.Contain("'shape': (16, 24, 1)").And.Contain("'<f4'"));
                    var png = PngGray16Reader.Read(Path.Combine(_dataset, ((string)frame["depth_path"]).Substring(2)), out _, out _);
                    Assert.That(depth, Is.EqualTo(png.Select(s => (float)(s * 0.001)).ToArray()), name + ": exact depth");
                    for (var j = 0; j < 16; j++)
                        for (var i = 0; i < 24; i++)
                        {
                            var z = depth[j * 24 + i];
                            if (z == 0) continue;
                            // pixels_to_viewdirs at the pixel centre (use_center), then pixels_to_points = dir·depth/cos + position.
                            var local = new[] { (i + 0.5 - cx) / f, (j + 0.5 - cy) / f, 1.0 };
                            var norm = Math.Sqrt(local.Sum(v => v * v));
                            var dir = Enumerable.Range(0, 3).Select(r => (o[0][r] * local[0] + o[1][r] * local[1] + o[2][r] * local[2]) / norm).ToArray();
                            var cos = dir[0] * o[2][0] + dir[1] * o[2][1] + dir[2] * o[2][2];
                            var point = Enumerable.Range(0, 3).Select(r => dir[r] * (z * scale) / cos + position[r]).ToArray();
                            // Back in our world it is NeRF's ray through the same pixel centre at the PNG's z.
                            NerfRays.Ray(c2w.ToRows(), angleX, 24, 16, i + 0.5, j + 0.5, out var ro, out var rd);
                            for (var r = 0; r < 3; r++)
                                Assert.That(point[r] / scale + center[r], Is.EqualTo(ro[r] + png[j * 24 + i] * 0.001 * rd[r]).Within(1e-5), name + " point");
                        }

                    // rgb/1x: RGBA, the RGB over the protocol background, alpha 255 (DyCheck: valid pixel).
                    var source = PngReader.Read(Path.Combine(_dataset, ((string)frame["file_path"]).Substring(2) + ".png"));
                    var rgba = PngReader.Read(Path.Combine(output, "rgb", "1x", name + ".png"));
                    Assert.That(rgba.ColorType, Is.EqualTo(PngInfo.ColorTypeRgba));
                    for (var k = 0; k < 24 * 16; k++)
                    {
                        int a = source.Samples[4 * k + 3];
                        var bg = new[] { background.R, background.G, background.B };
                        for (var c = 0; c < 3; c++)
                            Assert.That(rgba.Samples[4 * k + c], Is.EqualTo((source.Samples[4 * k + c] * a + bg[c] * (255 - a) + 127) / 255), name);
                        Assert.That(rgba.Samples[4 * k + 3], Is.EqualTo(255));
                    }
                    frames++;
                }
            Assert.That(frames, Is.EqualTo(9), "train 2 cameras and test 1, at 3 steps");
            Assert.That(Directory.Exists(Path.Combine(output, "covisible")), Is.False, "no exact co-visibility: see DyCheckExport");
            Assert.That(result.Warnings.Select(w => w.Field), Has.Member("val"));
        }

        [Test]
        public void Float32ArrayWritesTheShapeNumPyReads()
        {
            // np.load reads the dict's shape; a one-dimensional tuple needs its comma, "(3,)".
            var (header, values) = NumpyFilesTests.ParseNpy(NumpyFiles.Float32Array(new[] { 1f, 2.5f, 0f, -4f }, 2, 2, 1));
            Assert.That(header.TrimEnd(' ', '\n'), Is.EqualTo("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 2, 1), }"));
            Assert.That(values, Is.EqualTo(new[] { 1f, 2.5f, 0f, -4f }));
            Assert.That(NumpyFilesTests.ParseNpy(NumpyFiles.Float32Array(new[] { 1f, 2f, 3f }, 3)).header, Does.Contain("'shape': (3,), }"));
            Assert.Throws<ArgumentException>(() => NumpyFiles.Float32Array(new float[5], 2, 2, 1));
        }

        static NerfiesView View(int camera, int time) =>
            new NerfiesView(new ExportFrame("test", "test/r_" + time + ".png", Matrix4x4d.Identity), false, camera, time);

        [Test]
        public void ASplitWithTimeIdsPastItsFrameCountIsNamed()
        {
            Assert.That(DyCheck.TimeIdsPastFrameCount("val", new[] { View(2, 0), View(2, 1) }), Is.Null);
            var problem = DyCheck.TimeIdsPastFrameCount("val", new[] { View(2, 0), View(2, 3) });
            Assert.That(problem.Field, Is.EqualTo("splits/val.json"));
            Assert.That(problem.Value, Is.EqualTo("1 of 2 frames"));
            Assert.That(problem.Reason, Does.Contain("2_00003").And.Contain("iphone_dataset.py:98–102"));
            Assert.That(DyCheck.Gap(new[] { 0, 1, 1, 2 }), Is.Null);
            Assert.That(DyCheck.Gap(new[] { 0, 2 }), Is.EqualTo("0, 2"));
        }

        [Test]
        public void AMonocularCaptureKeepsItsTestViewsOnTrainTimesAndSaysWhatIsDropped()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "mono", new AnalyticDataset.Options
                {
                    Width = 8, Height = 8, Supersampling = 1, Train = 3, Val = 1, Test = 3, TimeSteps = 3, Monocular = true, PointCloud = 0,
                });
                var result = DatasetConverter.Convert(folder, ExportTarget.Dycheck);
                var val = JObject.Parse(File.ReadAllText(Path.Combine(folder, "dycheck", "splits", "val.json")));
                // Test view 0 is at time 0 (a train time); views 1 and 2 lie between train steps.
                Assert.That(val["frame_names"].Select(v => (string)v), Is.EqualTo(new[] { "1_00000" }));
                var dropped = result.Warnings.Single(w => w.Field == "test");
                Assert.That(dropped.Value, Is.EqualTo("2 views"));
                Assert.That(dropped.Reason, Does.StartWith("are not exported"));
            }
        }

        [Test]
        public void ADatasetWithoutDepthIsRefusedInOneLine()
        {
            using (var temp = new TempFolder())
            {
                var options = NerfiesTests.Options();
                options.Configure = s => { s.Train.Depth = ExtraOutput.None; };
                var folder = AnalyticDataset.Write(temp.Path, "nodepth", options);
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Dycheck));
                Assert.That(e.Problems.Count, Is.EqualTo(1));
                Assert.That(e.Problems[0].Field, Is.EqualTo("depth"));
                Assert.That(e.Problems[0].Value, Does.StartWith("train/"));
                Assert.That(Directory.Exists(Path.Combine(folder, "dycheck")), Is.False);
                // Nerfies reads depth only for near and far: it bounds the target's reach instead, and says so.
                var nerfies = DatasetConverter.Convert(folder, ExportTarget.Nerfies);
                Assert.That(nerfies.Warnings.Select(w => w.Field), Has.Member("scene.json: near, far"));
            }
        }
    }
}
