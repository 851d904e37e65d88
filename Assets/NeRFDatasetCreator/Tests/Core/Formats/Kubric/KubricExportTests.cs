using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <c>convert --to kubric</c> read back as Kubric's MOVi builder reads a scene folder — a re-implementation of
    /// <c>load_scene_directory</c> and <c>read_png</c> (google-research/kubric 0ee21e2 challenges/movi/movi_e.py:346–434,
    /// 591–611), decoded as its docstring says (movi_e.py:72–83) — and compared with our flow (Δrow = dy, Δcol = dx
    /// within Kubric's 16-bit quantisation step), with the camera-induced motion of static pixels computed from the
    /// depth EXRs and poses alone (pins sign, axis order and Kubric's backward direction of time), and with the dataset.
    /// </summary>
    [TestFixture]
    public class KubricExportTests
    {
        TempFolder _temp;
        string _dataset, _export;

        [OneTimeSetUp]
        public void Write()
        {
            _temp = new TempFolder();
            _dataset = FlowExportDataset.Write(_temp.Path, "mono", monocular: true);
            _export = _temp.Combine("kubric");
            DatasetConverter.Convert(_dataset, ExportTarget.Kubric, _export);
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        sealed class Scene
        {
            public int NumFrames;
            public JObject Metadata, Events;
            public double[] ForwardRange, BackwardRange;
            public List<ushort[,,]> Forward = new List<ushort[,,]>(), Backward = new List<ushort[,,]>();
            public List<byte[,,]> Video = new List<byte[,,]>();
        }

        /// <summary>load_scene_directory(scene_dir, target_size, layers=("rgba", "forward_flow", "backward_flow")), line for line.</summary>
        static Scene Load(string sceneDir, (int H, int W) targetSize)
        {
            var scene = new Scene();
            // :350–357: json.load of data_ranges.json, metadata.json and events.json.
            var dataRanges = JObject.Parse(File.ReadAllText(Path.Combine(sceneDir, "data_ranges.json")));
            scene.Metadata = JObject.Parse(File.ReadAllText(Path.Combine(sceneDir, "metadata.json")));
            scene.Events = JObject.Parse(File.ReadAllText(Path.Combine(sceneDir, "events.json")));
            // :359: num_frames = metadata["metadata"]["num_frames"]
            scene.NumFrames = (int)scene.Metadata["metadata"]["num_frames"];
            // :361–374: the keys the result dict reads (a KeyError in Python is a null here).
            Assert.That(scene.Metadata["metadata"]["num_instances"], Is.Not.Null);
            Assert.That(scene.Metadata["metadata"]["background"], Is.Not.Null);
            Assert.That(scene.Metadata["instances"], Is.InstanceOf<JArray>());
            foreach (var key in new[] { "focal_length", "sensor_width", "field_of_view", "positions", "quaternions" }) // format_camera_information :449–456
                Assert.That(scene.Metadata["camera"][key], Is.Not.Null, key);
            Assert.That(scene.Events["collisions"], Is.InstanceOf<JArray>()); // format_events_information :472–482
            // :376–380: resolution = metadata["metadata"]["resolution"]; the asserts; scale = resolution[1] / target_size[0].
            var resolution = (JArray)scene.Metadata["metadata"]["resolution"];
            Assert.That((double)resolution[1] / targetSize.H, Is.EqualTo((double)resolution[0] / targetSize.W));
            var scale = (double)resolution[1] / targetSize.H;
            Assert.That(scale, Is.EqualTo((int)resolution[1] / targetSize.H));
            // :382–385: paths[key] = [scene_dir / f"{key}_{f:05d}.png" for f in range(num_frames)]
            string PathOf(string key, int f) => Path.Combine(sceneDir, key + "_" + f.ToString("00000") + ".png");
            // :396–412: the ranges divided by scale; each frame read_png(...)[..., :2] (subsample_nearest_neighbor at scale 1 is the identity, :529–541).
            scene.ForwardRange = new[] { (double)dataRanges["forward_flow"]["min"] / scale, (double)dataRanges["forward_flow"]["max"] / scale };
            scene.BackwardRange = new[] { (double)dataRanges["backward_flow"]["min"] / scale, (double)dataRanges["backward_flow"]["max"] / scale };
            for (var f = 0; f < scene.NumFrames; f++)
            {
                scene.Forward.Add(FirstTwo(ReadPng16(PathOf("forward_flow", f))));
                scene.Backward.Add(FirstTwo(ReadPng16(PathOf("backward_flow", f))));
                // :428–431: subsample_avg(read_png(frame_path), target_size)[..., :3] — an 8-bit image.
                var rgba = PngReader.Read(PathOf("rgba", f));
                Assert.That(rgba.BitDepth, Is.EqualTo(8));
                var video = new byte[rgba.Height, rgba.Width, 3];
                for (var y = 0; y < rgba.Height; y++)
                    for (var x = 0; x < rgba.Width; x++)
                        for (var c = 0; c < 3; c++) video[y, x, c] = rgba.Samples[(y * rgba.Width + x) * rgba.Channels + c];
                scene.Video.Add(video);
            }
            return scene;
        }

        /// <summary>read_png (:591–611): bitdepth 16 → uint16, rows stacked, reshape (height, width, planes).</summary>
        static ushort[,,] ReadPng16(string path)
        {
            var png = PngReader.Read(path);
            Assert.That(png.BitDepth, Is.EqualTo(16), path);
            var planes = png.Channels;
            var data = new ushort[png.Height, png.Width, planes];
            for (var y = 0; y < png.Height; y++)
                for (var x = 0; x < png.Width; x++)
                    for (var c = 0; c < planes; c++)
                    {
                        var i = 2 * ((y * png.Width + x) * planes + c);
                        data[y, x, c] = (ushort)((png.Samples[i] << 8) | png.Samples[i + 1]);
                    }
            return data;
        }

        static ushort[,,] FirstTwo(ushort[,,] a)
        {
            Assert.That(a.GetLength(2), Is.EqualTo(3), "Kubric's flow PNG is RGB: two channels padded with a zero channel (file_io.py:109–111)");
            var r = new ushort[a.GetLength(0), a.GetLength(1), 2];
            for (var y = 0; y < a.GetLength(0); y++)
                for (var x = 0; x < a.GetLength(1); x++)
                {
                    r[y, x, 0] = a[y, x, 0];
                    r[y, x, 1] = a[y, x, 1];
                    Assert.That(a[y, x, 2], Is.EqualTo(0));
                }
            return r;
        }

        /// <summary>movi_e.py:76–77: <c>sample["forward_flow"] / 65535 * (maxv - minv) + minv</c>.</summary>
        static double Decode(ushort code, double[] range) => code / 65535.0 * (range[1] - range[0]) + range[0];

        static double HalfStep(double[] range) => (range[1] - range[0]) / 131070.0 + 1e-6 * Math.Max(1, range[1] - range[0]);

        string SceneDir => Path.Combine(_export, Kubric.ScenesFolder, "train");

        [Test]
        public void TheLoaderReadsEveryFrameAndTheFlowIsOursAsRowColumnWithinHalfAQuantisationStep()
        {
            var scene = Load(SceneDir, (FlowExportDataset.Height, FlowExportDataset.Width));
            var record = FlowRecord.Read(_dataset);
            Assert.That(scene.NumFrames, Is.EqualTo(5));
            Assert.That(scene.Forward.Count, Is.EqualTo(5));
            int moved = 0;
            for (var t = 0; t < scene.NumFrames; t++)
                foreach (var forward in new[] { true, false })
                {
                    var other = forward ? t + 1 : t - 1;
                    var layer = forward ? scene.Forward[t] : scene.Backward[t];
                    var range = forward ? scene.ForwardRange : scene.BackwardRange;
                    float[] flow = null;
                    if (other >= 0 && other < 5)
                    {
                        var pair = record.Pairs.Single(p => p.Video == "train" && p.From == t && p.To == other);
                        flow = FloFile.Read(Path.Combine(_dataset, pair.FlowFile), out _, out _);
                    }
                    for (var v = 0; v < FlowExportDataset.Height; v++)
                        for (var u = 0; u < FlowExportDataset.Width; u++)
                        {
                            double row = 0, col = 0; // the edge frames and pixels without flow are 0
                            var p = v * FlowExportDataset.Width + u;
                            if (flow != null && !float.IsNaN(flow[2 * p]))
                            {
                                // Kubric: forward p(t+1) − p(t); backward p(t) − p(t−1), the negative of our t → t−1 flow.
                                var s = forward ? 1 : -1;
                                row = s * flow[2 * p + 1];
                                col = s * flow[2 * p];
                                if (Math.Abs(col) > 0.5) moved++;
                            }
                            Assert.That(Decode(layer[v, u, 0], range), Is.EqualTo(row).Within(HalfStep(range)), "Δrow " + (forward ? "forward" : "backward") + " t=" + t + " at " + u + "," + v);
                            Assert.That(Decode(layer[v, u, 1], range), Is.EqualTo(col).Within(HalfStep(range)), "Δcol");
                        }
                }
            Assert.That(moved, Is.GreaterThan(500));
        }

        [Test]
        public void StaticPixelsMoveAsTheDepthAndPosesSayForwardAndBackwardInTheSameDirectionOfTime()
        {
            var scene = Load(SceneDir, (FlowExportDataset.Height, FlowExportDataset.Width));
            var record = FlowRecord.Read(_dataset);
            var frames = record.Video("train").Frames;
            var f = FlowExportDataset.Focal(_dataset);
            var checkedPixels = 0;
            for (var t = 0; t < 5; t++)
            {
                var depth = ExrReader.Read(Path.Combine(_dataset, FlowExportDataset.DepthExr(frames[t].Image)));
                var here = FlowExportDataset.Pose(_dataset, frames[t].Image);
                foreach (var forward in new[] { true, false })
                {
                    var other = forward ? t + 1 : t - 1;
                    if (other < 0 || other >= 5) continue;
                    // Static: zero scene flow on the target (the scene-flow EXR of the pair).
                    var pair = record.Pairs.Single(p => p.Video == "train" && p.From == t && p.To == other);
                    var sceneFlow = ExrReader.Read(Path.Combine(_dataset, pair.SceneFlowFile));
                    var there = FlowExportDataset.Pose(_dataset, frames[other].Image);
                    var layer = forward ? scene.Forward[t] : scene.Backward[t];
                    var range = forward ? scene.ForwardRange : scene.BackwardRange;
                    for (var v = 0; v < FlowExportDataset.Height; v++)
                        for (var u = 0; u < FlowExportDataset.Width; u++)
                        {
                            var p = v * FlowExportDataset.Width + u;
                            if (sceneFlow.Channel("A")[p] == 0 || sceneFlow.Channel("R")[p] != 0 || sceneFlow.Channel("G")[p] != 0 || sceneFlow.Channel("B")[p] != 0) continue;
                            var landing = FlowExportDataset.StaticLanding(depth, here, there, f, u, v);
                            if (landing == null) continue;
                            // Where the point is at the other frame minus where it is now; Kubric's backward is now minus then.
                            double dRow = landing.Value.Y - (v + 0.5), dCol = landing.Value.X - (u + 0.5);
                            if (!forward) { dRow = -dRow; dCol = -dCol; }
                            Assert.That(Decode(layer[v, u, 0], range), Is.EqualTo(dRow).Within(0.05 + HalfStep(range)), "Δrow t=" + t + (forward ? " forward" : " backward") + " at " + u + "," + v);
                            Assert.That(Decode(layer[v, u, 1], range), Is.EqualTo(dCol).Within(0.05 + HalfStep(range)), "Δcol");
                            checkedPixels++;
                        }
                }
            }
            Assert.That(checkedPixels, Is.GreaterThan(2000));
        }

        [Test]
        public void MetadataHoldsTheResolutionAsWidthHeightAndTheCameraOfEveryFrame()
        {
            var scene = Load(SceneDir, (FlowExportDataset.Height, FlowExportDataset.Width));
            Assert.That(scene.Metadata["metadata"]["resolution"].ToObject<int[]>(), Is.EqualTo(new[] { 64, 48 }));
            Assert.That(scene.Events["collisions"].Count(), Is.EqualTo(0));
            var camera = scene.Metadata["camera"];
            var transforms = JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "transforms_train.json")));
            // Kubric: fov = 2 atan(sensor_width / (2 focal_length)) (cameras.py:122–130): the horizontal field of view.
            Assert.That((double)camera["field_of_view"], Is.EqualTo((double)transforms["camera_angle_x"]).Within(1e-9));
            Assert.That(2 * Math.Atan2((double)camera["sensor_width"] / 2, (double)camera["focal_length"]), Is.EqualTo((double)transforms["camera_angle_x"]).Within(1e-9));
            var frames = FlowRecord.Read(_dataset).Video("train").Frames;
            for (var t = 0; t < 5; t++)
            {
                var pose = FlowExportDataset.Pose(_dataset, frames[t].Image);
                var position = camera["positions"][t].ToObject<double[]>();
                Assert.That(position, Is.EqualTo(new[] { pose[0, 3], pose[1, 3], pose[2, 3] }).Within(1e-9));
                var q = camera["quaternions"][t].ToObject<double[]>(); // (w, x, y, z)
                var rotation = new Quaterniond(q[1], q[2], q[3], q[0]);
                // The camera looks down its −Z with +Y up (Blender's camera), as the c2w's columns say.
                foreach (var axis in new[] { 1, 2 })
                {
                    var local = axis == 1 ? Vector3d.UnitY : Vector3d.UnitZ;
                    var world = rotation.Rotate(local);
                    var column = pose.Column(axis);
                    Assert.That(new[] { world.X, world.Y, world.Z }, Is.EqualTo(new[] { column.X, column.Y, column.Z }).Within(1e-9));
                }
            }
        }

        [Test]
        public void RgbaIsTheImageOverTheProtocolBackgroundWithAlpha255()
        {
            var background = ProtocolBackground.For(_dataset);
            var source = PngReader.Read(Path.Combine(_dataset, "train", "r_2.png"));
            var written = PngReader.Read(Path.Combine(SceneDir, "rgba_00002.png"));
            Assert.That(written.Channels, Is.EqualTo(4));
            int opaque = 0, clear = 0;
            for (var p = 0; p < source.Width * source.Height; p++)
            {
                Assert.That(written.Samples[4 * p + 3], Is.EqualTo(255));
                var alpha = source.Samples[4 * p + 3];
                if (alpha != 255 && alpha != 0) continue;
                var expected = alpha == 255 ? new[] { source.Samples[4 * p], source.Samples[4 * p + 1], source.Samples[4 * p + 2] } : new[] { background.R, background.G, background.B };
                Assert.That(new[] { written.Samples[4 * p], written.Samples[4 * p + 1], written.Samples[4 * p + 2] }, Is.EqualTo(expected));
                if (alpha == 255) opaque++; else clear++;
            }
            Assert.That(opaque, Is.GreaterThan(100));
            Assert.That(clear, Is.GreaterThan(100));
        }

        [Test]
        public void TheRecordSaysWhatEachFileHolds()
        {
            var record = JObject.Parse(File.ReadAllText(Path.Combine(_export, Kubric.RecordFileName)));
            Assert.That((string)record["source"], Is.EqualTo("flow/flow.json"));
            foreach (var key in new[] { "rgba_%05d.png", "forward_flow_%05d.png", "backward_flow_%05d.png", "data_ranges.json", "metadata.json", "events.json" })
                Assert.That((string)record["files"][key], Is.Not.Empty, key);
            Assert.That((string)record["files"]["backward_flow_%05d.png"], Does.Contain("p(t) − p(t−1)"));
            Assert.That(record["scenes"][0]["frames"].ToObject<string[]>(), Is.EqualTo(Enumerable.Range(0, 5).Select(i => "train/r_" + i + ".png")));
        }

        [Test]
        public void QuantisationRoundsToTheNearestCodeAndThePngIsSixteenBitRgbWithZeroBlue()
        {
            Assert.That(KubricFlowPng.Quantise(-2, -2, 3), Is.EqualTo(0));
            Assert.That(KubricFlowPng.Quantise(3, -2, 3), Is.EqualTo(65535));
            // 0 in [−2, 3]: 2 · 65535 / 5 = 26214 exactly; 0.1 above it is 1310.7 steps → 27525 (26214 + 1311 rounded).
            Assert.That(KubricFlowPng.Quantise(0, -2, 3), Is.EqualTo(26214));
            Assert.That(KubricFlowPng.Quantise(0.1, -2, 3), Is.EqualTo(27525));
            Assert.That(KubricFlowPng.Quantise(5, 0, 0), Is.EqualTo(0), "an empty range (no motion at all) is code 0, read back as min");
            var codes = new ushort[] { 0, 65535, 258, 1, 40000, 7 };
            var png = PngReader.Decode(KubricFlowPng.Encode(codes, 3, 1), "x.png");
            Assert.That((png.BitDepth, png.Channels, png.Width, png.Height), Is.EqualTo((16, 3, 3, 1)));
            Assert.That(png.Samples, Is.EqualTo(new byte[] { 0, 0, 255, 255, 0, 0, 1, 2, 0, 1, 0, 0, 156, 64, 0, 7, 0, 0 }));
        }

        [Test]
        public void MultiViewWritesOneSceneFolderPerCameraOfEverySplit()
        {
            var dataset = FlowExportDataset.Write(_temp.Path, "multi", monocular: false);
            var output = _temp.Combine("kubric-multi");
            DatasetConverter.Convert(dataset, ExportTarget.Kubric, output);
            var folders = Directory.GetDirectories(Path.Combine(output, Kubric.ScenesFolder)).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal);
            Assert.That(folders, Is.EqualTo(new[] { "test_cam00", "train_cam00", "train_cam01", "val_cam00" }));
            var scene = Load(Path.Combine(output, Kubric.ScenesFolder, "train_cam01"), (48, 64));
            Assert.That(scene.NumFrames, Is.EqualTo(3));
            // A static camera: every position is the same.
            var positions = scene.Metadata["camera"]["positions"].ToObject<double[][]>();
            Assert.That(positions[2], Is.EqualTo(positions[0]));
        }

        [Test]
        public void ADatasetWithoutFlowOrWithoutBackwardFlowIsRefusedNamingTheFixAndNothingIsWritten()
        {
            var plain = AnalyticDataset.Write(_temp.Path, "noflow", new AnalyticDataset.Options { Width = 32, Height = 24, Supersampling = 1, Train = 3, Val = 1, Test = 1, TimeSteps = 3, Monocular = true, PointCloud = 0 });
            var output = _temp.Combine("kubric-noflow");
            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(plain, ExportTarget.Kubric, output));
            Assert.That(e.Message, Does.Contain("flow/flow.json").And.Contain("nerf-dataset flow <dataset>"));
            Assert.That(Directory.Exists(Path.Combine(output, Kubric.ScenesFolder)), Is.False);
            var forwardOnly = FlowExportDataset.Write(_temp.Path, "fwd", monocular: true, new FlowSettings { On = true, Backward = false });
            e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(forwardOnly, ExportTarget.Kubric, _temp.Combine("kubric-fwd")));
            Assert.That(e.Message, Does.Contain("train 1 → 0").And.Contain("backward flow"));
        }
    }
}
