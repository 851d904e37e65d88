using System.Diagnostics;
using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// Issue 22: a crafted merge journal made clean (and the merge's own recovery) create folders and move files outside
    /// what it cleans. Every path read from a journal must lie inside the folders its operation owns, or recovery
    /// refuses, naming the journal, and changes nothing.
    /// </summary>
    [TestFixture]
    public class JournalPathsTests
    {
        static readonly ViewCounts Counts = new ViewCounts(2, 1, 1);

        /// <summary>The real tool, killed by the OS in the middle of <c>merge --files move</c> (as in <see cref="KilledProcessTests"/>).</summary>
        static string KilledMerge(Scratch scratch, out string[] args)
        {
            var shards = ShardFolders.Create(scratch.PathOf("shards"), 2, Counts);
            args = new[] { "merge", "--files", "move", "--out", scratch.PathOf("lego") }.Concat(shards).ToArray();
            var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            start.ArgumentList.Add(typeof(Program).Assembly.Location);
            foreach (var a in args) start.ArgumentList.Add(a);
            start.Environment[Program.KillVariable] = "19";
            using (var process = Process.Start(start))
            {
                var err = process.StandardError.ReadToEndAsync();
                var outText = process.StandardOutput.ReadToEnd();
                Assert.That(process.WaitForExit(60000), Is.True);
                Assert.That(process.ExitCode, Is.EqualTo(137), "killed by SIGKILL\n" + outText + err.Result);
            }
            return Directory.GetDirectories(scratch.Root, ".lego.merging-*").Single();
        }

        /// <summary>Points the journal's first move that already happened at <paramref name="elsewhere"/>.</summary>
        static void Redirect(string staging, string elsewhere)
        {
            var path = OperationJournal.PathIn(staging);
            var journal = JObject.Parse(File.ReadAllText(path));
            var move = ((JArray)journal["moves"]).OfType<JObject>().First(m => File.Exists(Path.Combine(staging, (string)m["to"])));
            move["from"] = elsewhere;
            File.WriteAllText(path, journal.ToString());
        }

        [TestCase("clean")]
        [TestCase("merge")]
        public void AMergeJournalNamingAPathOutsideTheShardsIsRefused(string next)
        {
            using (var scratch = new Scratch())
            using (var outside = new Scratch())
            {
                var staging = KilledMerge(scratch, out var args);
                var victim = outside.PathOf("victim", "train", "r_0.png");
                Redirect(staging, victim);
                var stagedBefore = Directory.GetFiles(staging, "r_*", SearchOption.AllDirectories).Length;

                var run = next == "clean" ? ToolRun.Of("clean", scratch.Root) : ToolRun.Of(args);
                Assert.That(run.Out + run.Err, Does.Contain("refused to recover the interrupted merge of " + scratch.PathOf("lego") + ": its journal " +
                                                            OperationJournal.PathIn(staging) + " names " + victim + ", which is not inside one of the shard folders"), run.ToString());
                Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
                Assert.That(Interruptions.HasStackTrace(run.Out + run.Err), Is.False, run.ToString());
                Assert.That(Directory.Exists(outside.PathOf("victim")), Is.False, "nothing was created outside the shards\n" + run);
                Assert.That(Directory.GetFiles(staging, "r_*", SearchOption.AllDirectories).Length, Is.EqualTo(stagedBefore), "nothing was moved\n" + run);
            }
        }

        [Test]
        public void AMergeJournalListingAForeignFolderAsAShardIsRefused()
        {
            using (var scratch = new Scratch())
            using (var outside = new Scratch())
            {
                var staging = KilledMerge(scratch, out _);
                var path = OperationJournal.PathIn(staging);
                var journal = JObject.Parse(File.ReadAllText(path));
                journal["shards"] = new JArray(outside.Root); // no shard.json there
                var victim = outside.PathOf("victim", "r_0.png");
                ((JArray)journal["moves"]).OfType<JObject>().First(m => File.Exists(Path.Combine(staging, (string)m["to"])))["from"] = victim;
                File.WriteAllText(path, journal.ToString());

                var run = ToolRun.Of("clean", scratch.Root);
                Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
                Assert.That(run.Err, Does.Contain("error: refused to recover the interrupted merge").And.Contain(path), run.ToString());
                Assert.That(Directory.Exists(outside.PathOf("victim")), Is.False);
                Assert.That(Directory.Exists(staging), Is.True, "a refused working folder is kept");
            }
        }

        [Test]
        public void ConvertAndReplaceJournalsNamingPathsOutsideTheirFoldersAreRefused()
        {
            using (var scratch = new Scratch())
            using (var outside = new Scratch())
            {
                var dataset = RenderedDataset.PlanOnly(scratch, "lego");
                // convert: a file to move "into place" above the output.
                var convert = Path.Combine(dataset, ".convert.partial-20240101-120000-0123abcd~");
                Directory.CreateDirectory(convert);
                File.WriteAllText(Path.Combine(convert, "x.txt"), "x");
                new OperationJournal { Operation = "convert", Output = dataset, State = OperationJournal.Committing, Files = { "../../escape.txt" } }.Save(convert);
                // a plan's replace: the "aside" to delete is a user's folder elsewhere.
                var precious = outside.PathOf("precious");
                Directory.CreateDirectory(precious);
                var write = scratch.PathOf("other.partial-20240101-120000-0123abcd~");
                Directory.CreateDirectory(write);
                File.WriteAllText(Path.Combine(write, "transforms_train.json"), "{}");
                new OperationJournal { Operation = "write", Output = scratch.PathOf("other"), State = OperationJournal.Committing, Aside = precious }.Save(write);

                var run = ToolRun.Of("clean", scratch.Root);
                Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
                Assert.That(run.Err, Does.Contain("refused to recover the interrupted convert of " + dataset + ": its journal " + OperationJournal.PathIn(convert) + " names ../../escape.txt"));
                Assert.That(run.Err, Does.Contain("refused to recover the interrupted write of " + scratch.PathOf("other") + ": its journal " + OperationJournal.PathIn(write) + " names " + precious));
                Assert.That(Directory.Exists(precious), Is.True);
                Assert.That(Directory.Exists(convert) && Directory.Exists(write), Is.True, "refused working folders are kept");
                Assert.That(Directory.Exists(scratch.PathOf("other")), Is.False, "the refused write was not moved into place");
            }
        }
    }
}
