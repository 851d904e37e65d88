using System.Diagnostics;
using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// End to end: the real nerf-dataset process, killed by the OS (SIGKILL, via the tool's
    /// NERF_DATASET_KILL_AT_FILE_OPERATION seam) in the middle of <c>merge --files move</c>, after it had moved images out
    /// of the shards; the next merge moves them back and completes.
    /// </summary>
    [TestFixture]
    public class KilledProcessTests
    {
        [Test]
        public void AMergeKilledByTheOsIsRecoveredByTheNextMerge()
        {
            using (var scratch = new Scratch())
            {
                var counts = new ViewCounts(2, 1, 1);
                var shards = ShardFolders.Create(scratch.PathOf("shards"), 2, counts);
                var output = scratch.PathOf("lego");
                var args = new[] { "merge", "--files", "move", "--out", output }.Concat(shards).ToArray();
                // 3 transforms files and a config per shard read, staging folder, journal (2), then transfers: step 19 is mid-way through the moves.
                var tool = typeof(Program).Assembly.Location;
                var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
                start.ArgumentList.Add(tool);
                foreach (var a in args) start.ArgumentList.Add(a);
                start.Environment[Program.KillVariable] = "19";
                using (var process = Process.Start(start))
                {
                    var err = process.StandardError.ReadToEndAsync();
                    var outText = process.StandardOutput.ReadToEnd();
                    Assert.That(process.WaitForExit(60000), Is.True);
                    Assert.That(process.ExitCode, Is.EqualTo(137), "killed by SIGKILL (128 + 9)\n" + outText + err.Result);
                }
                var staging = Directory.GetDirectories(scratch.Root, ".lego.merging-*").Single();
                var stranded = Directory.GetFiles(staging, "r_*", SearchOption.AllDirectories);
                Assert.That(stranded, Is.Not.Empty, "the kill came after some images had left the shards");
                Assert.That(Directory.Exists(output), Is.False);

                var again = ToolRun.Of(args);
                Assert.That(again.ExitCode, Is.EqualTo(0), again.ToString());
                Assert.That(again.Out, Does.Contain("note: rolled back the interrupted merge into " + output + ": moved " + stranded.Length + " file(s) back into the shard folders"));
                foreach (var split in ViewCounts.SplitNames)
                    for (var i = 0; i < counts.Of(split); i++)
                        Assert.That(File.ReadAllBytes(Path.Combine(output, split, "r_" + i + ".png")), Is.EqualTo(ShardFolders.ImageBytes(split, i)));
                Assert.That(Interruptions.Entries(scratch.Root), Is.EqualTo(new[] { "lego", "shards" }));
            }
        }
    }
}
