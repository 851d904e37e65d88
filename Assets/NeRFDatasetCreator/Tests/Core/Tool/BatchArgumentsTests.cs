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
            Assert.That(a.Shard, Is.EqualTo(new ShardSpec(2, 8)));
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
            Assert.That(a.Shard, Is.Null);
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

        // The shard goes through ShardSpec.TryParse, so batch mode refuses exactly what ShardSpec refuses
        // (including N above ShardSpec.MaxCount) and names the argument as the docs spell it, whatever case was typed.
        [TestCase("8/8", "shard index i outside [0, N-1]", "from 0 to 7")]
        [TestCase("1/0", "shard count N outside [1, 10000]", "machines of the job array")]
        [TestCase("0/10001", "shard count N outside [1, 10000]", "machines of the job array")]
        [TestCase("-1/4", "not of the form i/N", "-nerfShard 2/8")]
        [TestCase("1-4", "not of the form i/N", "-nerfShard 2/8")]
        [TestCase("a/b", "not of the form i/N", "-nerfShard 2/8")]
        [TestCase("1/4/2", "not of the form i/N", "-nerfShard 2/8")]
        [TestCase("+1/4", "not of the form i/N", "-nerfShard 2/8")]
        public void BadShards(string shard, string reason, string fix)
        {
            var a = BatchArguments.Parse(new[] { "-nerfConfig", "a.json", "-NERFSHARD", shard });
            Assert.That(a.Problems, Has.Count.EqualTo(1));
            Assert.That(a.Problems[0].Field, Is.EqualTo("-nerfShard"));
            Assert.That(a.Problems[0].Value, Is.EqualTo(shard));
            Assert.That(a.Problems[0].Reason, Does.Contain(reason));
            Assert.That(a.Problems[0].Fix, Does.Contain(fix));
            Assert.That(a.Shard, Is.Null);
            Assert.That(a.Shard, Is.Null);
        }

        [TestCase("0/1", 0, 1)]
        [TestCase("3/4", 3, 4)]
        [TestCase(" 1/4", 1, 4)]
        [TestCase("9999/10000", 9999, 10000)]
        public void GoodShards(string shard, int index, int count)
        {
            var a = BatchArguments.Parse(new[] { "-nerfShard", shard, "-nerfConfig", "a.json" });
            Assert.That(a.IsValid, Is.True);
            Assert.That(a.Shard, Is.EqualTo(new ShardSpec(index, count)));
            Assert.That(a.Shard.Value.Index, Is.EqualTo(index));
            Assert.That(a.Shard.Value.Count, Is.EqualTo(count));
        }
    }
}
