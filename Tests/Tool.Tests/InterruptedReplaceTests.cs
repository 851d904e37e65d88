using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// plan with "overwrite": "replace" over an earlier plan, stopped (as by kill -9) at every file operation: at every
    /// moment the old or the new dataset exists, and the next plan — or clean — leaves exactly one complete dataset.
    /// The capture uses the same write session (DatasetWriteSession), so this covers it too.
    /// </summary>
    [TestFixture]
    public class InterruptedReplaceTests
    {
        const string Config = "{ \"width\": 16, \"height\": 12, \"overwrite\": \"replace\", \"distance\": SEED, " +
                              "\"splits\": { \"train\": { \"count\": 2 }, \"val\": { \"count\": 1 }, \"test\": { \"count\": 1 } } }";

        static (string output, string oldConfig, string newConfig) Setup(Scratch scratch)
        {
            var oldConfig = scratch.WriteText("old.json", Config.Replace("SEED", "4"));
            var newConfig = scratch.WriteText("new.json", Config.Replace("SEED", "5"));
            var output = scratch.PathOf("lego");
            var run = ToolRun.Of("plan", "--config", oldConfig, "--out", output);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            return (output, oldConfig, newConfig);
        }

        static string Train(string dataset) => File.ReadAllText(Path.Combine(dataset, "transforms_train.json"));

        [TestCase("plan")]
        [TestCase("clean")]
        public void AReplaceKilledAtAnyStepNeverLosesBothDatasets(string next)
        {
            int steps;
            string oldTrain, newTrain;
            using (var probe = new Scratch())
            {
                var (output, _, newConfig) = Setup(probe);
                oldTrain = Train(output);
                steps = Interruptions.Steps(out var run, "plan", "--config", newConfig, "--out", output);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
                newTrain = Train(output);
            }
            Assert.That(newTrain, Is.Not.EqualTo(oldTrain), "the distances give different datasets");

            var movedAside = 0;
            for (var step = 1; step <= steps; step++)
                using (var scratch = new Scratch())
                {
                    var (output, _, newConfig) = Setup(scratch);
                    Interruptions.StopAt(step, "plan", "--config", newConfig, "--out", output);
                    var where = "killed before step " + step + " of " + steps;

                    // Right after the kill: the old dataset is in place, or moved aside with the complete new one beside it, or the new one is in place.
                    if (Directory.Exists(output)) Assert.That(Train(output), Is.EqualTo(oldTrain).Or.EqualTo(newTrain), where);
                    else
                    {
                        var aside = Directory.GetDirectories(scratch.Root, "lego.replaced-*~").Single();
                        movedAside++;
                        Assert.That(Train(aside), Is.EqualTo(oldTrain), where);
                    }

                    var again = next == "plan"
                        ? ToolRun.Of("plan", "--config", newConfig, "--out", output)
                        : ToolRun.Of("clean", scratch.Root);
                    where += "\n" + again;
                    Assert.That(again.ExitCode, Is.EqualTo(0), where);
                    Assert.That(Interruptions.HasStackTrace(again.Out + again.Err), Is.False, where);
                    if (next == "plan") Assert.That(Train(output), Is.EqualTo(newTrain), where);
                    else Assert.That(Train(output), Is.EqualTo(oldTrain).Or.EqualTo(newTrain), where);
                    Assert.That(File.Exists(Path.Combine(output, OperationJournal.FileName)), Is.False, where);
                    Assert.That(Interruptions.Entries(output), Is.EqualTo(new[] { "dataset_config.json", "eval_protocol.json", "rig_preview.ply", "rig_preview.png", "transforms_test.json", "transforms_train.json", "transforms_val.json" }), where);

                    // A partial folder of the killed run is reported, never silently deleted; clean removes it.
                    if (next == "plan" && Interruptions.Entries(scratch.Root).Any(n => n.Contains(".partial-")))
                        Assert.That(again.Err, Does.Contain("note: left over: ").And.Contain("nerf-dataset clean " + scratch.Root), where);
                    if (next == "plan") ToolRun.Of("clean", scratch.Root);
                    Assert.That(Interruptions.Entries(scratch.Root), Is.EqualTo(new[] { "lego", "new.json", "old.json" }), where);
                }
            Assert.That(movedAside, Is.EqualTo(1), "one step lies between moving the old dataset aside and moving the new one in");
        }
    }
}
