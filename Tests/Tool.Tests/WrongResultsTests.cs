using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// Issue 22, "Wrong results and unclear errors": each case of the trial, run through the tool as a user would,
    /// with faults injected through <see cref="FileOps"/> and a real process where a kill is involved.
    /// </summary>
    [TestFixture]
    public class WrongResultsTests
    {
        Scratch _scratch;
        string _dataset;

        [SetUp]
        public void SetUp()
        {
            _scratch = new Scratch();
            _dataset = RenderedDataset.Create(_scratch, "ds");
        }

        [TearDown]
        public void TearDown()
        {
            FileOps.Faults = null;
            _scratch.Dispose();
        }

        string Transforms(string split) => Path.Combine(_dataset, "transforms_" + split + ".json");

        void EditJson(string split, Action<JObject> change)
        {
            var json = JObject.Parse(File.ReadAllText(Transforms(split)));
            change(json);
            File.WriteAllText(Transforms(split), json.ToString());
        }

        void EmptySplit(string split)
        {
            EditJson(split, j => j["frames"] = new JArray());
            Directory.Delete(Path.Combine(_dataset, split), true);
        }

        /// <summary>Every frame's image path relative to the dataset (train/r_0.png, …), as RenderedDataset writes them.</summary>
        static string[] Images() =>
            new[] { ("train", RenderedDataset.Train), ("val", RenderedDataset.Val), ("test", RenderedDataset.Test) }
                .SelectMany(s => Enumerable.Range(0, s.Item2).Select(i => s.Item1 + "/r_" + i + ".png")).ToArray();

        static string DepthOf(string image) => image.Substring(0, image.Length - 4) + "_depth_0000.png";

        /// <summary>A 16-bit grey depth PNG of the images' size beside every image, named by each frame's depth_path (keys only: never guessed).</summary>
        void AddDepth()
        {
            var png = TestPng.Encode(RenderedDataset.Width, RenderedDataset.Height, 16, PngInfo.ColorTypeGray);
            foreach (var image in Images()) File.WriteAllBytes(Path.Combine(_dataset, DepthOf(image)), png);
            foreach (var split in new[] { "train", "val", "test" })
                EditJson(split, j =>
                {
                    foreach (JObject frame in (JArray)j["frames"])
                        frame["depth_path"] = "./" + DepthOf(((string)frame["file_path"]).Substring(2) + ".png");
                });
        }

        // ---- Empty splits -------------------------------------------------------------------------------------------

        [TestCase("nerfstudio", "val")]
        [TestCase("nerfstudio", "test")]
        [TestCase("colmap", "val")]
        [TestCase("colmap", "test")]
        [TestCase("ngp", "val")]
        [TestCase("ngp", "test")]
        public void AnEmptyValOrTestSplitConverts(string target, string split)
        {
            EmptySplit(split);
            var validate = ToolRun.Of("validate", _dataset);
            Assert.That(validate.ExitCode, Is.EqualTo(0), validate.ToString());
            var run = ToolRun.Of("convert", _dataset, "--to", target);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.Contain("converted " + _dataset + " to " + target));
        }

        [Test]
        public void AnEmptyTrainSplitIsRefusedNamingTheSplitFile()
        {
            EmptySplit("train");
            var run = ToolRun.Of("convert", _dataset, "--to", "nerfstudio");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("error: transforms_train.json"));
            Assert.That(run.Err, Does.Contain("every loader trains on the train split"));
            Assert.That(File.Exists(Path.Combine(_dataset, "transforms.json")), Is.False);
        }

        // ---- Unusable depth PNGs --------------------------------------------------------------------------------------

        /// <summary>The four kinds of unusable depth file of the trial, one per frame, the other frames' depth good.</summary>
        string[] SpoilDepth()
        {
            AddDepth();
            var eightBit = DepthOf("train/r_0.png");
            File.WriteAllBytes(Path.Combine(_dataset, eightBit), TestPng.Encode(RenderedDataset.Width, RenderedDataset.Height, 8, PngInfo.ColorTypeGray));
            var wrongSize = DepthOf("train/r_1.png");
            File.WriteAllBytes(Path.Combine(_dataset, wrongSize), TestPng.Encode(RenderedDataset.Width + 1, RenderedDataset.Height, 16, PngInfo.ColorTypeGray));
            // A valid 16-bit PNG whose IHDR claims 65535 × 65535 (CRC recomputed, so only the size is wrong).
            var huge = DepthOf("val/r_0.png");
            var bytes = TestPng.Encode(RenderedDataset.Width, RenderedDataset.Height, 16, PngInfo.ColorTypeGray);
            foreach (var offset in new[] { 16, 20 }) { bytes[offset] = 0; bytes[offset + 1] = 0; bytes[offset + 2] = 0xFF; bytes[offset + 3] = 0xFF; }
            var crc = Crc32.Compute(bytes, 12, 17);
            bytes[29] = (byte)(crc >> 24); bytes[30] = (byte)(crc >> 16); bytes[31] = (byte)(crc >> 8); bytes[32] = (byte)crc;
            File.WriteAllBytes(Path.Combine(_dataset, huge), bytes);
            var truncated = DepthOf("test/r_0.png");
            var whole = TestPng.Encode(RenderedDataset.Width, RenderedDataset.Height, 16, PngInfo.ColorTypeGray);
            File.WriteAllBytes(Path.Combine(_dataset, truncated), whole.Take(whole.Length / 2).ToArray());
            return new[] { eightBit, wrongSize, huge, truncated };
        }

        [Test]
        public void ColmapDepthsRefusesEveryUnusableDepthPngNamingEach()
        {
            var bad = SpoilDepth();
            var run = ToolRun.Of("convert", _dataset, "--to", "colmap", "--depths");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            foreach (var file in bad)
                Assert.That(run.Err.Split('\n').Count(l => l.StartsWith("error: ", StringComparison.Ordinal) && l.Contains(file)), Is.EqualTo(1), file + "\n" + run);
            Assert.That(run.Err, Does.Contain("convert refused: 4 problems"));
            Assert.That(Directory.Exists(Path.Combine(_dataset, "colmap")), Is.False, "nothing written");
        }

        [Test]
        public void WithoutDepthsTheUnusableDepthPngsAreNamedInWarningsAndLeftOut()
        {
            var bad = SpoilDepth();
            var run = ToolRun.Of("convert", _dataset, "--to", "nerfstudio");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            foreach (var file in bad)
                Assert.That(run.Err.Split('\n').Count(l => l.StartsWith("warning: ", StringComparison.Ordinal) && l.Contains(file)), Is.EqualTo(1), file + "\n" + run);
            Assert.That(File.ReadAllText(Path.Combine(_dataset, "transforms.json")), Does.Not.Contain("depth_file_path"), "depth on some frames only is left out");
        }

        // ---- Imported cameras ---------------------------------------------------------------------------------------

        string PlanConfig(string source, int trainCount = 3, string time = null) =>
            _scratch.WriteText("config.json", "{ \"width\": 32, \"height\": 24, \"splits\": { \"train\": { \"count\": " + trainCount +
                ", \"source\": { \"kind\": \"imported\", \"path\": " + JToken.FromObject(source).ToString(Newtonsoft.Json.Formatting.None) + ", \"fileSplit\": \"\" } }, \"val\": { \"count\": 1 }, \"test\": { \"count\": 1 } }" +
                (time == null ? "" : ", \"time\": " + time) + " }");

        [Test]
        public void AColmapCameraCentreThatOverflowsIsASettingsErrorNamingImagesTxtAndTheLine()
        {
            var model = _scratch.PathOf("model");
            Directory.CreateDirectory(model);
            File.WriteAllText(Path.Combine(model, "cameras.txt"), "# a model\n1 PINHOLE 32 24 30 30 16 12\n");
            // 45° about x: the centre −Rᵀt adds two components of 1.7e308, beyond the largest double.
            File.WriteAllText(Path.Combine(model, "images.txt"),
                "# images\n2 1 0 0 0 0 0 4 1 train_r_1.png\n\n1 0.9238795325112867 0.3826834323650898 0 0 0 1.7e308 1.7e308 1 train_r_0.png\n\n");
            var run = ToolRun.Of("plan", "--config", PlanConfig(model), "--out", _scratch.PathOf("planned"));
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("images.txt line 4"));
            Assert.That(run.Err, Does.Contain("NaN or infinite"));
            Assert.That(run.Err, Does.Not.Contain("unexpected"));
            Assert.That(Directory.Exists(_scratch.PathOf("planned")), Is.False);
        }

        [Test]
        public void AThreeGigabyteTransformsFileIsRefusedNamingItBeforeItIsRead()
        {
            var big = _scratch.PathOf("huge_transforms.json");
            using (var file = new FileStream(big, FileMode.CreateNew)) file.SetLength(3L << 30); // sparse: no disk used
            var run = ToolRun.Of("plan", "--config", PlanConfig(big), "--out", _scratch.PathOf("planned"));
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain(big));
            Assert.That(run.Err, Does.Contain(big + ": is 3 GiB"));
            Assert.That(run.Err, Does.Not.Contain("memory"));
        }

        [Test]
        public void AThreeGigabyteSplitFileIsAProblemNamingItInValidateAndConvert()
        {
            File.Delete(Transforms("val"));
            using (var file = new FileStream(Transforms("val"), FileMode.CreateNew)) file.SetLength(3L << 30);
            var validate = ToolRun.Of("validate", _dataset);
            Assert.That(validate.ExitCode, Is.EqualTo(1), validate.ToString());
            Assert.That(validate.Out, Does.Contain("problem: transforms_val.json: is 3 GiB, more than the 512 MiB"));
            var convert = ToolRun.Of("convert", _dataset, "--to", "ngp");
            Assert.That(convert.ExitCode, Is.EqualTo(1), convert.ToString());
            Assert.That(convert.Err, Does.Contain("error: transforms_val.json = " + Transforms("val") + ": is 3 GiB"));
            Assert.That(validate.Out + convert.Err, Does.Not.Contain("memory").And.Not.Contain("permissions"));
        }

        [Test]
        public void AMonocularCaptureWithImportedTrainCamerasIgnoresTheTrainCount()
        {
            var run = ToolRun.Of("plan", "--config", PlanConfig(Fixtures.LegoTrainPath, 1, "{ \"mode\": \"monocular\", \"start\": 0, \"end\": 2 }"), "--out", _scratch.PathOf("planned"));
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.Contain("planned 100 train"));
            var frames = JObject.Parse(File.ReadAllText(_scratch.PathOf("planned", "transforms_train.json")))["frames"];
            Assert.That(frames.Count(), Is.EqualTo(100));
            Assert.That((double)frames[99]["time"], Is.EqualTo(1.0), "one train view per time step, the last at the end");
        }

        [Test]
        public void AMonocularCaptureWhoseImportedFileHoldsOneCameraIsRefusedNamingTheSource()
        {
            var one = _scratch.WriteText("one.json", "{ \"camera_angle_x\": 0.69, \"frames\": [ { \"file_path\": \"./train/r_0\", \"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]] } ] }");
            var run = ToolRun.Of("plan", "--config", PlanConfig(one, 5, "{ \"mode\": \"monocular\", \"start\": 0, \"end\": 2 }"), "--out", _scratch.PathOf("planned"));
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("splits.train.source"));
            Assert.That(run.Err, Does.Contain("1 camera"));
        }

        // ---- points3d.ply ---------------------------------------------------------------------------------------------

        /// <summary>Writes <paramref name="bytes"/> as the dataset's points3d.ply and records it in dataset_config.json as this plugin's own.</summary>
        string OwnPly(byte[] bytes, int points)
        {
            var ply = Path.Combine(_dataset, PointCloudOwnership.FileName);
            File.WriteAllBytes(ply, bytes);
            File.WriteAllText(Path.Combine(_dataset, "dataset_config.json"),
                new JObject { [PointCloudRecord.Key] = PointCloudRecord.Of(ply, PointCloudOwnership.FileName, points).ToJson() }.ToString());
            return ply;
        }

        [Test]
        public void APlyHeaderClaimingTwoBillionPointsIsRefusedNamingTheFile()
        {
            var ply = OwnPly(System.Text.Encoding.ASCII.GetBytes(PlyWriter.Header(2000000000)).Concat(new byte[27]).ToArray(), 2000000000);
            var run = ToolRun.Of("convert", _dataset, "--to", "colmap");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("error: points3d.ply = " + ply + ": is truncated"));
            Assert.That(run.Err, Does.Contain("2000000000 points"));
            Assert.That(run.Err, Does.Not.Contain("memory"));
        }

        [Test]
        public void ATruncatedPlyIsRefusedNamingTheFile()
        {
            using (var stream = new MemoryStream())
            {
                PlyWriter.Write(stream, Enumerable.Range(0, 10).Select(i => new CloudPoint(new Vector3d(i, 0, 0), Vector3d.UnitZ, 1, 2, 3)).ToList());
                var bytes = stream.ToArray();
                var ply = OwnPly(bytes.Take(bytes.Length - 10).ToArray(), 10);
                var run = ToolRun.Of("convert", _dataset, "--to", "colmap");
                Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
                Assert.That(run.Err, Does.Contain("error: points3d.ply = " + ply + ": is truncated"));
                Assert.That(Interruptions.HasStackTrace(run.Err), Is.False);
            }
        }

        // ---- I/O errors name their file -------------------------------------------------------------------------------

        [Test]
        public void ADiskFullWhileWritingDepthMapsNamesTheFile()
        {
            AddDepth();
            FileOps.Faults = FileFaultPlan.FailingAt(1, (op, path) => new IOException("No space left on device"),
                path => path.Contains(Path.DirectorySeparatorChar + "depths" + Path.DirectorySeparatorChar));
            var run = ToolRun.Of("convert", _dataset, "--to", "colmap", "--depths");
            FileOps.Faults = null;
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            var error = run.Err.Split('\n').Single(l => l.StartsWith("error: ", StringComparison.Ordinal));
            Assert.That(error, Does.Contain("No space left on device"));
            Assert.That(error, Does.Contain(Path.Combine("depths", "train_r_0.png")));
            Assert.That(Interruptions.Entries(_dataset).Where(e => e.StartsWith("colmap", StringComparison.Ordinal)), Is.Empty, "the working folder was removed");
        }

        // ---- Interrupted and racing converts -------------------------------------------------------------------------

        [Test]
        public void AConvertKilledWhileDeletingItsEmptiedWorkingFolderIsFinishedByTheRerun()
        {
            var args = new[] { "convert", _dataset, "--to", "colmap" };
            var output = Path.Combine(_dataset, "colmap");
            // Where the working folder is deleted, in a dry run on a copy (same steps).
            var copy = RenderedDataset.Create(_scratch, "copy");
            var counting = FileFaultPlan.Counting();
            FileOps.Faults = counting;
            var dry = ToolRun.Of("convert", copy, "--to", "colmap");
            FileOps.Faults = null;
            Assert.That(dry.ExitCode, Is.EqualTo(0), dry.ToString());
            var step = counting.Operations.ToList().FindIndex(o => o.StartsWith("delete folder ", StringComparison.Ordinal) && o.Contains(".convert.partial-")) + 1;
            Assert.That(step, Is.GreaterThan(0), string.Join("\n", counting.Operations));

            var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            start.ArgumentList.Add(typeof(Program).Assembly.Location);
            foreach (var a in args) start.ArgumentList.Add(a);
            start.Environment[Program.KillVariable] = step.ToString(System.Globalization.CultureInfo.InvariantCulture);
            using (var process = Process.Start(start))
            {
                var err = process.StandardError.ReadToEndAsync();
                var outText = process.StandardOutput.ReadToEnd();
                Assert.That(process.WaitForExit(60000), Is.True);
                Assert.That(process.ExitCode, Is.EqualTo(137), "killed by SIGKILL (128 + 9)\n" + outText + err.Result);
            }
            // The kill came in the middle of the recursive delete: the files it had unlinked are gone, the folders remain.
            var working = Directory.GetDirectories(output, ".convert.partial-*").Single();
            foreach (var file in Directory.GetFiles(working, "*", SearchOption.AllDirectories)) File.Delete(file);

            var again = ToolRun.Of(args);
            Assert.That(again.ExitCode, Is.EqualTo(0), again.ToString());
            Assert.That(again.Out, Does.Contain("(the interrupted earlier convert, now finished)"));
            Assert.That(again.Err, Does.Not.Contain("already exists"));
            Assert.That(Interruptions.Entries(output), Is.EqualTo(new[] { "eval_protocol.json", "images", "sparse" }));
            Assert.That(Directory.GetFiles(Path.Combine(output, "images")).Length, Is.EqualTo(Images().Length));
        }

        [Test]
        public void WhenTwoConvertsRaceTheLoserRemovesItsOwnWorkingFolder()
        {
            var args = new[] { "convert", _dataset, "--to", "nerfstudio" };
            var steps = Interruptions.Steps(out var alone, args);
            Assert.That(alone.ExitCode, Is.EqualTo(0), alone.ToString());
            for (var n = 1; n <= steps; n++)
            {
                File.Delete(Path.Combine(_dataset, "transforms.json"));
                if (Directory.Exists(Path.Combine(_dataset, "camera_paths"))) Directory.Delete(Path.Combine(_dataset, "camera_paths"), true);
                ToolRun winner = null;
                // Before the loser's n-th file operation the winner runs from start to end (FileOps.Faults stays set: its
                // operations are counted too, but only the n-th acts).
                FileOps.Faults = FileFaultPlan.Killing(n, () => winner = ToolRun.Of(args));
                var loser = ToolRun.Of(args);
                FileOps.Faults = null;
                var context = "step " + n + "\nwinner: " + winner + "\nloser: " + loser;
                Assert.That(winner, Is.Not.Null, context);
                Assert.That(new[] { winner.ExitCode, loser.ExitCode }, Has.Member(0), context);
                Assert.That(Interruptions.HasStackTrace(winner.Err + loser.Err), Is.False, context);
                Assert.That(JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "transforms.json")))["frames"].Count(), Is.EqualTo(Images().Length), context);
                Assert.That(Interruptions.Entries(_dataset).Where(e => e.StartsWith(".", StringComparison.Ordinal)), Is.Empty, "no working folder or journal left\n" + context);
            }
        }

        // ---- validate -------------------------------------------------------------------------------------------------

        [Test]
        public void ValidateCountsAFileNamedByDepthPathAndDepthFilePathOnce()
        {
            AddDepth();
            foreach (var split in new[] { "train", "val", "test" })
                EditJson(split, j =>
                {
                    j["integer_depth_scale"] = 0.001;
                    foreach (JObject frame in j["frames"])
                    {
                        var depth = "./" + DepthOf(((string)frame["file_path"]).Substring(2) + ".png");
                        frame["depth_path"] = depth;
                        frame["depth_file_path"] = depth;
                    }
                });
            var run = ToolRun.Of("validate", _dataset);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.Contain(", " + Images().Length + " extra files;"));
        }
    }
}
