using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// merge stopped (as by kill -9) or failing at every one of its file operations, on three small shards: the next
    /// merge into the same --out finishes or rolls back the interrupted one, and every view's files exist exactly once.
    /// </summary>
    [TestFixture]
    public class InterruptedMergeTests
    {
        static readonly ViewCounts Counts = new ViewCounts(2, 1, 1);
        const int ShardCount = 2;

        static string[] Args(string output, string[] shards, bool move) =>
            new[] { "merge", "--out", output, "--files", move ? "move" : "copy" }.Concat(shards).ToArray();

        static int StepsOfAMerge(bool move)
        {
            using (var probe = new Scratch())
            {
                var shards = ShardFolders.Create(probe.PathOf("shards"), ShardCount, Counts);
                var steps = Interruptions.Steps(out var run, Args(probe.PathOf("lego"), shards, move));
                Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
                return steps;
            }
        }

        [TestCase(false)]
        [TestCase(true)]
        public void AMergeKilledAtAnyStepIsFinishedOrRolledBackByTheNextOne(bool move)
        {
            var steps = StepsOfAMerge(move);
            Assert.That(steps, Is.GreaterThan(12), "reads, journal, transfers, JSON, rename");
            for (var step = 1; step <= steps; step++)
                using (var scratch = new Scratch())
                {
                    var shards = ShardFolders.Create(scratch.PathOf("shards"), ShardCount, Counts);
                    var output = scratch.PathOf("lego");
                    var args = Args(output, shards, move);
                    Interruptions.StopAt(step, args);
                    var wasInPlace = Directory.Exists(output);
                    var hadWorkingFolder = Directory.GetDirectories(scratch.Root, ".lego.merging-*").Length > 0;

                    var again = ToolRun.Of(args);
                    var where = "killed before step " + step + " of " + steps + "\n" + again;
                    Assert.That(again.ExitCode, Is.EqualTo(0), where);
                    // It says what it did about the interrupted run.
                    var said = again.Out + again.Err;
                    if (wasInPlace) Assert.That(said, Does.Contain("note: finished the interrupted merge"), where);
                    else if (hadWorkingFolder) Assert.That(said, Does.Match("note: (finished|rolled back) the interrupted merge|note: removed|merged"), where);
                    Assert.That(again.Out + again.Err, Does.Not.Contain("re-render").And.Not.Contain("Rerun"), where);
                    AssertMergedOnce(output, shards, move, where);
                    Assert.That(Interruptions.Entries(scratch.Root), Is.EqualTo(new[] { "lego", "shards" }), where + "\nno working folder is left");
                }
        }

        [Test]
        public void AMergeFailingAtAnyStepChangesNothingOrCompletes()
        {
            var steps = StepsOfAMerge(true);
            for (var step = 1; step <= steps; step++)
                using (var scratch = new Scratch())
                {
                    var shards = ShardFolders.Create(scratch.PathOf("shards"), ShardCount, Counts);
                    var before = ShardFolders.Snapshot(scratch.PathOf("shards"));
                    var output = scratch.PathOf("lego");
                    var run = Interruptions.FailAt(step, (op, path) => new IOException("No space left on device"), Args(output, shards, true));
                    var where = "failing at step " + step + " of " + steps + "\n" + run;
                    Assert.That(Interruptions.HasStackTrace(run.Out + run.Err), Is.False, where);
                    // Failing to delete the journal after the rename still succeeds; the next run on the output removes it.
                    if (run.ExitCode == 0) AssertMergedOnce(output, shards, true, where, allowJournal: step == steps);
                    else
                    {
                        Assert.That(run.ExitCode, Is.EqualTo(1), where);
                        Assert.That(run.Err, Does.Contain("No space left on device"), where);
                        Assert.That(ShardFolders.Snapshot(scratch.PathOf("shards")), Is.EqualTo(before), where + "\nevery moved file is back");
                        Assert.That(Directory.Exists(output), Is.False, where);
                    }
                    Assert.That(Interruptions.Entries(scratch.Root).Where(n => n.StartsWith(".")), Is.Empty, where + "\nno working folder is left");
                }
        }

        /// <summary>Every planned view's image (and test depth file) exists once, in the output, with its bytes; moved ones are gone from the shards.</summary>
        static void AssertMergedOnce(string output, string[] shards, bool move, string where, bool allowJournal = false)
        {
            if (!allowJournal) Assert.That(File.Exists(Path.Combine(output, OperationJournal.FileName)), Is.False, where + "\nthe journal is gone");
            foreach (var split in ViewCounts.SplitNames)
            {
                var frames = ShardFolders.ReadJson(Path.Combine(output, "transforms_" + split + ".json"))["frames"];
                Assert.That(frames.Count(), Is.EqualTo(Counts.Of(split)), where);
                for (var i = 0; i < Counts.Of(split); i++)
                {
                    Assert.That(File.ReadAllBytes(Path.Combine(output, split, "r_" + i + ".png")), Is.EqualTo(ShardFolders.ImageBytes(split, i)), where + "\n" + split + "/r_" + i);
                    var inShards = shards.Count(s => File.Exists(Path.Combine(s, split, "r_" + i + ".png")));
                    Assert.That(inShards, Is.EqualTo(move ? 0 : 1), where + "\n" + split + "/r_" + i + " in the shards");
                }
            }
            foreach (var shard in shards)
                Assert.That(File.Exists(Path.Combine(shard, ShardManifest.FileName)), Is.True, where + "\nshard metadata stays");
        }
    }
}
