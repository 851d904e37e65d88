using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class BatchArgumentsTests
    {
        [Test]
        public void ReadsThePluginsArgumentsAmongUnitysOwn()
        {
            var argv = new[]
            {
                "/opt/Unity/Editor/Unity", "-batchmode", "-projectPath", "/p", "-executeMethod", "NerfDatasetCreator.Editor.BatchCapture.Run",
                "-nerfConfig", "cfg/lego.json", "-nerfScene", "Assets/Scenes/Lego.unity", "-nerfOut", "/data/lego", "-nerfShard", "2/8", "-logFile", "-",
            };
            var a = BatchArguments.Parse(argv);
            Assert.That(a.Problems, Is.Empty);
            Assert.That(a.IsValid, Is.True);
            Assert.That(a.ConfigPath, Is.EqualTo("cfg/lego.json"));
            Assert.That(a.Scene, Is.EqualTo("Assets/Scenes/Lego.unity"));
            Assert.That(a.OutputFolder, Is.EqualTo("/data/lego"));
            Assert.That(a.ShardIndex, Is.EqualTo(2));
            Assert.That(a.ShardCount, Is.EqualTo(8));
        }

        [Test]
        public void NamesAreCaseInsensitive()
        {
            var a = BatchArguments.Parse(new[] { "-NERFCONFIG", "a.json", "-nerfout", "o", "-NerfScene", "s" });
            Assert.That(a.IsValid, Is.True);
            Assert.That(a.ConfigPath, Is.EqualTo("a.json"));
            Assert.That(a.OutputFolder, Is.EqualTo("o"));
            Assert.That(a.Scene, Is.EqualTo("s"));
        }

        [Test]
        public void OptionalArgumentsMayBeAbsent()
        {
            var a = BatchArguments.Parse(new[] { "-nerfConfig", "a.json" });
            Assert.That(a.IsValid, Is.True);
            Assert.That(a.Scene, Is.Null);
            Assert.That(a.OutputFolder, Is.Null);
            Assert.That(a.ShardIndex, Is.Null);
        }

        [Test]
        public void UnknownArgumentsAreIgnored()
        {
            var a = BatchArguments.Parse(new[] { "-nerfConfigs", "x", "-nerf", "-nerfConfig", "a.json", "-quit" });
            Assert.That(a.IsValid, Is.True);
            Assert.That(a.ConfigPath, Is.EqualTo("a.json"));
        }

        [Test]
        public void MissingConfigIsAProblem()
        {
            var a = BatchArguments.Parse(new[] { "-batchmode" });
            Assert.That(a.Problems.Select(p => p.Field), Is.EqualTo(new[] { "-nerfConfig" }));
        }

        [Test]
        public void AnArgumentWithoutValueIsAProblem()
        {
            var a = BatchArguments.Parse(new[] { "-nerfConfig", "a.json", "-nerfOut", "-logFile" });
            Assert.That(a.Problems.Select(p => p.Field), Is.EqualTo(new[] { "-nerfOut" }));
            Assert.That(a.OutputFolder, Is.Null);
        }

        [TestCase("8/8")]
        [TestCase("1/0")]
        [TestCase("-1/4")]
        [TestCase("1-4")]
        [TestCase("a/b")]
        [TestCase("1/4/2")]
        [TestCase(" 1/4")]
        public void BadShards(string shard)
        {
            var a = BatchArguments.Parse(new[] { "-nerfConfig", "a.json", "-nerfShard", shard });
            Assert.That(a.Problems.Select(p => p.Field), Is.EqualTo(new[] { "-nerfShard" }));
            Assert.That(a.ShardIndex, Is.Null);
        }

        [TestCase("0/1", 0, 1)]
        [TestCase("3/4", 3, 4)]
        public void GoodShards(string shard, int index, int count)
        {
            var a = BatchArguments.Parse(new[] { "-nerfShard", shard, "-nerfConfig", "a.json" });
            Assert.That(a.IsValid, Is.True);
            Assert.That(a.ShardIndex, Is.EqualTo(index));
            Assert.That(a.ShardCount, Is.EqualTo(count));
        }
    }
}
