using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary><c>merge</c> on the shard folders a sharded capture leaves (written by the Core tests' ShardFolders).</summary>
    [TestFixture]
    public class MergeCommandTests
    {
        static readonly ViewCounts Counts = new ViewCounts(5, 3, 4);
        Scratch _scratch;
        string[] _shards;
        string _output;

        [SetUp]
        public void SetUp()
        {
            _scratch = new Scratch();
            _shards = ShardFolders.Create(_scratch.PathOf("shards"), 3, Counts);
            _output = _scratch.PathOf("lego");
        }

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        [Test]
        public void MergesCopiesAndPrintsTheSummary()
        {
            var run = ToolRun.Of(new[] { "merge", "--out", _output }.Concat(_shards).ToArray());
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Is.EqualTo("merged 5 train, 3 val, 4 test frames (16 files) into " + _output + "\n"), "12 images and 4 depth files");
            Assert.That(run.Err, Is.Empty);
            var test = ShardFolders.ReadJson(Path.Combine(_output, "transforms_test.json"));
            Assert.That(test["frames"].Select(f => (string)f["file_path"]), Is.EqualTo(new[] { "./test/r_0", "./test/r_1", "./test/r_2", "./test/r_3" }));
            Assert.That(File.ReadAllBytes(Path.Combine(_output, "val", "r_2.png")), Is.EqualTo(ShardFolders.ImageBytes("val", 2)));
            // View 2 of val is global view 7 → shard 7 mod 3 = 1; copying leaves it there.
            Assert.That(File.Exists(Path.Combine(_shards[1], "val", "r_2.png")), Is.True);
        }

        [Test]
        public void FilesMoveTakesTheImagesOutOfTheShards()
        {
            var run = ToolRun.Of(new[] { "merge", "--files", "move", "--out=" + _output }.Concat(_shards.Reverse()).ToArray());
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(File.ReadAllBytes(Path.Combine(_output, "val", "r_2.png")), Is.EqualTo(ShardFolders.ImageBytes("val", 2)));
            Assert.That(File.Exists(Path.Combine(_shards[1], "val", "r_2.png")), Is.False);
            Assert.That(File.Exists(Path.Combine(_shards[1], "transforms_val.json")), Is.True, "the shard's JSON stays");
        }

        [Test]
        public void AMissingShardIsRefusedWithExitOneAndNothingChanges()
        {
            var before = ShardFolders.Snapshot(_scratch.Root);
            var run = ToolRun.Of("merge", "--files", "move", "--out", _output, _shards[0], _shards[2]);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Out, Is.Empty, "every reason goes to stderr");
            var lines = run.Err.TrimEnd('\n').Split('\n');
            Assert.That(lines.Where(l => l.StartsWith("error: ")), Is.Not.Empty);
            Assert.That(run.Err, Does.Contain("lack shard(s) 1/3").And.Contain("-nerfShard 1/3"));
            Assert.That(lines.Last(), Does.StartWith("merge refused: ").And.EndWith("no file was changed."));
            Assert.That(Directory.Exists(_output), Is.False);
            Assert.That(ShardFolders.Snapshot(_scratch.Root), Is.EqualTo(before));
        }

        [Test]
        public void AnExistingOutputFolderIsNeverWrittenInto()
        {
            Directory.CreateDirectory(_output);
            File.WriteAllText(Path.Combine(_output, "notes.txt"), "precious");
            var run = ToolRun.Of(new[] { "merge", "--out", _output }.Concat(_shards).ToArray());
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("error: output = " + _output + ": already exists"));
            Assert.That(Directory.GetFileSystemEntries(_output), Is.EqualTo(new[] { Path.Combine(_output, "notes.txt") }));
        }

        [Test]
        public void AFolderThatIsNoShardIsNamed()
        {
            var plain = _scratch.PathOf("plain");
            Directory.CreateDirectory(plain);
            var run = ToolRun.Of(new[] { "merge", "--out", _output, plain }.Concat(_shards).ToArray());
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain(plain).And.Contain("shard.json"));
        }

        [TestCase(new[] { "merge", "shard-0" }, "merge needs --out")]
        [TestCase(new[] { "merge", "--out", "lego" }, "merge needs the shard folders")]
        [TestCase(new[] { "merge", "--out", "lego", "--files", "link", "shard-0" }, "--files = link: is not copy or move")]
        public void UsageErrorsExitTwo(string[] args, string error)
        {
            var run = ToolRun.Of(args);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("error: " + error).And.Contain("usage:"));
        }
    }
}
