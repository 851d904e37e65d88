using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// convert --to replica read back as the SLAM methods read it: SplaTAM spla-tam/SplaTAM da6bbcd
    /// datasets/gradslam_datasets/replica.py:45–63 (natsorted globs of results/frame*.jpg and depth*.png; traj.txt line
    /// i → 4×4 c2w as is) and basedataset.py:125–134, 257 (camera_params; depth / png_depth_scale), MonoGS muskie82/MonoGS
    /// 6c9254c utils/dataset.py:19–45 (sorted globs; inv(c2w)), Gaussian-SLAM VladimirYugay/Gaussian-SLAM eaec10d
    /// src/entities/datasets.py:47–72 (every traj.txt line).
    /// </summary>
    public class ReplicaExportTests
    {
        sealed class Read
        {
            public List<string> Colour, Depth;
            public List<double[,]> Poses;
        }

        /// <summary>The readers' code: the sorted globs (zero-padded names: natsort = sort) and every traj.txt line split on whitespace.</summary>
        static Read ReadLikeTheLoaders(string folder)
        {
            var results = Path.Combine(folder, "results");
            var read = new Read
            {
                Colour = Directory.GetFiles(results, "frame*.jpg").OrderBy(f => f, StringComparer.Ordinal).ToList(),
                Depth = Directory.GetFiles(results, "depth*.png").OrderBy(f => f, StringComparer.Ordinal).ToList(),
                Poses = new List<double[,]>(),
            };
            foreach (var line in File.ReadAllLines(Path.Combine(folder, "traj.txt")))
            {
                var values = line.Split((char[])null, StringSplitOptions.RemoveEmptyEntries).Select(v => double.Parse(v, System.Globalization.CultureInfo.InvariantCulture)).ToArray();
                Assert.That(values.Length, Is.EqualTo(16), "np.array(...).reshape(4, 4) needs 16 numbers a line (Gaussian-SLAM reads every line)");
                var m = new double[4, 4];
                for (var i = 0; i < 16; i++) m[i / 4, i % 4] = values[i];
                read.Poses.Add(m);
            }
            return read;
        }

        [Test]
        public void TheSequenceReadsBackAsTheLoadersReadIt()
        {
            using (var temp = new TempFolder())
            {
                var folder = SlamTestData.Monocular(temp.Path, "mono");
                var result = DatasetConverter.Convert(folder, ExportTarget.Replica);
                var output = Path.Combine(folder, "replica");
                Assert.That(result.OutputDirectory, Is.EqualTo(output));
                var scene = BlenderDatasetLoader.Load(folder);
                var frames = SlamTestData.TrainInTime(scene);
                var read = ReadLikeTheLoaders(output);
                Assert.That(read.Colour.Select(Path.GetFileName), Is.EqualTo(Enumerable.Range(0, frames.Count).Select(i => "frame" + i.ToString("D6") + ".jpg")));
                Assert.That(read.Depth.Select(Path.GetFileName), Is.EqualTo(Enumerable.Range(0, frames.Count).Select(i => "depth" + i.ToString("D6") + ".png")));
                Assert.That(read.Poses, Has.Count.EqualTo(frames.Count));
                Assert.That(result.Warnings.Select(w => w.Field), Does.Contain("test"), "the test view is said to be left out");

                // Intrinsics: the yaml holds the dataset's camera exactly (fl = W/2 / tan(camera_angle_x / 2), centred principal point).
                var yaml = Path.Combine(output, "splatam.yaml");
                var k = scene.Intrinsics;
                Assert.That(SlamTestData.YamlNumber(yaml, "fx"), Is.EqualTo(k.FlX));
                Assert.That(SlamTestData.YamlNumber(yaml, "fy"), Is.EqualTo(k.FlY));
                Assert.That(SlamTestData.YamlNumber(yaml, "cx"), Is.EqualTo(20.0));
                Assert.That(SlamTestData.YamlNumber(yaml, "cy"), Is.EqualTo(15.0));
                Assert.That(SlamTestData.YamlNumber(yaml, "image_width"), Is.EqualTo(40));
                Assert.That(SlamTestData.YamlNumber(yaml, "image_height"), Is.EqualTo(30));
                Assert.That(SlamTestData.YamlNumber(yaml, "png_depth_scale"), Is.EqualTo(6553.5));
                Assert.That(k.FlX, Is.EqualTo(20 / Math.Tan(k.CameraAngleX / 2)).Within(1e-12));
                Assert.That(File.ReadAllText(yaml), Does.Contain("dataset_name: 'replica'"), "SplaTAM picks ReplicaDataset by dataset_name");
                Assert.That(SlamTestData.YamlNumber(Path.Combine(output, "monogs.yaml"), "depth_scale"), Is.EqualTo(6553.5));
                Assert.That(SlamTestData.YamlNumber(Path.Combine(output, "gaussian_slam.yaml"), "fx"), Is.EqualTo(k.FlX));

                for (var i = 0; i < frames.Count; i++)
                {
                    // Pose: the OpenCV c2w of the frame at the i-th time, to 1e-6 (round-trip text: exact here).
                    SlamTestData.AssertPose(SlamTestData.OpenCv(frames[i].CameraToWorld), read.Poses[i], 1e-6, "traj.txt line " + i);

                    // Depth: code / 6553.5 within one Replica step of the dataset's depth.
                    var depth = PngGray16Reader.Read(read.Depth[i], out var dw, out var dh);
                    Assert.That(dw, Is.EqualTo(40));
                    Assert.That(dh, Is.EqualTo(30));
                    var source = SlamTestData.SourceDepth(scene, frames[i]);
                    for (var p = 0; p < depth.Length; p++)
                        Assert.That(depth[p] / 6553.5, Is.EqualTo(source[p]).Within(1 / 6553.5), "depth pixel " + p + " of frame " + i);
                    Assert.That(depth.Count(d => d > 0), Is.GreaterThan(100), "the target is in view");

                    // Colour: the JPEG decodes to the composite over the protocol background within the stated PSNR.
                    var bg = ProtocolBackground.For(folder);
                    var decoded = JpegWriter.DecodeRgb(File.ReadAllBytes(read.Colour[i]), out var w, out var h);
                    Assert.That(w, Is.EqualTo(40));
                    Assert.That(h, Is.EqualTo(30));
                    var psnr = SlamTestData.Psnr(decoded, SlamTestData.ExpectedRgb(scene, frames[i], bg.R, bg.G, bg.B));
                    TestContext.Progress.WriteLine("replica frame " + i + ": JPEG q" + JpegWriter.Quality + " PSNR " + psnr.ToString("F2") + " dB");
                    Assert.That(psnr, Is.GreaterThan(38), "frame " + i);
                }
            }
        }

        [Test]
        public void DepthBackProjectedThroughTheWrittenCameraLandsWhereNerfsRaySaysIt()
        {
            using (var temp = new TempFolder())
            {
                var folder = SlamTestData.Monocular(temp.Path, "mono", steps: 3);
                DatasetConverter.Convert(folder, ExportTarget.Replica);
                var output = Path.Combine(folder, "replica");
                var scene = BlenderDatasetLoader.Load(folder);
                var frames = SlamTestData.TrainInTime(scene);
                var read = ReadLikeTheLoaders(output);
                var yaml = Path.Combine(output, "splatam.yaml");
                double fx = SlamTestData.YamlNumber(yaml, "fx"), fy = SlamTestData.YamlNumber(yaml, "fy"), cx = SlamTestData.YamlNumber(yaml, "cx"), cy = SlamTestData.YamlNumber(yaml, "cy");
                var checkedPixels = 0;
                for (var f = 0; f < frames.Count; f++)
                {
                    var depth = PngGray16Reader.Read(read.Depth[f], out var w, out var h);
                    var c2w = frames[f].CameraToWorld;
                    var cv = read.Poses[f];
                    for (var j = 0; j < h; j += 3)
                        for (var i = 0; i < w; i += 3)
                        {
                            var d = depth[j * w + i] / 6553.5;
                            if (d == 0) continue;
                            // The methods' back-projection at the pixel centre (u, v) = (i + ½, j + ½), x right / y down / z forward, then c2w.
                            double u = i + 0.5, v = j + 0.5;
                            var pc = new[] { (u - cx) / fx * d, (v - cy) / fy * d, d, 1 };
                            var world = new double[3];
                            for (var r = 0; r < 3; r++) for (var c = 0; c < 4; c++) world[r] += cv[r, c] * pc[c];
                            // NeRF's ray through the same pixel centre: dir = ((u − W/2)/f, −(v − H/2)/f, −1) in OpenGL axes, z-depth d.
                            var dir = new Vector3d((u - w / 2.0) / fx, -(v - h / 2.0) / fy, -1);
                            var expected = c2w.MultiplyPoint(d * dir);
                            PoseAssert.Close(world, new[] { expected.X, expected.Y, expected.Z }, 1e-9, "pixel (" + i + ", " + j + ") of frame " + f);
                            checkedPixels++;
                        }
                }
                Assert.That(checkedPixels, Is.GreaterThan(50));
            }
        }

        [Test]
        public void AStaticDatasetIsRefusedForWantOfTime()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "still", new AnalyticDataset.Options { Width = 16, Height = 12, Supersampling = 1, Train = 3, Val = 1, Test = 1, PointCloud = 0 });
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Replica));
                Assert.That(e.Problems.Single().Field, Is.EqualTo("time_seconds"));
                Assert.That(e.Problems.Single().Reason, Does.Contain("this dataset has no time"));
                Assert.That(Directory.Exists(Path.Combine(folder, "replica")), Is.False, "nothing written");
            }
        }

        [Test]
        public void ASequenceWithoutDepthIsRefused()
        {
            using (var temp = new TempFolder())
            {
                var folder = SlamTestData.Monocular(temp.Path, "nodepth", steps: 3, width: 16, height: 12, configure: s => s.Train.Depth = ExtraOutput.None);
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Replica));
                Assert.That(e.Problems.Single().Field, Is.EqualTo("depth_path"));
                Assert.That(e.Problems.Single().Reason, Does.Contain("RGB-D sequence"));
            }
        }

        [Test]
        public void AMultiViewCaptureIsRefusedAsSeveralCamerasAtATime()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "multi", new AnalyticDataset.Options { Width = 16, Height = 12, Supersampling = 1, Train = 2, Val = 1, Test = 1, TimeSteps = 2, PointCloud = 0 });
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Replica));
                Assert.That(e.Problems.Single().Field, Is.EqualTo("time_seconds"));
                Assert.That(e.Problems.Single().Reason, Does.Contain("multi-view"));
            }
        }

        [Test]
        public void TrajectoryLineIsTheOpenCvCameraToWorldRowMajor()
        {
            // A camera at (1, 2, 3) looking along +Y (OpenGL −Z = +Y), up +Z: OpenCV x = (1,0,0), y = −up = (0,0,−1), z = (0,1,0).
            var c2w = Matrix4x4d.FromRowMajor(
                1, 0, 0, 1,
                0, 0, -1, 2,
                0, 1, 0, 3,
                0, 0, 0, 1);
            Assert.That(Replica.TrajectoryLine(c2w), Is.EqualTo("1 0 0 1 0 0 1 2 0 -1 0 3 0 0 0 1"));
        }
    }
}
