using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.IO.Compression;
using System.Linq;
using System.Text;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <c>convert --to nsff</c> read back as Neural Scene Flow Fields reads a scene (zhengqili/Neural-Scene-Flow-Fields
    /// d400175): a re-implementation of nsff_exp/load_llff.py <c>_load_data</c> (10–117) and <c>load_llff_data</c>'s
    /// pose reordering (314–335), run_nerf_helpers.py <c>read_optical_flow</c> (579–600) as run_nerf.py calls it per
    /// frame (347–360) and adds the pixel grid (317, 410–411), and np.load of .npy / .npz. Compared with our flow, masks
    /// and scene flow, with where static points land from the depth EXRs and the poses NSFF reads (pins sign and axes),
    /// and with the dataset's depth.
    /// </summary>
    [TestFixture]
    public class NsffExportTests
    {
        const int W = FlowExportDataset.Width, H = FlowExportDataset.Height;
        TempFolder _temp;
        string _dataset, _export;

        [OneTimeSetUp]
        public void Write()
        {
            _temp = new TempFolder();
            _dataset = FlowExportDataset.Write(_temp.Path, "mono", monocular: true);
            _export = _temp.Combine("nsff");
            DatasetConverter.Convert(_dataset, ExportTarget.Nsff, _export);
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        /// <summary>np.load of a .npy: the header dict's descr and shape, then the C-order data ('&lt;f4', '&lt;f8', '|u1', '|b1').</summary>
        static (string Descr, int[] Shape, double[] Values) NpLoad(byte[] bytes)
        {
            Assert.That(bytes[0] == 0x93 && Encoding.ASCII.GetString(bytes, 1, 5) == "NUMPY", Is.True);
            int headerLength = bytes[8] | (bytes[9] << 8);
            var header = Encoding.ASCII.GetString(bytes, 10, headerLength);
            var descr = header.Split(new[] { "'descr': '" }, StringSplitOptions.None)[1].Split('\'')[0];
            Assert.That(header, Does.Contain("'fortran_order': False"));
            var shapeText = header.Split(new[] { "'shape': (" }, StringSplitOptions.None)[1].Split(')')[0];
            var shape = shapeText.Split(',').Select(s => s.Trim()).Where(s => s.Length > 0).Select(s => int.Parse(s, CultureInfo.InvariantCulture)).ToArray();
            var count = shape.Aggregate(1, (a, b) => a * b);
            var data = 10 + headerLength;
            var values = new double[count];
            for (var i = 0; i < count; i++)
                switch (descr)
                {
                    case "<f4": values[i] = BitConverter.ToSingle(bytes, data + 4 * i); break;
                    case "<f8": values[i] = BitConverter.ToDouble(bytes, data + 8 * i); break;
                    case "|u1":
                    case "|b1": values[i] = bytes[data + i]; break;
                    default: Assert.Fail("np.load of " + descr + " is not re-implemented here"); break;
                }
            return (descr, shape, values);
        }

        static Dictionary<string, (string Descr, int[] Shape, double[] Values)> NpzLoad(string path)
        {
            var arrays = new Dictionary<string, (string, int[], double[])>();
            using (var zip = ZipFile.OpenRead(path))
                foreach (var entry in zip.Entries)
                    using (var stream = entry.Open())
                    using (var memory = new MemoryStream())
                    {
                        stream.CopyTo(memory);
                        arrays[entry.FullName.Substring(0, entry.FullName.Length - 4)] = NpLoad(memory.ToArray()); // np.load(npz)[key]: key.npy
                    }
            return arrays;
        }

        sealed class Loaded
        {
            public double[][,] Poses; // per image, the 3 × 5 [c0 c1 c2 t hwf] after load_llff_data's reordering: OpenGL [right up back]
            public double[][] Bds;
            public int ImageCount;
            public List<double[]> Disp = new List<double[]>();
            public List<double[]> Masks = new List<double[]>();
        }

        /// <summary>_load_data(basedir, start_frame=0, end_frame=n, height=final_height) and load_llff_data's pose reordering.</summary>
        static Loaded LoadData(string basedir, int startFrame, int endFrame, int finalHeight)
        {
            var loaded = new Loaded();
            // :14–18: poses_arr = np.load('poses_bounds.npy')[start:end]; poses = [:, :-2].reshape([-1, 3, 5]); bds = [:, -2:].
            var arr = NpLoad(File.ReadAllBytes(Path.Combine(basedir, "poses_bounds.npy")));
            Assert.That(arr.Descr, Is.EqualTo("<f8"));
            Assert.That(arr.Shape[1], Is.EqualTo(17));
            var rows = Math.Min(arr.Shape[0], endFrame) - startFrame;
            loaded.Poses = new double[rows][,];
            loaded.Bds = new double[rows][];
            for (var i = 0; i < rows; i++)
            {
                var p = new double[3, 5];
                for (var r = 0; r < 3; r++) for (var c = 0; c < 5; c++) p[r, c] = arr.Values[17 * (startFrame + i) + 5 * r + c];
                // load_llff_data :328–330: np.concatenate([poses[:, 1:2], -poses[:, 0:1], poses[:, 2:]], 1).
                var reordered = new double[3, 5];
                for (var r = 0; r < 3; r++)
                {
                    reordered[r, 0] = p[r, 1];
                    reordered[r, 1] = -p[r, 0];
                    for (var c = 2; c < 5; c++) reordered[r, c] = p[r, c];
                }
                loaded.Poses[i] = reordered;
                loaded.Bds[i] = new[] { arr.Values[17 * (startFrame + i) + 15], arr.Values[17 * (startFrame + i) + 16] };
            }
            // :20–22: img0 = the first of sorted(os.listdir('images')) ending in JPG/jpg/png; sh = imread(img0).shape.
            bool IsImage(string f) => f.EndsWith("JPG", StringComparison.Ordinal) || f.EndsWith("jpg", StringComparison.Ordinal) || f.EndsWith("png", StringComparison.Ordinal);
            var img0 = Sorted(Path.Combine(basedir, "images")).First(IsImage);
            var sh = PngReader.Read(Path.Combine(basedir, "images", img0));
            // :30–34: height given → factor = sh[0] / height; width = int(round(sh[1] / factor)); sfx = '_{}x{}'.format(width, height).
            var factor = sh.Height / (double)finalHeight;
            var width = (int)Math.Round(sh.Width / factor);
            var imgdir = Path.Combine(basedir, "images_" + width + "x" + finalHeight); // :44
            Assert.That(Directory.Exists(imgdir), Is.True, imgdir + " (:45–47 returns None without it)");
            var imgfiles = Sorted(imgdir).Where(IsImage).Skip(startFrame).Take(endFrame - startFrame).ToList(); // :49–51
            Assert.That(imgfiles.Count, Is.EqualTo(rows), "Mismatch between imgs and poses (:53–56)");
            loaded.ImageCount = imgfiles.Count;
            foreach (var f in imgfiles)
            {
                var image = PngReader.Read(Path.Combine(imgdir, f)); // :71 imread(f)[..., :3] / 255
                Assert.That((image.Width, image.Height), Is.EqualTo((W, H)));
            }
            for (var i = 0; i < rows; i++)
            {
                // :59–60: poses[:2, 4] = sh[:2] of the images read; poses[2, 4] *= 1 / factor.
                loaded.Poses[i][0, 4] = sh.Height;
                loaded.Poses[i][1, 4] = sh.Width;
                loaded.Poses[i][2, 4] /= factor;
            }
            // :77–86: disp/ sorted *.npy, [start:end], read_MiDaS_disp = np.load, resized (nearest) to the image size.
            foreach (var f in Sorted(Path.Combine(basedir, "disp")).Where(f => f.EndsWith("npy", StringComparison.Ordinal)).Skip(startFrame).Take(endFrame - startFrame))
            {
                var disp = NpLoad(File.ReadAllBytes(Path.Combine(basedir, "disp", f)));
                Assert.That(disp.Shape, Is.EqualTo(new[] { H, W }), "cv2.resize to the image size is then the identity");
                loaded.Disp.Add(disp.Values);
            }
            // :88–96: motion_masks/ sorted *.png, imread / 255, masks > 1e-3.
            foreach (var f in Sorted(Path.Combine(basedir, "motion_masks")).Where(f => f.EndsWith("png", StringComparison.Ordinal)).Skip(startFrame).Take(endFrame - startFrame))
            {
                var mask = PngReader.Read(Path.Combine(basedir, "motion_masks", f));
                Assert.That((mask.Width, mask.Height, mask.Channels), Is.EqualTo((W, H, 1)));
                loaded.Masks.Add(mask.Samples.Select(b => b / 255.0 > 1e-3 ? 1.0 : 0.0).ToArray());
            }
            // :111–115: the image, disparity and mask counts and sizes agree.
            Assert.That(loaded.Disp.Count, Is.EqualTo(loaded.ImageCount));
            Assert.That(loaded.Masks.Count, Is.EqualTo(loaded.ImageCount));
            return loaded;
        }

        static List<string> Sorted(string dir) => Directory.GetFiles(dir).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal).ToList();

        /// <summary>read_optical_flow(basedir, img_i, start_frame, fwd): flow_i1/%05d_fwd.npz or _bwd.npz, keys flow and mask, np.float32(mask).</summary>
        static (double[] Flow, double[] Mask) ReadOpticalFlow(string basedir, int imgI, int startFrame, bool fwd)
        {
            var path = Path.Combine(basedir, "flow_i1", (startFrame + imgI).ToString("00000", CultureInfo.InvariantCulture) + (fwd ? "_fwd.npz" : "_bwd.npz"));
            var data = NpzLoad(path);
            Assert.That(data["flow"].Shape, Is.EqualTo(new[] { H, W, 2 }));
            Assert.That(data["flow"].Descr, Is.EqualTo("<f4"));
            Assert.That(data["mask"].Shape, Is.EqualTo(new[] { H, W }));
            return (data["flow"].Values, data["mask"].Values);
        }

        string Scene => Path.Combine(_export, "train");

        [Test]
        public void TheLoaderReadsTheSceneAndThePosesAreTheDatasets()
        {
            var loaded = LoadData(Scene, 0, 5, H);
            var frames = FlowRecord.Read(_dataset).Video("train").Frames;
            var f = FlowExportDataset.Focal(_dataset);
            for (var i = 0; i < 5; i++)
            {
                var pose = FlowExportDataset.Pose(_dataset, frames[i].Image);
                for (var r = 0; r < 3; r++)
                    for (var c = 0; c < 4; c++)
                        Assert.That(loaded.Poses[i][r, c], Is.EqualTo(pose[r, c]).Within(1e-9), "c2w " + r + "," + c + " of image " + i);
                Assert.That(new[] { loaded.Poses[i][0, 4], loaded.Poses[i][1, 4], loaded.Poses[i][2, 4] }, Is.EqualTo(new[] { H, W, f }).Within(1e-9));
                Assert.That(loaded.Bds[i][0], Is.GreaterThan(0).And.LessThan(loaded.Bds[i][1]));
            }
        }

        [Test]
        public void TheFlowIsOursFromTheFramesRunNerfReadsAndTheMaskIsVisibleInTheOtherFrame()
        {
            var record = FlowRecord.Read(_dataset);
            int visible = 0, hidden = 0;
            for (var imgI = 0; imgI < 5; imgI++)
            {
                // run_nerf.py:347–360: image 0 reads fwd only, the last bwd only, the others both.
                var reads = imgI == 0 ? new[] { true } : imgI == 4 ? new[] { false } : new[] { true, false };
                foreach (var fwd in reads)
                {
                    var (flow, mask) = ReadOpticalFlow(Scene, imgI, 0, fwd);
                    var pair = record.Pairs.Single(p => p.Video == "train" && p.From == imgI && p.To == imgI + (fwd ? 1 : -1));
                    var ours = FloFile.Read(Path.Combine(_dataset, pair.FlowFile), out _, out _);
                    var occluded = PngReader.Read(Path.Combine(_dataset, pair.OccludedFile)).Samples;
                    var outside = PngReader.Read(Path.Combine(_dataset, pair.OutsideFile)).Samples;
                    for (var p = 0; p < W * H; p++)
                    {
                        var none = float.IsNaN(ours[2 * p]);
                        Assert.That(flow[2 * p], Is.EqualTo(none ? 0 : ours[2 * p]), "dx at " + p);
                        Assert.That(flow[2 * p + 1], Is.EqualTo(none ? 0 : ours[2 * p + 1]), "dy at " + p);
                        var expected = !none && occluded[p] == 0 && outside[p] == 0 ? 1.0 : 0.0;
                        Assert.That(mask[p], Is.EqualTo(expected), "mask at " + p);
                        if (expected == 1) visible++;
                        else if (!none) hidden++;
                    }
                }
                Assert.That(File.Exists(Path.Combine(Scene, "flow_i1", imgI.ToString("00000") + "_fwd.npz")), Is.EqualTo(imgI < 4), "no forward flow from the last frame");
                Assert.That(File.Exists(Path.Combine(Scene, "flow_i1", imgI.ToString("00000") + "_bwd.npz")), Is.EqualTo(imgI > 0), "no backward flow from the first frame");
            }
            Assert.That(visible, Is.GreaterThan(1500));
            Assert.That(hidden, Is.GreaterThan(0), "some points are hidden or outside at the other frame (mask 0 with a flow)");
        }

        [Test]
        public void FlowPlusThePixelGridIsWhereStaticPointsLandByNsffsPosesAndProjection()
        {
            var loaded = LoadData(Scene, 0, 5, H);
            var frames = FlowRecord.Read(_dataset).Video("train").Frames;
            var checkedPixels = 0;
            for (var imgI = 0; imgI < 5; imgI++)
            {
                var depth = ExrReader.Read(Path.Combine(_dataset, FlowExportDataset.DepthExr(frames[imgI].Image)));
                foreach (var fwd in new[] { true, false })
                {
                    var other = imgI + (fwd ? 1 : -1);
                    if (other < 0 || other > 4) continue;
                    var (flow, mask) = ReadOpticalFlow(Scene, imgI, 0, fwd);
                    var here = Pose(loaded.Poses[imgI]);
                    var there = Pose(loaded.Poses[other]);
                    var focal = loaded.Poses[imgI][2, 4];
                    for (var v = 0; v < H; v++)
                        for (var u = 0; u < W; u++)
                        {
                            var p = v * W + u;
                            if (mask[p] == 0 || loaded.Masks[imgI][p] != 0) continue; // visible and static (motion mask 0)
                            var landing = FlowExportDataset.StaticLanding(depth, here, there, focal, u, v);
                            if (landing == null) continue;
                            // run_nerf.py:317, 410–411: target = flow + uv_grid (kornia create_meshgrid, (x, y) = (column, row) indices);
                            // perspective_projection (run_nerf_helpers.py:522–526) gives continuous x = f·X/−Z + W/2, the pixel index + 0.5.
                            Assert.That(flow[2 * p] + u, Is.EqualTo(landing.Value.X - 0.5).Within(0.05), "x at " + u + "," + v + " image " + imgI + (fwd ? " fwd" : " bwd"));
                            Assert.That(flow[2 * p + 1] + v, Is.EqualTo(landing.Value.Y - 0.5).Within(0.05), "y");
                            checkedPixels++;
                        }
                }
            }
            Assert.That(checkedPixels, Is.GreaterThan(1000));
        }

        static Matrix4x4d Pose(double[,] p) => Matrix4x4d.FromRows(new[]
        {
            new[] { p[0, 0], p[0, 1], p[0, 2], p[0, 3] },
            new[] { p[1, 0], p[1, 1], p[1, 2], p[1, 3] },
            new[] { p[2, 0], p[2, 1], p[2, 2], p[2, 3] },
            new[] { 0.0, 0, 0, 1 },
        });

        [Test]
        public void MotionMasksAreWhereTheSceneFlowIsNotZeroAndDisparityIsOneOverDepth()
        {
            var loaded = LoadData(Scene, 0, 5, H);
            var record = FlowRecord.Read(_dataset);
            var frames = record.Video("train").Frames;
            int moving = 0, still = 0;
            for (var t = 0; t < 5; t++)
            {
                var expected = new bool[W * H];
                foreach (var other in new[] { t - 1, t + 1 })
                {
                    if (other < 0 || other > 4) continue;
                    var sf = ExrReader.Read(Path.Combine(_dataset, record.Pairs.Single(p => p.Video == "train" && p.From == t && p.To == other).SceneFlowFile));
                    for (var p = 0; p < W * H; p++)
                        if (sf.Channel("A")[p] != 0 && (sf.Channel("R")[p] != 0 || sf.Channel("G")[p] != 0 || sf.Channel("B")[p] != 0)) expected[p] = true;
                }
                var depth = ExrReader.Read(Path.Combine(_dataset, FlowExportDataset.DepthExr(frames[t].Image)));
                for (var p = 0; p < W * H; p++)
                {
                    Assert.That(loaded.Masks[t][p], Is.EqualTo(expected[p] ? 1.0 : 0.0), "motion mask at " + p + " of frame " + t);
                    if (expected[p]) moving++; else still++;
                    var z = depth.Channel("Y")[p];
                    if (z > 0 && !float.IsInfinity(z))
                        // The depth PNG holds z in steps of 1e-3 output units: 1 / z within that rounding.
                        Assert.That(loaded.Disp[t][p], Is.EqualTo(1 / z).Within(1e-3 / (z * z) + 1e-6), "disparity at " + p);
                    else Assert.That(loaded.Disp[t][p], Is.EqualTo(0), "no surface: disparity 0");
                }
            }
            Assert.That(moving, Is.GreaterThan(100));
            Assert.That(still, Is.GreaterThan(1000));
        }

        [Test]
        public void MultiViewWritesOneSceneFolderPerVideoAndTheRecordSaysWhatEachFileHolds()
        {
            var dataset = FlowExportDataset.Write(_temp.Path, "multi", monocular: false);
            var output = _temp.Combine("nsff-multi");
            var result = DatasetConverter.Convert(dataset, ExportTarget.Nsff, output);
            var folders = Directory.GetDirectories(output).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal);
            Assert.That(folders, Is.EqualTo(new[] { "test_cam00", "train_cam00", "train_cam01", "val_cam00" }));
            var loaded = LoadData(Path.Combine(output, "val_cam00"), 0, 3, H);
            Assert.That(loaded.ImageCount, Is.EqualTo(3));
            Assert.That(result.TrainCommands, Has.Count.EqualTo(4));
            Assert.That(result.TrainCommands[0], Does.Contain("--final_height 48 --start_frame 0 --end_frame 3 --target_idx 2"));
            var record = JObject.Parse(File.ReadAllText(Path.Combine(output, Nsff.RecordFileName)));
            foreach (var key in new[] { "images/%05d.png", "poses_bounds.npy", "disp/%05d.npy", "motion_masks/%05d.png", "flow_i1/%05d_fwd.npz", "flow_i1/%05d_bwd.npz" })
                Assert.That((string)record["files"][key], Is.Not.Empty, key);
        }

        [Test]
        public void ADatasetWithoutFlowOrSceneFlowIsRefusedNamingTheFix()
        {
            var plain = AnalyticDataset.Write(_temp.Path, "noflow", new AnalyticDataset.Options { Width = 32, Height = 24, Supersampling = 1, Train = 3, Val = 1, Test = 1, TimeSteps = 3, Monocular = true, PointCloud = 0 });
            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(plain, ExportTarget.Nsff, _temp.Combine("nsff-noflow")));
            Assert.That(e.Message, Does.Contain("flow/flow.json").And.Contain("nerf-dataset flow <dataset>"));
            Assert.That(Directory.Exists(_temp.Combine("nsff-noflow", "train")), Is.False);
            var noSceneFlow = FlowExportDataset.Write(_temp.Path, "nosf", monocular: true, new FlowSettings { On = true, SceneFlow = false });
            e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(noSceneFlow, ExportTarget.Nsff, _temp.Combine("nsff-nosf")));
            Assert.That(e.Message, Does.Contain("motion_masks").And.Contain("--no-scene-flow"));
        }
    }
}
