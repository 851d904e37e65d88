using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class JsonValuesTests
    {
        const string Huge = "123456789012345678901234567890";

        [Test]
        public void AWholeNumberBeyond64BitsIsANumberButNotALong()
        {
            var token = JToken.Parse(Huge);
            Assert.That(JsonValues.TryNumber(token, out var value), Is.True);
            Assert.That(value, Is.EqualTo(1.2345678901234568e29).Within(1e15));
            Assert.That(JsonValues.TryLong(token, out _), Is.False);
            Assert.That(JsonValues.TryInt(token, out _), Is.False);
        }

        [TestCase("7", 7)]
        [TestCase("-2147483648", int.MinValue)]
        public void WholeNumbersInRangeAreInts(string json, int expected)
        {
            Assert.That(JsonValues.TryInt(JToken.Parse(json), out var value), Is.True);
            Assert.That(value, Is.EqualTo(expected));
        }

        [TestCase("2147483648")]
        [TestCase("1.5")]
        [TestCase("\"7\"")]
        [TestCase("null")]
        public void OtherValuesAreNotInts(string json) => Assert.That(JsonValues.TryInt(JToken.Parse(json), out _), Is.False);

        [Test]
        public void ABigIntegerTransformsValueIsReportedNotThrown()
        {
            var doc = DatasetFolder.Read("{ \"camera_angle_x\": 0.5, \"w\": " + Huge + ", \"frames\": [] }");
            Assert.That(doc.Problems, Has.Some.EqualTo("w is not a whole number (" + Huge + ")."));
        }

        [Test]
        public void ABigIntegerShardIndexIsAProblemNamingTheField()
        {
            var e = Assert.Throws<InvalidParameterException>(() => ShardManifest.Parse(
                "{ \"format\": \"nerf-dataset-creator/shard\", \"version\": " + Huge + ", \"shardIndex\": " + Huge + ", \"shardCount\": 2, " +
                "\"viewCounts\": { \"train\": 1, \"val\": 0, \"test\": 0 }, \"views\": { \"train\": [" + Huge + "], \"val\": [], \"test\": [] } }", "shard.json"));
            Assert.That(e.Problems.Select(p => p.Field), Is.SupersetOf(new[] { "shard.json: version", "shard.json: shardIndex", "shard.json: views.train" }));
        }
    }
}
