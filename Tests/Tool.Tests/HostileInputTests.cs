using System;
using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>The classes of bad input of issue 12, each refused or warned about with the field named — never a crash, never data touched outside the output.</summary>
    [TestFixture]
    public class HostileInputTests
    {
        const string Huge = "123456789012345678901234567890";
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

        void Edit(string split, Func<string, string> change) => File.WriteAllText(Transforms(split), change(File.ReadAllText(Transforms(split))));

        void EditJson(string split, Action<JObject> change)
        {
            var json = JObject.Parse(File.ReadAllText(Transforms(split)));
            change(json);
            File.WriteAllText(Transforms(split), json.ToString());
        }

        [Test]
        public void AWholeNumberBeyond64BitsIsAProblemNamingTheFieldInValidateAndConvert()
        {
            EditJson("train", j =>
            {
                j["w"] = JToken.Parse(Huge);
                j["frames"][0]["transform_matrix"][0][0] = JToken.Parse(Huge);
            });
            var validate = ToolRun.Of("validate", _dataset);
            Assert.That(validate.ExitCode, Is.EqualTo(1), validate.ToString());
            Assert.That(validate.Out, Does.Contain("problem: transforms_train.json: w is not a whole number (" + Huge + ")"));
            Assert.That(validate.Out, Does.Contain("problem: transforms_train.json frame 0"));
            var convert = ToolRun.Of("convert", _dataset, "--to", "nerfstudio");
            Assert.That(convert.ExitCode, Is.EqualTo(1), convert.ToString());
            Assert.That(Interruptions.HasStackTrace(validate.Out + validate.Err + convert.Out + convert.Err), Is.False);
        }

        [Test]
        public void AWholeNumberBeyond64BitsInShardJsonIsAProblemNamingTheField()
        {
            var shards = ShardFolders.Create(_scratch.PathOf("shards"), 2, new ViewCounts(2, 1, 1));
            var manifest = Path.Combine(shards[1], "shard.json");
            File.WriteAllText(manifest, File.ReadAllText(manifest).Replace("\"shardIndex\": 1", "\"shardIndex\": " + Huge).Replace("\"train\": [\n      1\n    ]", "\"train\": [ " + Huge + " ]"));
            var run = ToolRun.Of(new[] { "merge", "--out", _scratch.PathOf("lego") }.Concat(shards).ToArray());
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("shard.json: shardIndex = " + Huge + ": is not a whole number."));
            Assert.That(run.Err, Does.Contain("shard.json: views.train = " + Huge));
        }

        [TestCase("transforms_train.json")]
        [TestCase("dataset_config.json")]
        public void AnUnreadableFileIsAProblemNotACrash(string name)
        {
            File.WriteAllText(Path.Combine(_dataset, "dataset_config.json"), "{ \"imagesRendered\": true }");
            // Tests run as root on CI, where chmod 000 does not deny reads: the seam denies them instead.
            FileOps.Faults = FileFaultPlan.FailingAt(1, (op, path) => new UnauthorizedAccessException("Access to the path '" + path + "' is denied."), path => path.EndsWith(name, StringComparison.Ordinal));
            var run = ToolRun.Of("validate", _dataset);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Out, Does.Contain("problem: " + name + ": cannot be read: Access to the path"));
        }

        [Test]
        public void DuplicateFilePathsAreAProblemAndConvertRefusesThem()
        {
            EditJson("train", j => j["frames"][1]["file_path"] = "./train/r_0");
            var validate = ToolRun.Of("validate", _dataset);
            Assert.That(validate.ExitCode, Is.EqualTo(1), validate.ToString());
            Assert.That(validate.Out, Does.Contain("problem: transforms_train.json frame 1 (./train/r_0): file_path is also transforms_train.json frame 0's"));
            var convert = ToolRun.Of("convert", _dataset, "--to", "nerfstudio");
            Assert.That(convert.ExitCode, Is.EqualTo(1), convert.ToString());
            Assert.That(convert.Err, Does.Contain("train.frames[1].file_path = ./train/r_0: names train/r_0.png, which another frame already uses"));
            Assert.That(File.Exists(Path.Combine(_dataset, "transforms.json")), Is.False);
        }

        [Test]
        public void AnEmptyTrainSplitIsAProblem()
        {
            EditJson("train", j => j["frames"] = new JArray());
            var run = ToolRun.Of("validate", _dataset);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Out, Does.Contain("problem: transforms_train.json: has no frames; every loader trains on the train split"));
            Assert.That(run.Out, Does.Not.Contain("OK"));
        }

        [Test]
        public void UnreferencedAndSixteenBitImagesAreWarned()
        {
            File.WriteAllBytes(Path.Combine(_dataset, "train", "r_7.png"), TestPng.Encode(RenderedDataset.Width, RenderedDataset.Height, 8, PngInfo.ColorTypeRgba));
            File.WriteAllBytes(Path.Combine(_dataset, "train", "r_0_depth_0000.png"), TestPng.Encode(RenderedDataset.Width, RenderedDataset.Height, 16, PngInfo.ColorTypeGray));
            var run = ToolRun.Of("validate", _dataset);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.Contain("warning: train/: 1 image(s) no frame names (train/r_7.png)"), "r_0's companion is not counted");

            var sixteen = TestPng.Encode(RenderedDataset.Width, RenderedDataset.Height, 16, PngInfo.ColorTypeGray);
            foreach (var png in Directory.GetFiles(_dataset, "r_?.png", SearchOption.AllDirectories)) File.WriteAllBytes(png, sixteen);
            run = ToolRun.Of("validate", _dataset);
            Assert.That(run.Out, Does.Contain("every colour image is 16-bit"), run.ToString());
        }

        [Test]
        public void ConvertWarnsThatItIgnoresAStaleWidthAndHeight()
        {
            EditJson("train", j => j["w"] = 99);
            var run = ToolRun.Of("convert", _dataset, "--to", "nerfstudio");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Err, Does.Contain("warning: train.w, h = 99 × 24: differ from the images' 32 × 24; convert uses the images' size"));
        }

        [Test]
        public void ConvertNeverReadsThroughAFilePathLeavingTheDataset()
        {
            var outside = _scratch.PathOf("outside");
            Directory.CreateDirectory(outside);
            File.Copy(Path.Combine(_dataset, "train", "r_0.png"), Path.Combine(outside, "secret.png"));
            EditJson("train", j => j["frames"][0]["file_path"] = "../outside/secret");
            var run = ToolRun.Of("convert", _dataset, "--to", "colmap");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("train.frames[0].file_path = ../outside/secret: leaves"));
            Assert.That(Directory.Exists(Path.Combine(_dataset, "colmap")), Is.False, "nothing written, the empty output folder removed again");
        }

        [Test]
        public void ConvertNeverReadsThroughASymbolicLink()
        {
            var outside = _scratch.PathOf("outside.png");
            File.Copy(Path.Combine(_dataset, "train", "r_0.png"), outside);
            File.Delete(Path.Combine(_dataset, "train", "r_0.png"));
            File.CreateSymbolicLink(Path.Combine(_dataset, "train", "r_0.png"), outside);
            var run = ToolRun.Of("convert", _dataset, "--to", "colmap");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("goes through the symbolic link"));
        }

        [Test]
        public void MergeMoveNeverFollowsASymlinkedSplitFolderOutOfTheShard()
        {
            var shards = ShardFolders.Create(_scratch.PathOf("shards"), 2, new ViewCounts(2, 1, 1));
            var elsewhere = _scratch.PathOf("elsewhere");
            Directory.Move(Path.Combine(shards[0], "train"), elsewhere);
            Directory.CreateSymbolicLink(Path.Combine(shards[0], "train"), elsewhere);
            var before = ShardFolders.Snapshot(elsewhere);
            var run = ToolRun.Of(new[] { "merge", "--files", "move", "--out", _scratch.PathOf("lego") }.Concat(shards).ToArray());
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain(Path.Combine(shards[0], "train") + " = (symbolic link): is a link"));
            Assert.That(ShardFolders.Snapshot(elsewhere), Is.EqualTo(before), "nothing moved from outside the shard");
        }

        [Test]
        public void MergeNeverTransfersAShardsMetadata()
        {
            var shards = ShardFolders.Create(_scratch.PathOf("shards"), 2, new ViewCounts(2, 1, 1));
            var file = Path.Combine(shards[0], "transforms_train.json");
            var json = ShardFolders.ReadJson(file);
            json["frames"][0]["extra_path"] = "./shard.json";
            ShardFolders.WriteJson(file, json);
            var before = ShardFolders.Snapshot(_scratch.PathOf("shards"));
            var run = ToolRun.Of(new[] { "merge", "--files", "move", "--out", _scratch.PathOf("lego") }.Concat(shards).ToArray());
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("extra_path = ./shard.json: names the shard's own metadata file"));
            Assert.That(ShardFolders.Snapshot(_scratch.PathOf("shards")), Is.EqualTo(before));
        }

        [Test]
        public void MergeWarnsWhenItsOutputIsInsideAShardFolder()
        {
            var shards = ShardFolders.Create(_scratch.PathOf("shards"), 2, new ViewCounts(2, 1, 1));
            var run = ToolRun.Of(new[] { "merge", "--out", Path.Combine(shards[1], "merged") }.Concat(shards).ToArray());
            Assert.That(run.Out + run.Err, Does.Contain("warning: --out " + Path.Combine(shards[1], "merged") + " is inside shard 1/2"));
        }

        [Test]
        public void APlanNameTooLongForTheWorkingFolderIsRefusedUpFront()
        {
            var config = _scratch.WriteText("c.json", "{ \"splits\": { \"train\": { \"count\": 2 } } }");
            var output = _scratch.PathOf(new string('x', 240));
            var run = ToolRun.Of("plan", "--config", config, "--out", output);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.StartWith("error: --out = xxxx").And.Contain("240 bytes"));
            Assert.That(Interruptions.Entries(_scratch.Root).Where(n => n.StartsWith("xxxx")), Is.Empty);
        }

        [Test]
        public void AConfigWarnsAboutCommentsAndTrailingCommasButNotItsOutputFolder()
        {
            var config = _scratch.WriteText("c.json", "{\n  // my rig\n  \"outputFolder\": \"D:/datasets\",\n  \"splits\": { \"train\": { \"count\": 2, }, },\n}");
            var run = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("out"));
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Err, Does.Contain("warning: " + config + "(2,3) = a comment: is not JSON"));
            Assert.That(run.Err, Does.Contain("warning: " + config + "(4,36) = a trailing comma"));
            // outputFolder is where Unity's capture writes; --out names the plan's folder (issue 33: the README's first command warned on the sample config).
            Assert.That(run.Err, Does.Not.Contain("outputFolder"));
        }

        [Test]
        public void AnUnknownFormationQuotesTheValue()
        {
            var config = _scratch.WriteText("c.json", "{ \"splits\": { \"train\": { \"count\": 2, \"formation\": { \"kind\": \"helix\" } } } }");
            var run = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("out"));
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("splits.train.formation.kind: \"helix\" is not a known formation"));
        }

        [Test]
        public void CleanReportsLeftoversWithTheirSizeAndRemovesThem()
        {
            var config = _scratch.WriteText("c.json", "{ \"splits\": { \"train\": { \"count\": 2 } } }");
            Interruptions.StopAt(9, "plan", "--config", config, "--out", _scratch.PathOf("out")); // after the first file the plan writes (its working folder is born in 5 steps)
            var partial = Directory.GetDirectories(_scratch.Root, "out.partial-*~").Single();
            var dry = ToolRun.Of("clean", _scratch.Root, "--dry-run");
            Assert.That(dry.ExitCode, Is.EqualTo(0), dry.ToString());
            Assert.That(dry.Out, Does.StartWith("would remove " + partial + " (2 files, ").And.Contain("B): the partial files of a plan or capture of " + _scratch.PathOf("out")));
            Assert.That(Directory.Exists(partial), Is.True, "a dry run changes nothing");
            var clean = ToolRun.Of("clean", _scratch.Root);
            Assert.That(clean.Out, Does.StartWith("removed " + partial), clean.ToString());
            Assert.That(Directory.Exists(partial), Is.False);
            Assert.That(ToolRun.Of("clean", _scratch.Root).Out, Does.StartWith("nothing to clean in " + _scratch.Root));
        }
    }
}
