using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// convert --to tum read back with the TUM readers' code, the same in SplaTAM spla-tam/SplaTAM da6bbcd
    /// datasets/gradslam_datasets/tum.py:44–116, MonoGS muskie82/MonoGS 6c9254c utils/dataset.py:48–122 and Gaussian-SLAM
    /// VladimirYugay/Gaussian-SLAM eaec10d src/entities/datasets.py:75–151: np.loadtxt(delimiter=' ', '#' comments,
    /// groundtruth with skiprows=1), nearest-timestamp association within 0.08 s, the frame_rate = 32 thinning, and
    /// scipy's Rotation.from_quat (scalar-last) for the pose.
    /// </summary>
    public class TumRgbdExportTests
    {
        /// <summary>np.loadtxt(path, delimiter=' ', dtype=str, skiprows): the first skiprows lines go whatever they hold, then '#' lines are comments.</summary>
        static List<string[]> LoadTxt(string path, int skipRows)
        {
            var rows = new List<string[]>();
            foreach (var line in File.ReadAllLines(path).Skip(skipRows))
            {
                var content = line.Split('#')[0];
                if (content.Trim().Length == 0) continue;
                rows.Add(content.Split(' '));
            }
            Assert.That(rows.Select(r => r.Length).Distinct().Count(), Is.EqualTo(1), path + ": loadtxt needs the same column count on every line");
            return rows;
        }

        sealed class Sequence
        {
            public List<string> Colour = new List<string>(), Depth = new List<string>();
            public List<double[,]> Poses = new List<double[,]>();
            public List<double> Times = new List<double>();
        }

        /// <summary>tum.py get_filepaths / load_poses (MonoGS load_poses): associate, thin at 32 fps, pose from (t, q).</summary>
        static Sequence ReadLikeTheLoaders(string folder)
        {
            var image = LoadTxt(Path.Combine(folder, "rgb.txt"), 0);
            var depth = LoadTxt(Path.Combine(folder, "depth.txt"), 0);
            var pose = LoadTxt(Path.Combine(folder, "groundtruth.txt"), 1);
            double T(string s) => double.Parse(s, CultureInfo.InvariantCulture);
            var ti = image.Select(r => T(r[0])).ToArray();
            var td = depth.Select(r => T(r[0])).ToArray();
            var tp = pose.Select(r => T(r[0])).ToArray();
            int ArgMin(double[] a, double t) => Enumerable.Range(0, a.Length).OrderBy(k => Math.Abs(a[k] - t)).ThenBy(k => k).First();
            var associations = new List<(int i, int j, int k)>();
            for (var i = 0; i < ti.Length; i++)
            {
                int j = ArgMin(td, ti[i]), k = ArgMin(tp, ti[i]);
                if (Math.Abs(td[j] - ti[i]) < 0.08 && Math.Abs(tp[k] - ti[i]) < 0.08) associations.Add((i, j, k));
            }
            var indices = new List<int> { 0 };
            for (var a = 1; a < associations.Count; a++)
                if (ti[associations[a].i] - ti[associations[indices[indices.Count - 1]].i] > 1.0 / 32) indices.Add(a);
            var sequence = new Sequence();
            foreach (var a in indices)
            {
                var (i, j, k) = associations[a];
                sequence.Colour.Add(Path.Combine(folder, image[i][1]));
                sequence.Depth.Add(Path.Combine(folder, depth[j][1]));
                sequence.Times.Add(ti[i]);
                var v = pose[k].Skip(1).Select(T).ToArray(); // tx ty tz qx qy qz qw
                // scipy Rotation.from_quat: normalise, scalar-last.
                var n = Math.Sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6]);
                double x = v[3] / n, y = v[4] / n, z = v[5] / n, w = v[6] / n;
                sequence.Poses.Add(new double[,]
                {
                    { 1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), v[0] },
                    { 2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), v[1] },
                    { 2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), v[2] },
                    { 0, 0, 0, 1 },
                });
            }
            return sequence;
        }

        [Test]
        public void TheSequenceReadsBackAsTheLoadersReadIt()
        {
            using (var temp = new TempFolder())
            {
                var folder = SlamTestData.Monocular(temp.Path, "mono");
                var result = DatasetConverter.Convert(folder, ExportTarget.Tum);
                var output = Path.Combine(folder, "tum");
                Assert.That(result.OutputDirectory, Is.EqualTo(output));
                var scene = BlenderDatasetLoader.Load(folder);
                var frames = SlamTestData.TrainInTime(scene);
                var read = ReadLikeTheLoaders(output);
                Assert.That(read.Colour, Has.Count.EqualTo(frames.Count), "5 steps over 1 s are 0.25 s apart: none thinned out");
                Assert.That(result.Warnings.Select(w => w.Field), Has.None.EqualTo("rgb.txt"));
                foreach (var file in new[] { "rgb.txt", "depth.txt", "groundtruth.txt" })
                    Assert.That(File.ReadAllLines(Path.Combine(output, file)).Take(3), Has.All.StartWith("# "), file + " has TUM's three header lines");

                var yaml = Path.Combine(output, "splatam.yaml");
                Assert.That(SlamTestData.YamlNumber(yaml, "fx"), Is.EqualTo(scene.Intrinsics.FlX));
                Assert.That(SlamTestData.YamlNumber(yaml, "cy"), Is.EqualTo(15.0));
                Assert.That(SlamTestData.YamlNumber(yaml, "png_depth_scale"), Is.EqualTo(5000));
                Assert.That(File.ReadAllText(yaml), Does.Contain("dataset_name: 'tum'"));
                Assert.That(SlamTestData.YamlNumber(Path.Combine(output, "gaussian_slam.yaml"), "crop_edge"), Is.EqualTo(0), "tum_rgbd.yaml's 16-pixel crop is for a real lens's border");

                var bg = ProtocolBackground.For(folder);
                for (var i = 0; i < frames.Count; i++)
                {
                    // Real timestamps: the capture's time_seconds (0, 0.25, … 1 for 5 steps over [0, 1] s), to the microsecond.
                    Assert.That(read.Times[i], Is.EqualTo(frames[i].Timing.Seconds.Value).Within(5e-7));
                    Assert.That(read.Times[i], Is.EqualTo(i * 0.25).Within(5e-7));
                    SlamTestData.AssertPose(SlamTestData.OpenCv(frames[i].CameraToWorld), read.Poses[i], 1e-6, "groundtruth line " + i);

                    var depth = PngGray16Reader.Read(read.Depth[i], out _, out _);
                    var source = SlamTestData.SourceDepth(scene, frames[i]);
                    for (var p = 0; p < depth.Length; p++)
                        Assert.That(depth[p] / 5000.0, Is.EqualTo(source[p]).Within(1 / 5000.0), "depth pixel " + p + " of frame " + i);

                    var colour = PngReader.Read(read.Colour[i]);
                    Assert.That(colour.ColorType, Is.EqualTo(PngInfo.ColorTypeRgb), "RGB: MonoGS's np.array(Image.open(…)) would keep a 4th channel");
                    Assert.That(colour.Samples, Is.EqualTo(SlamTestData.ExpectedRgb(scene, frames[i], bg.R, bg.G, bg.B)), "bit-exact composite, frame " + i);
                }
            }
        }

        [Test]
        public void FramesCloserThanTheReadersThirtySecondAreWarnedAndCounted()
        {
            using (var temp = new TempFolder())
            {
                // 41 steps over [0, 1] s are 1/40 s apart: the readers keep a frame only when more than 1/32 s has passed
                // since the last kept one, so they keep steps 0, 2, 4, … (0.05 s apart): 21 of 41.
                var folder = SlamTestData.Monocular(temp.Path, "fast", steps: 41, width: 12, height: 8);
                var result = DatasetConverter.Convert(folder, ExportTarget.Tum);
                var read = ReadLikeTheLoaders(Path.Combine(folder, "tum"));
                Assert.That(read.Colour, Has.Count.EqualTo(21));
                var warning = result.Warnings.Single(w => w.Field == "rgb.txt");
                Assert.That(warning.Value, Does.StartWith("20 of 41 frames"));
                Assert.That(warning.Reason, Does.Contain("they train on 21"));
            }
        }

        [Test]
        public void TheQuaternionIsTheCameraToWorldRotationScalarLast()
        {
            // Camera at (1, 2, 3) looking along +Y, up +Z: OpenCV R = [x y z] with columns (1,0,0), (0,0,−1), (0,1,0), i.e.
            // rows (1,0,0), (0,0,1), (0,−1,0): cos θ = 0 and −sin θ = 1, a −90° turn about x: q = (−sin 45°, 0, 0, cos 45°).
            var c2w = Matrix4x4d.FromRowMajor(
                1, 0, 0, 1,
                0, 0, -1, 2,
                0, 1, 0, 3,
                0, 0, 0, 1);
            var parts = TumRgbd.PoseLine("0.500000", c2w).Split(' ').Select(s => double.Parse(s, CultureInfo.InvariantCulture)).ToArray();
            Assert.That(parts.Take(4), Is.EqualTo(new[] { 0.5, 1, 2, 3 }));
            Assert.That(parts.Skip(4), Is.EqualTo(new[] { -Math.Sqrt(0.5), 0, 0, Math.Sqrt(0.5) }).Within(1e-15));
        }

        [Test]
        public void AStaticDatasetIsRefusedForWantOfTime()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "still", new AnalyticDataset.Options { Width = 16, Height = 12, Supersampling = 1, Train = 3, Val = 1, Test = 1, PointCloud = 0 });
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Tum));
                Assert.That(e.Problems.Single().Field, Is.EqualTo("time_seconds"));
                Assert.That(e.Problems.Single().Reason, Does.Contain("--to tum"));
                Assert.That(Directory.Exists(Path.Combine(folder, "tum")), Is.False, "nothing written");
            }
        }
    }
}
