using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ShardManifestTests
    {
        [Test]
        public void ManifestListsTheViewsOfTheShard()
        {
            var json = ShardManifest.ForShard(new ShardSpec(2, 3), new ViewCounts(5, 3, 4)).ToJson();
            var expected = JObject.Parse(@"{
                ""format"": ""nerf-dataset-creator/shard"", ""version"": 1,
                ""shardIndex"": 2, ""shardCount"": 3, ""assignment"": ""round-robin"",
                ""viewCounts"": { ""train"": 5, ""val"": 3, ""test"": 4 },
                ""views"": { ""train"": [2], ""val"": [0], ""test"": [0, 3] } }");
            Assert.That(JToken.DeepEquals(json, expected), Is.True, json.ToString());
        }

        [Test]
        public void ParseReadsWhatToJsonWrites()
        {
            var original = ShardManifest.ForShard(new ShardSpec(1, 4), new ViewCounts(10, 0, 7));
            var read = ShardManifest.Parse(original.ToJson().ToString(), "shard.json");
            Assert.That(read.Shard, Is.EqualTo(new ShardSpec(1, 4)));
            Assert.That(read.Counts.Test, Is.EqualTo(7));
            Assert.That(read.Views("train"), Is.EqualTo(new[] { 1, 5, 9 }));
            Assert.That(read.Views("val"), Is.Empty);
            Assert.That(read.Views("test"), Is.EqualTo(new[] { 3 }));   // test starts at global 10; 13 mod 4 = 1, 17 is past the end
        }

        [Test]
        public void ParseNamesEveryBadField()
        {
            var json = @"{ ""format"": ""nerf-dataset-creator/shard"", ""version"": 1, ""shardIndex"": 5, ""shardCount"": 4,
                ""viewCounts"": { ""train"": 2, ""val"": 1 }, ""views"": { ""train"": [0, 2], ""val"": [], ""test"": [] } }";
            var e = Assert.Throws<InvalidParameterException>(() => ShardManifest.Parse(json, "s/shard.json"));
            var text = e.Message;
            Assert.That(text, Does.Contain("s/shard.json: shardIndex/shardCount = 5/4"));
            Assert.That(text, Does.Contain("s/shard.json: viewCounts: test = (missing)"));
            Assert.That(text, Does.Contain("s/shard.json: views.train = 2"));
        }

        [Test]
        public void AFormatOrAssignmentOfTheWrongTypeIsAProblemNamingTheField()
        {
            var json = ShardManifest.ForShard(new ShardSpec(0, 2), new ViewCounts(2, 1, 1)).ToJson();
            json["format"] = new JObject();
            json["assignment"] = "blocks";
            var e = Assert.Throws<InvalidParameterException>(() => ShardManifest.Parse(json.ToString(), "s/shard.json"));
            Assert.That(e.Problems.Select(p => p.Field), Is.EqualTo(new[] { "s/shard.json: format", "s/shard.json: assignment" }));
            Assert.That(e.Problems[0].Value, Is.EqualTo("{}"));
        }

        [Test]
        public void NotJsonIsReportedAsUnreadable()
        {
            var e = Assert.Throws<InvalidParameterException>(() => ShardManifest.Parse("{ nope", "x/shard.json"));
            Assert.That(e.Problems[0].Field, Is.EqualTo("x/shard.json"));
            Assert.That(e.Problems[0].Reason, Does.StartWith("is not valid JSON"));
        }
    }
}
