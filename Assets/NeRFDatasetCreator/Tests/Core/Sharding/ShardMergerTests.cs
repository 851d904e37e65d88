using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ShardMergerTests
    {
        static readonly ViewCounts Counts = new ViewCounts(5, 3, 4);
        string root;
        string output;

        [SetUp]
        public void CreateTempFolder()
        {
            root = Path.Combine(Path.GetTempPath(), "nerf-merge-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(root);
            output = Path.Combine(root, "merged");
        }

        [TearDown]
        public void DeleteTempFolder()
        {
            if (Directory.Exists(root)) Directory.Delete(root, true);
        }

        static string Lines(MergeResult result) => string.Join("\n", result.Lines());

        [Test]
        public void TheMergedConfigSaysImagesRenderedOnlyWhenEveryShardDid()
        {
            var shards = ShardFolders.Create(root, 3, Counts);
            var configPath = Path.Combine(shards[1], "dataset_config.json");
            var config = ShardFolders.ReadJson(configPath);
            config["imagesRendered"] = false;
            ShardFolders.WriteJson(configPath, config);

            var result = ShardMerger.Merge(shards, output);

            Assert.That(result.Succeeded, Is.True, Lines(result));
            var merged = ShardFolders.ReadJson(Path.Combine(output, "dataset_config.json"));
            Assert.That(merged["imagesRendered"].Type, Is.EqualTo(JTokenType.Boolean));
            Assert.That((bool)merged["imagesRendered"], Is.False, "shard 1 rendered no images, so the whole dataset is not rendered");
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ThreeShardsMergeIntoOneDatasetOrderedBySplitThenIndex(bool move)
        {
            var shards = ShardFolders.Create(root, 3, Counts);
            var result = ShardMerger.Merge(shards, output, move);

            Assert.That(result.Succeeded, Is.True, Lines(result));
            Assert.That(result.FramesPerSplit["train"], Is.EqualTo(5));
            Assert.That(result.FramesPerSplit["test"], Is.EqualTo(4));
            Assert.That(result.FilesTransferred, Is.EqualTo(5 + 3 + 4 + 4), "12 images and 4 depth files");
            foreach (var split in ViewCounts.SplitNames)
            {
                var merged = ShardFolders.ReadJson(Path.Combine(output, "transforms_" + split + ".json"));
                Assert.That(merged.Properties().Select(p => p.Name), Is.EqualTo(new[] { "camera_angle_x", "w", "h", "frames", "aabb_scale" }), "key order of the shards' files");
                Assert.That((double)merged["camera_angle_x"], Is.EqualTo(ShardFolders.CameraAngleX));
                var frames = (JArray)merged["frames"];
                Assert.That(frames, Has.Count.EqualTo(Counts.Of(split)));
                for (var i = 0; i < frames.Count; i++)
                {
                    Assert.That(JToken.DeepEquals(frames[i], ShardFolders.Frame(split, i)), Is.True, split + " frame " + i + " kept key for key:\n" + frames[i]);
                    Assert.That(File.ReadAllBytes(Path.Combine(output, split, "r_" + i + ".png")), Is.EqualTo(ShardFolders.ImageBytes(split, i)));
                }
            }
            Assert.That(File.ReadAllBytes(Path.Combine(output, "test", "r_3_depth.png")), Is.EqualTo(ShardFolders.ImageBytes("test-depth", 3)));
            var config = ShardFolders.ReadJson(Path.Combine(output, "dataset_config.json"));
            Assert.That((int)config["seed"], Is.EqualTo(42));
            Assert.That(config["imagesRendered"].Type, Is.EqualTo(JTokenType.Boolean), "still the boolean DatasetConfig.Write writes, so validate and convert read it");
            Assert.That((bool)config["imagesRendered"], Is.True);
            Assert.That(config["statistics"], Is.Null, "per-shard timings describe no single run of the whole dataset");
            Assert.That(File.ReadAllText(Path.Combine(output, "dataset_config.json")), Does.Contain("\"createdUtc\": \"2026-01-01T10:00:00.000Z\""), "shard 0's date, verbatim");
            Assert.That(result.Warnings, Is.Empty, "the dates and counts differ, which is normal");
            Assert.That(File.Exists(Path.Combine(output, "shard.json")), Is.False, "the merged dataset is whole");
            Assert.That(Directory.GetDirectories(root).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal),
                Is.EqualTo(new[] { "merged", "shard-0", "shard-1", "shard-2" }), "no staging folder left behind");
            Assert.That(File.Exists(Path.Combine(shards[2], "test", "r_3.png")), Is.EqualTo(!move), "copy keeps, move takes the shard's images");
            Assert.That(File.Exists(Path.Combine(shards[2], "transforms_test.json")), Is.True, "the shard's JSON always stays");
        }

        [Test]
        public void AMissingShardIsNamedWithTheViewsItOwed()
        {
            var shards = ShardFolders.Create(root, 3, Counts);
            var before = ShardFolders.Snapshot(root);
            var result = ShardMerger.Merge(new[] { shards[0], shards[2] }, output, true);

            Assert.That(result.Succeeded, Is.False);
            var text = Lines(result);
            Assert.That(text, Does.Contain("lack shard(s) 1/3"));
            Assert.That(text, Does.Contain("-nerfShard 1/3"));
            Assert.That(Directory.Exists(output), Is.False);
            Assert.That(ShardFolders.Snapshot(root), Is.EqualTo(before), "a refused merge changes no file");
        }

        [Test]
        public void MissingFramesAreListedBySplitAndIndexWithTheResponsibleShard()
        {
            var shards = ShardFolders.Create(root, 3, Counts);
            // Shard 1 lost train r_4 (global view 4 → shard 1) from its transforms.
            var path = Path.Combine(shards[1], "transforms_train.json");
            var json = ShardFolders.ReadJson(path);
            ((JArray)json["frames"]).Last.Remove();
            ShardFolders.WriteJson(path, json);
            var before = ShardFolders.Snapshot(root);

            var result = ShardMerger.Merge(shards, output, true);

            Assert.That(result.Succeeded, Is.False);
            Assert.That(result.Problems, Has.Count.EqualTo(1), Lines(result));
            Assert.That(result.Problems[0].ToString(), Does.StartWith("train views = 1 missing: r_4 are in no shard; shard 1/3 (" + shards[1] + ")"));
            Assert.That(ShardFolders.Snapshot(root), Is.EqualTo(before));
        }

        [Test]
        public void AViewInTwoShardsIsReportedAsDuplicatedWithBothFiles()
        {
            var shards = ShardFolders.Create(root, 3, Counts);
            var path = Path.Combine(shards[0], "transforms_val.json");
            var json = ShardFolders.ReadJson(path);
            ((JArray)json["frames"]).Add(ShardFolders.Frame("val", 2)); // val r_2 belongs to shard 1
            ShardFolders.WriteJson(path, json);
            File.WriteAllBytes(Path.Combine(shards[0], "val", "r_2.png"), ShardFolders.ImageBytes("val", 2));

            var result = ShardMerger.Merge(shards, output);

            Assert.That(result.Succeeded, Is.False);
            var duplicate = result.Problems.Single(p => p.Field == "val/r_2");
            Assert.That(duplicate.Value, Is.EqualTo("duplicated"));
            Assert.That(duplicate.Reason, Does.Contain(Path.Combine(shards[0], "transforms_val.json")));
            Assert.That(duplicate.Reason, Does.Contain(Path.Combine(shards[1], "transforms_val.json")));
            Assert.That(Directory.Exists(output), Is.False);
        }

        [Test]
        public void ShardsWithDifferentCameraKeysAreRefusedNamingTheKeyAndBothValues()
        {
            var shards = ShardFolders.Create(root, 2, Counts);
            var path = Path.Combine(shards[1], "transforms_test.json");
            var json = ShardFolders.ReadJson(path);
            json["camera_angle_x"] = 0.5;
            json["w"] = 16;
            ShardFolders.WriteJson(path, json);

            var result = ShardMerger.Merge(shards, output);

            Assert.That(result.Problems.Select(p => p.Field), Is.EquivalentTo(new[]
            {
                Path.Combine(shards[1], "transforms_test.json") + ": camera_angle_x",
                Path.Combine(shards[1], "transforms_test.json") + ": w",
            }));
            var angle = result.Problems[0];
            Assert.That(angle.Value, Is.EqualTo("0.5"));
            Assert.That(angle.Reason, Does.Contain("0.6911112070083618"));
        }

        [Test]
        public void ADifferentDatasetConfigIsAMismatch()
        {
            var shards = ShardFolders.Create(root, 2, Counts);
            var path = Path.Combine(shards[1], "dataset_config.json");
            var config = ShardFolders.ReadJson(path);
            config["seed"] = 7;
            ShardFolders.WriteJson(path, config);

            var result = ShardMerger.Merge(shards, output);

            Assert.That(result.Problems, Has.Count.EqualTo(1));
            Assert.That(result.Problems[0].Field, Is.EqualTo(path + ": seed"));
            Assert.That(result.Problems[0].Value, Is.EqualTo("7"));
            Assert.That(result.Problems[0].Reason, Does.Contain("which has 42"));
        }

        [TestCase("[1, 2]", "(not an object)", "is not a JSON object.")]
        [TestCase("{\"seed\": ", "(unreadable)", "is not valid JSON: Unexpected end")]
        public void AConfigThatIsNoObjectIsAProblemNamingTheFile(string text, string value, string reason)
        {
            var shards = ShardFolders.Create(root, 2, Counts);
            var path = Path.Combine(shards[1], "dataset_config.json");
            File.WriteAllText(path, text);
            var before = ShardFolders.Snapshot(root);

            var result = ShardMerger.Merge(shards, output);

            Assert.That(result.Succeeded, Is.False);
            var problem = result.Problems.Single(p => p.Field == path);
            Assert.That(problem.Value, Is.EqualTo(value));
            Assert.That(problem.Reason, Does.StartWith(reason));
            Assert.That(problem.Fix, Is.EqualTo("Recapture this shard."));
            Assert.That(ShardFolders.Snapshot(root), Is.EqualTo(before), "a refused merge changes no file");
        }

        [Test]
        public void ADifferentUnityVersionIsOnlyAWarning()
        {
            var shards = ShardFolders.Create(root, 2, Counts);
            var path = Path.Combine(shards[1], "dataset_config.json");
            var config = ShardFolders.ReadJson(path);
            config["unityVersion"] = "6000.0.40f1";
            ShardFolders.WriteJson(path, config);

            var result = ShardMerger.Merge(shards, output);

            Assert.That(result.Succeeded, Is.True, Lines(result));
            Assert.That(result.Warnings.Single(), Does.Contain("unityVersion is \"6000.0.40f1\" but \"2022.3.62f1\""));
        }

        [Test]
        public void AMissingImageIsNamedAndMovesNothing()
        {
            var shards = ShardFolders.Create(root, 2, Counts);
            File.Delete(Path.Combine(shards[1], "test", "r_3_depth.png"));
            var before = ShardFolders.Snapshot(root);

            var result = ShardMerger.Merge(shards, output, true);

            Assert.That(result.Problems, Has.Count.EqualTo(1), Lines(result));
            Assert.That(result.Problems[0].Field, Does.EndWith("transforms_test.json: test r_3.depth_path"));
            Assert.That(result.Problems[0].Reason, Does.Contain("does not exist"));
            Assert.That(ShardFolders.Snapshot(root), Is.EqualTo(before));
        }

        [Test]
        public void AnExistingOutputFolderIsNeverWrittenInto()
        {
            var shards = ShardFolders.Create(root, 2, Counts);
            Directory.CreateDirectory(output);
            File.WriteAllText(Path.Combine(output, "keep.txt"), "mine");

            var result = ShardMerger.Merge(shards, output, true);

            Assert.That(result.Succeeded, Is.False);
            Assert.That(result.Problems[0].Reason, Does.Contain("already exists"));
            Assert.That(Directory.GetFileSystemEntries(output).Select(Path.GetFileName), Is.EqualTo(new[] { "keep.txt" }));
            Assert.That(File.Exists(Path.Combine(shards[0], "train", "r_0.png")), Is.True);
        }

        [TestCase(true)]
        [TestCase(false)]
        public void AWriteFailureHalfWayPutsEveryMovedFileBack(bool move)
        {
            // A failure only the file system can reveal: shard 0's frame r_0 names an extra file inside a folder called
            // "train/r_1.png", and shard 1's image of r_1 is a file of that very name. The plan is consistent; writing
            // fails when r_1.png meets the folder, after r_0's files were already moved into the staging folder.
            var counts = new ViewCounts(3, 0, 0);
            var shards = ShardFolders.Create(root, 2, counts);
            var path = Path.Combine(shards[0], "transforms_train.json");
            var json = ShardFolders.ReadJson(path);
            json["frames"][0]["extra_path"] = "./train/r_1.png/extra.bin";
            ShardFolders.WriteJson(path, json);
            Directory.CreateDirectory(Path.Combine(shards[0], "train", "r_1.png"));
            File.WriteAllText(Path.Combine(shards[0], "train", "r_1.png", "extra.bin"), "extra");
            var before = ShardFolders.Snapshot(root);

            var result = ShardMerger.Merge(shards, output, move);

            Assert.That(result.Succeeded, Is.False);
            Assert.That(result.Problems.Single().Reason, Does.StartWith("could not be written"));
            Assert.That(result.Problems.Single().Fix, Does.StartWith("Nothing was changed"));
            Assert.That(ShardFolders.Snapshot(root), Is.EqualTo(before), "every moved file is back where it was");
            Assert.That(Directory.GetDirectories(root).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal),
                Is.EqualTo(new[] { "shard-0", "shard-1" }), "no output and no staging folder");
        }

        [Test]
        public void ShardsOfDifferentJobsAreRefused()
        {
            var a = ShardFolders.Create(Path.Combine(root, "a"), 2, Counts);
            var b = ShardFolders.Create(Path.Combine(root, "b"), 3, Counts);

            var result = ShardMerger.Merge(new[] { a[0], b[1] }, output);

            Assert.That(result.Problems.Single().Field, Is.EqualTo(b[1] + ": shardCount"));
        }

        [Test]
        public void AFolderWithoutShardJsonIsNotAShard()
        {
            var shards = ShardFolders.Create(root, 2, Counts);
            File.Delete(Path.Combine(shards[1], "shard.json"));

            var result = ShardMerger.Merge(shards, output);

            Assert.That(result.Problems.Single().Field, Is.EqualTo(Path.Combine(shards[1], "shard.json")));
            Assert.That(result.Problems.Single().Fix, Does.Contain("-nerfShard"));
        }

        [Test]
        public void StrayFilesAreWarnedAboutAndLeftInPlace()
        {
            var shards = ShardFolders.Create(root, 2, Counts);
            File.WriteAllText(Path.Combine(shards[0], "transforms.json"), "{}");
            File.WriteAllText(Path.Combine(shards[0], "train", "notes.txt"), "x");

            var result = ShardMerger.Merge(shards, output, true);

            Assert.That(result.Succeeded, Is.True, Lines(result));
            Assert.That(result.Warnings, Has.Count.EqualTo(2));
            Assert.That(File.Exists(Path.Combine(shards[0], "transforms.json")), Is.True);
            Assert.That(File.Exists(Path.Combine(output, "transforms.json")), Is.False);
        }

        [Test]
        public void ThePointCloudOfShardZeroIsCarriedOver()
        {
            var shards = ShardFolders.Create(root, 2, Counts);
            File.WriteAllBytes(Path.Combine(shards[0], "points3d.ply"), new byte[] { 1, 2, 3 });

            var result = ShardMerger.Merge(shards, output, true);

            Assert.That(result.Succeeded, Is.True, Lines(result));
            Assert.That(result.Warnings, Is.Empty);
            Assert.That(File.ReadAllBytes(Path.Combine(output, "points3d.ply")), Is.EqualTo(new byte[] { 1, 2, 3 }));
        }

        [Test]
        public void ThePointCloudRecordOfShardZeroDescribesTheMergedDataset()
        {
            var shards = ShardFolders.Create(root, 2, Counts);
            File.WriteAllBytes(Path.Combine(shards[0], "points3d.ply"), new byte[] { 1, 2, 3 });
            var configPath = Path.Combine(shards[0], "dataset_config.json");
            var config = JObject.Parse(File.ReadAllText(configPath));
            config["pointCloud"] = new PointCloudRecord("points3d.ply", PointCloudRecord.HashOf(Path.Combine(shards[0], "points3d.ply")), 1).ToJson();
            File.WriteAllText(configPath, config.ToString());

            var result = ShardMerger.Merge(shards, output, true);

            Assert.That(result.Succeeded, Is.True, Lines(result));
            Assert.That(result.Warnings, Is.Empty, "only shard 0 writes the cloud and its record: not a difference worth a warning");
            var merged = JObject.Parse(File.ReadAllText(Path.Combine(output, "dataset_config.json")));
            Assert.That(JToken.DeepEquals(merged["pointCloud"], config["pointCloud"]), Is.True);
            Assert.That(PointCloudOwnership.IsOwn(output, new List<ValidationProblem>()), Is.True, "the copied file still has the recorded hash");
        }

        [Test]
        public void TwoPointCloudsAreAProblemNotAPick()
        {
            var shards = ShardFolders.Create(root, 2, Counts);
            File.WriteAllBytes(Path.Combine(shards[0], "points3d.ply"), new byte[] { 1 });
            File.WriteAllBytes(Path.Combine(shards[1], "points3d.ply"), new byte[] { 2 });

            var result = ShardMerger.Merge(shards, output, true);

            Assert.That(result.Succeeded, Is.False);
            Assert.That(result.Problems.Select(p => p.Field), Does.Contain("points3d.ply"));
            Assert.That(File.Exists(Path.Combine(output, "points3d.ply")), Is.False);
        }
    }
}
