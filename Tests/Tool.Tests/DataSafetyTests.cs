using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// Issue 32 items 1, 3 and 4 with real symbolic links and real processes: no command that writes is carried into a
    /// dataset by a link; a working folder whose journal names a live process (a real <c>sleep</c>) is never removed,
    /// empty or not; a <c>check --json</c> or <c>evaluate</c> killed by SIGKILL leaves nothing the rerun refuses.
    /// </summary>
    [TestFixture]
    public class DataSafetyTests
    {
        const int W = 40, H = 32;

        const string SmallConfig =
            "{ \"schemaVersion\": 1, \"name\": \"lego\", \"seed\": 5,\n" +
            "  \"splits\": { \"train\": { \"count\": 4 }, \"val\": { \"count\": 1 }, \"test\": { \"count\": 1 } } }";
        Scratch _scratch;

        [SetUp] public void SetUp() => _scratch = new Scratch();

        [TearDown]
        public void TearDown()
        {
            FileOps.Faults = null;
            _scratch.Dispose();
        }

        /// <summary>An analytic sphere dataset and plain renders of its test split (r_&lt;i&gt;.png).</summary>
        (string dataset, string renders) Sphere()
        {
            var dataset = _scratch.PathOf("sphere");
            var views = AnalyticSphereDataset.Write(dataset, W, H, train: 4, test: 3);
            var renders = _scratch.PathOf("renders");
            Directory.CreateDirectory(renders);
            for (var i = 0; i < views.Count; i++)
                File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], W, H, 6), W, H, PngPixelFormat.Rgb8));
            return (dataset, renders);
        }

        static string[] Entries(string folder) =>
            Directory.GetFileSystemEntries(folder, "*", SearchOption.AllDirectories).Select(e => e.Substring(folder.Length + 1)).OrderBy(e => e, StringComparer.Ordinal).ToArray();

        // ---- item 1: links into the dataset ----

        [TestCase(true, TestName = "EvaluateOutThroughAnAbsoluteFolderLinkIntoTheDatasetIsRefused")]
        [TestCase(false, TestName = "EvaluateOutThroughARelativeFolderLinkIntoTheDatasetIsRefused")]
        public void EvaluateOutThroughAFolderLinkIntoTheDatasetIsRefused(bool absolute)
        {
            var (dataset, renders) = Sphere();
            var before = Entries(dataset);
            var link = _scratch.PathOf("out-link");
            Directory.CreateSymbolicLink(link, absolute ? dataset : "sphere");

            var run = ToolRun.Of("evaluate", dataset, "--renders", renders, "--out", link);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("error: --out = " + link + ": is inside the dataset " + dataset + " (through a symbolic link: it is really " + dataset + "); evaluation never adds files to a dataset."), run.ToString());
            Assert.That(Entries(dataset), Is.EqualTo(before), "nothing was written into the dataset");
        }

        [Test]
        public void EvaluateOutBelowALinkToAnAncestorOfTheDatasetIsRefused()
        {
            var (dataset, renders) = Sphere();
            var before = Entries(dataset);
            // up → the scratch root, which holds the dataset: up/sphere/evaluation is really inside it.
            var up = _scratch.PathOf("renders", "up");
            Directory.CreateSymbolicLink(up, "..");
            var target = Path.Combine(up, "sphere", "evaluation");

            var run = ToolRun.Of("evaluate", dataset, "--renders", renders, "--out", target);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("is inside the dataset " + dataset + " (through a symbolic link: it is really " + Path.Combine(dataset, "evaluation") + ")"), run.ToString());
            Assert.That(Entries(dataset), Is.EqualTo(before));
        }

        [Test]
        public void CheckJsonThroughLinksIntoTheDatasetIsRefused()
        {
            var (dataset, _) = Sphere();
            var before = Entries(dataset);
            // A folder link to the dataset, and a dangling file link whose target would be created inside it.
            var folderLink = _scratch.PathOf("reports");
            Directory.CreateSymbolicLink(folderLink, dataset);
            var fileLink = _scratch.PathOf("report.json");
            File.CreateSymbolicLink(fileLink, Path.Combine(dataset, "report.json"));

            var viaFolder = ToolRun.Of("check", dataset, "--json", Path.Combine(folderLink, "report.json"));
            Assert.That(viaFolder.ExitCode, Is.EqualTo(1), viaFolder.ToString());
            Assert.That(viaFolder.Err, Does.Contain("is inside the dataset " + dataset + " (through a symbolic link: it is really " + Path.Combine(dataset, "report.json") + "); check never adds files to the dataset it checks."));
            var viaFile = ToolRun.Of("check", dataset, "--json", fileLink);
            Assert.That(viaFile.ExitCode, Is.EqualTo(1), viaFile.ToString());
            // .NET sees a dangling link as an existing file: refused as one, never written through.
            Assert.That(viaFile.Err, Does.Contain("error: " + fileLink + " already exists; check never replaces a file."));
            Assert.That(Entries(dataset), Is.EqualTo(before));

            // Plainly inside (no link) is refused too: check never adds a file to the dataset it checks.
            var plain = ToolRun.Of("check", dataset, "--json", Path.Combine(dataset, "report.json"));
            Assert.That(plain.ExitCode, Is.EqualTo(1), plain.ToString());
            Assert.That(plain.Err, Does.Contain("error: --json " + Path.Combine(dataset, "report.json") + " is inside the dataset " + dataset + "; check never adds files to the dataset it checks. Name a file outside the dataset for --json."));
            Assert.That(Entries(dataset), Is.EqualTo(before));

            // Outside the dataset the report is written as before.
            var outside = _scratch.PathOf("outside.json");
            var ok = ToolRun.Of("check", dataset, "--json", outside);
            Assert.That(File.Exists(outside), Is.True, ok.ToString());
        }

        [Test]
        public void PlanOutThroughALinkIntoADatasetIsRefused()
        {
            var (dataset, _) = Sphere();
            var before = Entries(dataset);
            var link = _scratch.PathOf("datasets");
            Directory.CreateSymbolicLink(link, dataset);
            var config = _scratch.WriteText("plan.json", SmallConfig);

            var run = ToolRun.Of("plan", "--config", config, "--out", Path.Combine(link, "nested"));
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("is inside the existing dataset " + dataset + " (through a symbolic link: it is really " + Path.Combine(dataset, "nested") + "); loaders would see a mixture."), run.ToString());
            Assert.That(Entries(dataset), Is.EqualTo(before));
        }

        [Test]
        public void CleanNeverActsThroughALinkNamedLikeAWorkingFolder()
        {
            // A folder elsewhere that looks like an interrupted plan of "lego" (our journal, an ended run), reached by a
            // link carrying a working folder's name: clean must not delete it, nor the link.
            var elsewhere = _scratch.PathOf("elsewhere");
            Directory.CreateDirectory(elsewhere);
            File.WriteAllText(Path.Combine(elsewhere, "keep.txt"), "the user's");
            var output = _scratch.PathOf("lego");
            new OperationJournal { Operation = "write", Output = output, Owner = new OperationOwner(Environment.MachineName, int.MaxValue - 7, null) }.Save(elsewhere);
            var link = WorkingFolders.NewPartial(output, DateTime.UtcNow);
            Directory.CreateSymbolicLink(link, elsewhere);

            var clean = ToolRun.Of("clean", _scratch.Root);
            Assert.That(clean.ExitCode, Is.EqualTo(0), clean.ToString());
            Assert.That(clean.Out + clean.Err, Does.Not.Contain("removed"), clean.ToString());
            Assert.That(Directory.Exists(link), Is.True, "the link stays");
            Assert.That(File.ReadAllText(Path.Combine(elsewhere, "keep.txt")), Is.EqualTo("the user's"));
        }

        // ---- item 3: a live run's working folder, empty or not ----

        [Test]
        public void AWorkingFolderOfALiveProcessIsNeverRemovedEmptyOrNot()
        {
            var output = _scratch.PathOf("lego");
            using (var sleep = Process.Start(new ProcessStartInfo("sleep", "600") { UseShellExecute = false }))
            {
                try
                {
                    var owner = new OperationOwner(Environment.MachineName, sleep.Id, sleep.StartTime.ToUniversalTime());
                    // Another plan's still-empty working folder: its journal (naming the live sleep process) and nothing else.
                    var working = WorkingFolders.NewPartial(output, DateTime.UtcNow);
                    WorkingFolders.Create(working, new OperationJournal { Operation = "write", Output = output, Owner = owner });
                    Assert.That(WorkingFolders.HoldsNoFile(working), Is.True, "still empty");

                    var config = _scratch.WriteText("plan.json", SmallConfig);
                    var plan = ToolRun.Of("plan", "--config", config, "--out", output);
                    Assert.That(plan.ExitCode, Is.EqualTo(0), plan.ToString());
                    Assert.That(plan.Err, Does.Contain("left " + working + " alone: process " + sleep.Id), plan.ToString());
                    Assert.That(Directory.Exists(working), Is.True, "the live run's folder is still there");

                    var clean = ToolRun.Of("clean", _scratch.Root);
                    Assert.That(Directory.Exists(working), Is.True, clean.ToString());
                    Assert.That(clean.Err, Does.Contain("kept " + working), clean.ToString());
                }
                finally
                {
                    sleep.Kill();
                    sleep.WaitForExit();
                }
            }
            // Its process has ended: now it is a leftover clean removes.
            var after = ToolRun.Of("clean", _scratch.Root);
            Assert.That(after.Out, Does.Contain("removed " + _scratch.PathOf("lego.partial-")), after.ToString());
            Assert.That(Directory.GetDirectories(_scratch.Root, "lego.partial-*"), Is.Empty);
        }

        // ---- item 4: killed by SIGKILL, rerun ----

        /// <summary>Runs the built tool in its own process, killed (SIGKILL) just before its <paramref name="killAt"/>-th file operation.</summary>
        static void RunKilled(int killAt, params string[] args)
        {
            var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            start.ArgumentList.Add(typeof(Program).Assembly.Location);
            foreach (var a in args) start.ArgumentList.Add(a);
            start.Environment[Program.KillVariable] = killAt.ToString(System.Globalization.CultureInfo.InvariantCulture);
            using (var process = Process.Start(start))
            {
                var err = process.StandardError.ReadToEndAsync();
                var outText = process.StandardOutput.ReadToEnd();
                Assert.That(process.WaitForExit(120000), Is.True);
                Assert.That(process.ExitCode, Is.EqualTo(137), "killed by SIGKILL (128 + 9)\n" + outText + err.Result);
            }
        }

        /// <summary>The 1-based number of the first file operation (as the in-process run counts them) that <paramref name="which"/> picks.</summary>
        static int StepOf(Func<string, bool> which, params string[] args)
        {
            var counting = FileFaultPlan.Counting();
            FileOps.Faults = counting;
            try { ToolRun.Of(args); }
            finally { FileOps.Faults = null; }
            var index = counting.Operations.ToList().FindIndex(o => which(o));
            Assert.That(index, Is.GreaterThanOrEqualTo(0), string.Join("\n", counting.Operations));
            return index + 1;
        }

        [Test]
        public void ACheckJsonKilledBeforeItsReportIsCompleteLeavesNothingTheRerunRefuses()
        {
            var (dataset, _) = Sphere();
            var json = _scratch.PathOf("report.json");
            var trial = _scratch.PathOf("trial.json");
            // The step that renames the complete temporary report into place, counted on an identical run.
            var move = StepOf(o => o.StartsWith("move ", StringComparison.Ordinal) && o.Contains(".trial.json.writing-"), "check", dataset, "--json", trial);
            File.Delete(trial);

            RunKilled(move, "check", dataset, "--json", json);
            Assert.That(File.Exists(json), Is.False, "no half-written report under its name");
            var leftovers = Directory.GetFiles(_scratch.Root, ".report.json.writing-*");
            Assert.That(leftovers, Has.Length.EqualTo(1), "the killed run's complete temporary file");

            var again = ToolRun.Of("check", dataset, "--json", json);
            Assert.That(again.ExitCode, Is.EqualTo(0), again.ToString());
            Assert.That(again.Out, Does.Contain("report: " + json));
            Assert.That((bool)JObject.Parse(File.ReadAllText(json))["failed"], Is.False);
            Assert.That(File.Exists(leftovers[0]), Is.False, "the ended run's temporary file was its own leftover: removed");
        }

        [Test]
        public void AnEvaluateKilledMidWayIsReplacedByTheRerun()
        {
            var (dataset, renders) = Sphere();
            var outFolder = _scratch.PathOf("evaluation");
            var trial = _scratch.PathOf("trial-evaluation");
            // Just after the first error map: the run dies with some maps written, no report, no metrics.json.
            var firstMap = StepOf(o => o.StartsWith("write ", StringComparison.Ordinal) && o.EndsWith("_error.png", StringComparison.Ordinal),
                "evaluate", dataset, "--renders", renders, "--out", trial);
            var complete = Entries(trial);

            RunKilled(firstMap + 1, "evaluate", dataset, "--renders", renders, "--out", outFolder);
            // Views are scored on every core, so another thread may finish its map between the first one and the kill
            // (seen on a loaded machine: 2): some maps, not all, and no report.
            var written = Directory.GetFiles(Path.Combine(outFolder, "errors")).Length;
            Assert.That(written, Is.GreaterThanOrEqualTo(1), "an error map was written before the kill");
            Assert.That(written, Is.LessThan(Directory.GetFiles(Path.Combine(trial, "errors")).Length), "the run died before its last map");
            Assert.That(File.Exists(Path.Combine(outFolder, "metrics.json")), Is.False);

            var again = ToolRun.Of("evaluate", dataset, "--renders", renders, "--out", outFolder);
            Assert.That(again.ExitCode, Is.EqualTo(0), again.ToString());
            Assert.That(Entries(outFolder), Is.EqualTo(complete), "the same files as an uninterrupted run, and no journal left");
            Assert.That((string)JObject.Parse(File.ReadAllText(Path.Combine(outFolder, "metrics.json")))["generator"], Is.EqualTo(MetricsJson.Generator));
        }
    }
}
