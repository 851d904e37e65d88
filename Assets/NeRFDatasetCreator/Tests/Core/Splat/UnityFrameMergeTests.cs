using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// merge carries unity_frame: it is not a per-run key (ShardMerger.PerRunConfigKeys), so every shard must record the
    /// same one and the merged config keeps it; a shard placed in another frame is a mismatch naming the key.
    /// </summary>
    [TestFixture]
    public class UnityFrameMergeTests
    {
        static readonly ViewCounts Counts = new ViewCounts(4, 2, 2);

        static JObject Frame(double centreX) => UnityFrameRecord.ToJson(new SceneNormalisation(new Vector3d(centreX, 2, 3), 0.5),
            new UnityFrameFacts("Assets/Scenes/S.unity:/Target", null, null, "Linear"));

        [Test]
        public void TheMergedConfigKeepsTheShardsFrame()
        {
            using (var temp = new TempFolder())
            {
                var shards = ShardFolders.Create(temp.Path, 2, Counts);
                foreach (var shard in shards) AddFrame(shard, Frame(1));
                var result = ShardMerger.Merge(shards, temp.Combine("merged"));
                Assert.That(result.Succeeded, Is.True, string.Join("\n", result.Problems));
                var merged = ShardFolders.ReadJson(temp.Combine("merged", "dataset_config.json"));
                Assert.That(merged[UnityFrameRecord.Key]?.ToString(Newtonsoft.Json.Formatting.None), Is.EqualTo(Frame(1).ToString(Newtonsoft.Json.Formatting.None)));
            }
        }

        [Test]
        public void AShardInAnotherFrameIsAMismatch()
        {
            using (var temp = new TempFolder())
            {
                var shards = ShardFolders.Create(temp.Path, 2, Counts);
                AddFrame(shards[0], Frame(1));
                AddFrame(shards[1], Frame(5));
                var result = ShardMerger.Merge(shards, temp.Combine("merged"));
                Assert.That(result.Succeeded, Is.False);
                Assert.That(result.Problems.Select(p => p.Field), Has.Some.EqualTo(Path.Combine(shards[1], "dataset_config.json") + ": " + UnityFrameRecord.Key));
                Assert.That(Directory.Exists(temp.Combine("merged")), Is.False);
            }
        }

        static void AddFrame(string shard, JObject frame)
        {
            var path = Path.Combine(shard, "dataset_config.json");
            var config = ShardFolders.ReadJson(path);
            config[UnityFrameRecord.Key] = frame;
            ShardFolders.WriteJson(path, config);
        }
    }
}
