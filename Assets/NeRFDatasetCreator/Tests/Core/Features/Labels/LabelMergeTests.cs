using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Two shards of a labelled analytic capture merge into one dataset with one labels.json; shards whose tables disagree are refused.</summary>
    [TestFixture]
    public class LabelMergeTests
    {
        TempFolder _temp;
        string[] _shards;

        [SetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _shards = Enumerable.Range(0, 2).Select(i => AnalyticDataset.Write(_temp.Path, "labelled",
                new AnalyticDataset.Options { Labels = true, PointCloud = 0, Shard = new ShardSpec(i, 2), DatasetFolder = "shard" + i })).ToArray();
        }

        [TearDown] public void Delete() => _temp.Dispose();

        [Test]
        public void ShardsWithTheSameLabelsMergeIntoALabelledDatasetThatPassesTheChecks()
        {
            Assert.That(File.ReadAllText(Path.Combine(_shards[1], "labels.json")), Is.EqualTo(File.ReadAllText(Path.Combine(_shards[0], "labels.json"))));
            var output = _temp.Combine("merged");
            var result = ShardMerger.Merge(_shards, output);
            Assert.That(result.Succeeded, Is.True, string.Join("\n", result.Lines()));
            Assert.That(result.Warnings.Where(w => w.Contains("labels")), Is.Empty);
            Assert.That(File.ReadAllText(Path.Combine(output, "labels.json")), Is.EqualTo(File.ReadAllText(Path.Combine(_shards[0], "labels.json"))));
            // The merged train preview shows views of both shards (a shard's own shows only its half).
            var preview = PngReader.Read(Path.Combine(output, "labels_preview_train.png"));
            var shardPreview = PngReader.Read(Path.Combine(_shards[0], "labels_preview_train.png"));
            Assert.That(preview.Height, Is.GreaterThan(shardPreview.Height));
            var report = DatasetCheck.Run(output, new DatasetCheckOptions());
            foreach (var name in new[] { InstanceMaskCheck.CheckName, InstanceReprojectionCheck.CheckName })
                Assert.That(report.Results.Single(r => r.Name == name).Status, Is.EqualTo(DatasetCheckStatus.Passed), string.Join("\n", report.SummaryLines));
            Assert.That(DatasetValidator.Validate(output).Problems, Is.Empty);
        }

        [Test]
        public void ShardsWhoseIdsNameOtherObjectsAreRefusedNamingTheIdAndTheFile()
        {
            // Shard 1 captured from an edited scene: Ball and Glass swapped places in the hierarchy.
            var path = Path.Combine(_shards[1], "labels.json");
            var json = JObject.Parse(File.ReadAllText(path));
            var instances = (JArray)json["instances"];
            instances[0]["path"] = "Analytic/Glass";
            instances[1]["path"] = "Analytic/Ball";
            File.WriteAllText(path, json.ToString());
            var output = _temp.Combine("merged");
            var result = ShardMerger.Merge(_shards, output);
            Assert.That(result.Succeeded, Is.False);
            var text = string.Join("\n", result.Lines());
            Assert.That(text, Does.Contain(path));
            Assert.That(text, Does.Contain("instance id 1 is \"Analytic/Ball\" (Sphere) in one and \"Analytic/Glass\" (Sphere) in the other"));
            Assert.That(Directory.Exists(output), Is.False);
        }

        [Test]
        public void AShardWithoutLabelsIsRefused()
        {
            File.Delete(Path.Combine(_shards[0], "labels.json"));
            var result = ShardMerger.Merge(_shards, _temp.Combine("merged"));
            Assert.That(result.Succeeded, Is.False);
            Assert.That(string.Join("\n", result.Lines()), Does.Contain("labels.json").And.Contain("is missing while"));
        }
    }
}
