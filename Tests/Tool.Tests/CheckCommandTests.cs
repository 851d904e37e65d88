using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary><c>nerf-dataset check</c> on analytically rendered datasets: the summary, the problem lines, --json, exit codes.</summary>
    [TestFixture]
    public class CheckCommandTests
    {
        Scratch _scratch;
        string _clean;

        static readonly string[] Checks = { "dataset", "alpha vs mask", "depth vs mask", "depth vs normals", "multi-view geometry", "point cloud vs masks", "colour vs geometry", "straight alpha", "instance vs mask", "exposure", "hdr", "materials", "motion blur", "relight", "geometry pack vs depth", "instance reprojection", "records" };

        [OneTimeSetUp]
        public void Render()
        {
            _scratch = new Scratch();
            // With labels, a geometry pack, exposure (train views modified, clean images beside them), hdr, materials and relighting on, so that every check has something to pass.
            _clean = AnalyticDataset.Write(_scratch.Root, "clean", new AnalyticDataset.Options
            {
                Train = 6, Val = 2, Test = 2, MeshesAt = AnalyticSceneMeshes.At, Labels = true, Materials = true,
                Configure = s =>
                {
                    s.Exposure.Mode = ExposureMode.Random;
                    s.Hdr.On = true;
                    s.Relighting = DemoDataset.RelightConditions();
                },
            });
        }

        [OneTimeTearDown] public void Delete() => _scratch.Dispose();

        [Test]
        public void CleanDatasetPrintsEveryCheckAndExitsZero()
        {
            var run = ToolRun.Of("check", _clean);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var lines = run.Out.Split('\n');
            foreach (var check in Checks)
                Assert.That(lines.Count(l => l.StartsWith("  " + check + ": ")), Is.EqualTo(1), check + "\n" + run);
            // A dataset without motion blur skips its check (Documentation~/check.md, "motion blur").
            Assert.That(lines.Where(l => l.StartsWith("  ") && !l.StartsWith("  dataset") && !l.StartsWith("  motion blur")).All(l => l.Contains("; threshold ") && l.EndsWith("; passed")), Is.True, run.ToString());
            Assert.That(lines.Single(l => l.StartsWith("  motion blur: ")), Does.Contain("skipped (no view is motion-blurred"), run.ToString());
            Assert.That(run.Out, Does.Not.Contain("problem:"));
            // Every check but motion blur ran (issue 33: a bare "OK" when most were skipped).
            Assert.That(run.Out.TrimEnd().Split('\n').Last(), Is.EqualTo("OK (" + (Checks.Length - 1) + " of " + Checks.Length + " checks ran; 1 skipped: motion blur)"));
        }

        [Test]
        public void ShiftedColourPrintsOneLinePerProblemAndExitsOne()
        {
            var folder = DatasetFaults.Copy(_clean, _scratch.PathOf("shifted"));
            DatasetFaults.EditImages(folder, DatasetFaults.IsColour, (png, s, _) => DatasetFaults.ShiftRight(png, s, 1));
            var run = ToolRun.Of("check", folder);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Out, Does.Contain("  colour vs geometry: "));
            Assert.That(run.Out, Does.Contain("problem: ./train/r_0.png frame 0 [colour vs geometry]: the alpha's edges lie 1 px right of "), run.ToString());
            Assert.That(run.Err, Does.StartWith("failed: "));
        }

        [Test]
        public void APlanIsRefusedInOneLine()
        {
            var plan = RenderedDataset.PlanOnly(_scratch, "planned");
            var run = ToolRun.Of("check", plan);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Out, Is.Empty);
            Assert.That(run.Err, Is.EqualTo("error: dataset_config.json: imagesRendered = false: this dataset was planned by nerf-dataset plan and has no images, but check decodes them. " +
                                            "Render the dataset with the Unity plugin (window or batch mode) and check that folder; nerf-dataset validate checks a plan's JSON files.\n"));
        }

        [Test]
        public void ManyProblemsOfOneCheckAreCappedWithACount()
        {
            // Every image of a 30-view split missing: 20 lines of the one cause, then how many more.
            var folder = _scratch.PathOf("many-missing");
            var config = _scratch.WriteText("many.json", "{ \"width\": 32, \"height\": 24, \"splits\": { \"train\": { \"count\": 30 }, \"val\": { \"count\": 1 }, \"test\": { \"count\": 1 } } }");
            Assert.That(ToolRun.Of("plan", "--config", config, "--out", folder).ExitCode, Is.EqualTo(0));
            File.Delete(Path.Combine(folder, "dataset_config.json")); // no longer marked as a plan
            var run = ToolRun.Of("validate", folder);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            var problems = run.Out.Split('\n').Where(l => l.StartsWith("problem: ")).ToList();
            // 32 images missing (30 train, 1 val, 1 test): 20 shown, then the count of the other 12.
            Assert.That(problems, Has.Count.EqualTo(21), run.ToString());
            Assert.That(problems.Last(), Is.EqualTo("problem: … and 12 more like these (32 in all)."));
            Assert.That(run.Err, Does.Contain("invalid: 32 problems"), "the count is of all of them");
        }

        [Test]
        public void JsonWritesTheWholeReportAndNeverReplacesAFile()
        {
            var json = _scratch.PathOf("report.json");
            var run = ToolRun.Of("check", _clean, "--json", json, "--split", "train", "--max-views", "4");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var report = JObject.Parse(File.ReadAllText(json));
            Assert.That((bool)report["failed"], Is.False);
            Assert.That((int)report["viewsChecked"], Is.EqualTo(4));
            Assert.That(report["checks"].Select(c => (string)c["name"]), Is.EqualTo(Checks));
            Assert.That(report["checks"].Single(c => (string)c["name"] == "multi-view geometry")["status"].ToString(), Is.EqualTo("passed"));

            File.WriteAllText(json, "not ours");
            var again = ToolRun.Of("check", _clean, "--json", json);
            Assert.That(again.ExitCode, Is.EqualTo(1), again.ToString());
            Assert.That(again.Err, Does.Contain("already exists"));
            Assert.That(File.ReadAllText(json), Is.EqualTo("not ours"));
        }

        [TestCase("check")]
        [TestCase("check", "a", "b")]
        [TestCase("check", "DIR", "--split", "training")]
        [TestCase("check", "DIR", "--max-views", "0")]
        [TestCase("check", "DIR", "--max-views", "many")]
        [TestCase("check", "DIR", "--frames", "3")]
        public void UsageMistakesExitTwo(params string[] args)
        {
            var run = ToolRun.Of(args.Select(a => a == "DIR" ? _clean : a).ToArray());
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.StartWith("error: "));
        }

        [Test]
        public void MissingFolderIsOneErrorLine()
        {
            var run = ToolRun.Of("check", _scratch.PathOf("nowhere"));
            Assert.That(run.ExitCode, Is.EqualTo(1));
            Assert.That(run.Err.Trim().Split('\n'), Has.Length.EqualTo(1));
            Assert.That(run.Err, Does.StartWith("error: ").And.Contain("nowhere"));
        }
    }
}
