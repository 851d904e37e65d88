using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// <c>nerf-dataset demo</c>: every preset's dataset passes validate and its own check (the report in the dataset
    /// says so, and a fresh <c>check</c> agrees), converts to every export that fits it, and its stand-in renders
    /// evaluate; the same command writes the same bytes; a folder it did not write is refused untouched; and the scene
    /// is asymmetric enough that mirrored poses fail the check. Small sizes keep the suite fast (the walk-through test
    /// runs the defaults).
    /// </summary>
    [TestFixture]
    public class DemoCommandTests
    {
        Scratch _scratch;

        [OneTimeSetUp] public void Create() => _scratch = new Scratch();

        [OneTimeTearDown] public void Delete() => _scratch.Dispose();

        /// <summary>The smallest sizes that show each preset (the lens needs <see cref="DemoDataset.MinLensSize"/>).</summary>
        static string[] Small(DemoPreset preset) => new[]
        {
            "--preset", DemoPresets.Name(preset), "--views", preset == DemoPreset.Dynamic || preset == DemoPreset.Flow ? "10" : "8", // flow: the 10 frames shape-of-motion needs
            "--size", preset == DemoPreset.Lens ? DemoDataset.MinLensSize.ToString(System.Globalization.CultureInfo.InvariantCulture) : "64",
        };

        string Demo(string name, params string[] options)
        {
            var folder = _scratch.PathOf(name);
            var run = ToolRun.Of(new[] { "demo", folder }.Concat(options).ToArray());
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            return folder;
        }

        static IEnumerable<DemoPreset> Presets => Enum.GetValues(typeof(DemoPreset)).Cast<DemoPreset>();

        [TestCaseSource(nameof(Presets))]
        public void EveryPresetPassesValidateAndCheckAndConvertsToEveryExportThatFitsIt(DemoPreset preset)
        {
            var folder = Demo("preset-" + DemoPresets.Name(preset), Small(preset));
            var report = JObject.Parse(File.ReadAllText(Path.Combine(folder, DatasetCheck.ReportFileName)));
            Assert.That((bool)report["failed"], Is.False, report.ToString());
            Assert.That((int)report["viewsChecked"], Is.GreaterThan(0));

            var validate = ToolRun.Of("validate", folder);
            Assert.That(validate.ExitCode, Is.EqualTo(0), validate.ToString());
            var check = ToolRun.Of("check", folder);
            Assert.That(check.ExitCode, Is.EqualTo(0), check.ToString());

            // Every pass the preset promises, for the first train view.
            var train = Path.Combine(folder, "train");
            foreach (var file in new[] { "r_0.png", "r_0_depth_0000.png", "r_0_normal_0000.png", "r_0_mask_0000.png" })
                Assert.That(File.Exists(Path.Combine(train, file)), Is.True, file);
            Assert.That(File.Exists(Path.Combine(folder, TargetPointCloud.FileName)), Is.True);
            Assert.That(Directory.Exists(Path.Combine(folder, TargetMeshPly.Folder)), Is.True, "the geometry pack");
            Assert.That(File.Exists(Path.Combine(train, "r_0_instance_0000.png")), Is.EqualTo(preset == DemoPreset.Labels));
            Assert.That(File.Exists(Path.Combine(folder, DatasetLayout.LabelsFileName)), Is.EqualTo(preset == DemoPreset.Labels));
            Assert.That(File.Exists(Path.Combine(train, "r_0_sharp_0000.png")), Is.EqualTo(preset == DemoPreset.Blur));
            Assert.That(File.Exists(Path.Combine(train, "r_0_clean.png")), Is.EqualTo(preset == DemoPreset.Exposure));
            Assert.That(File.Exists(Path.Combine(train, "r_0_hdr.exr")), Is.EqualTo(preset == DemoPreset.Hdr || preset == DemoPreset.Relight));
            Assert.That(File.Exists(Path.Combine(train, "r_0_albedo.exr")) && File.Exists(Path.Combine(train, "r_0_emission.exr")), Is.EqualTo(preset == DemoPreset.Materials || preset == DemoPreset.Relight), "the relight preset writes the material passes too");
            Assert.That(File.Exists(Path.Combine(train, "r_0_light_sky_120.png")), Is.EqualTo(preset == DemoPreset.Relight));
            Assert.That(File.Exists(Path.Combine(folder, RelightingKeys.LightsFile)), Is.EqualTo(preset == DemoPreset.Relight));
            Assert.That(File.Exists(Path.Combine(folder, "flow", "flow.json")), Is.EqualTo(preset == DemoPreset.Flow), "the flow preset computes flow/");
            var transforms = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")));
            Assert.That(transforms["k1"] != null, Is.EqualTo(preset == DemoPreset.Lens), "the lens preset records its distortion");
            Assert.That(transforms["frames"][0]["time"] != null, Is.EqualTo(preset == DemoPreset.Dynamic || preset == DemoPreset.Monocular || preset == DemoPreset.Flow), "the dynamic, monocular and flow presets record time");

            foreach (var target in DemoCommand.Targets(preset))
            {
                var name = ExportTargets.Name(target);
                var convert = ToolRun.Of("convert", folder, "--to", name, "--out", folder + "-" + name);
                Assert.That(convert.ExitCode, Is.EqualTo(0), name + "\n" + convert);
                Assert.That(Directory.EnumerateFiles(folder + "-" + name, "*", SearchOption.AllDirectories), Is.Not.Empty, name);
            }
        }

        [Test]
        public void TheExportsOfThePresetsCoverEveryConvertTarget()
        {
            var covered = Presets.SelectMany(DemoCommand.Targets).Select(ExportTargets.Name).Distinct().OrderBy(n => n);
            Assert.That(covered, Is.EqualTo(ExportTargets.Names.OrderBy(n => n)));
        }

        [Test]
        public void TheSameCommandWritesTheSameBytes()
        {
            var first = Demo("same-1", "--views", "6", "--size", "48");
            var second = Demo("same-2", "--views", "6", "--size", "48");
            var files = Directory.GetFiles(first, "*", SearchOption.AllDirectories).Select(f => Path.GetRelativePath(first, f)).OrderBy(f => f, StringComparer.Ordinal).ToList();
            Assert.That(Directory.GetFiles(second, "*", SearchOption.AllDirectories).Select(f => Path.GetRelativePath(second, f)).OrderBy(f => f, StringComparer.Ordinal), Is.EqualTo(files));
            Assert.That(files, Has.Member(DatasetCheck.ReportFileName).And.Member("train" + Path.DirectorySeparatorChar + "r_0.png"));
            foreach (var file in files)
            {
                byte[] a = File.ReadAllBytes(Path.Combine(first, file)), b = File.ReadAllBytes(Path.Combine(second, file));
                if (file == DatasetCheck.ReportFileName)
                {
                    // The report names the folder it checked; nothing else in it may differ.
                    var text = System.Text.Encoding.UTF8.GetString(b).Replace(JsonPath(second), JsonPath(first));
                    Assert.That(text, Is.EqualTo(System.Text.Encoding.UTF8.GetString(a)), file);
                }
                else Assert.That(b, Is.EqualTo(a), file);
            }
        }

        static string JsonPath(string path) => new JValue(path).ToString(Newtonsoft.Json.Formatting.None).Trim('"');

        [Test]
        public void ItRefusesAFolderItDidNotWriteAndLeavesItUntouched()
        {
            var folder = _scratch.PathOf("foreign");
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, "notes.txt"), "mine");
            var run = ToolRun.Of("demo", folder, "--views", "4", "--size", "32");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("error: folder = " + folder + ": already holds files that nerf-dataset demo did not write").And.Contain("demo refused: nothing was written."));
            Assert.That(Directory.GetFileSystemEntries(folder), Is.EqualTo(new[] { Path.Combine(folder, "notes.txt") }));
            Assert.That(File.ReadAllText(Path.Combine(folder, "notes.txt")), Is.EqualTo("mine"));
            Assert.That(Directory.GetFileSystemEntries(_scratch.Root).Where(e => Path.GetFileName(e).StartsWith("foreign", StringComparison.Ordinal)), Is.EqualTo(new[] { folder }), "no working folder left beside it");
        }

        [Test]
        public void ItNeverReplacesADatasetThatIsNotADemo()
        {
            // A real capture of the plugin (its settings named otherwise) is this plugin's, but not the demo's to replace.
            var capture = AnalyticDataset.Write(_scratch.Root, "capture", new AnalyticDataset.Options { Train = 2, Val = 1, Test = 1, PointCloud = 0 });
            var before = Directory.GetFiles(capture, "*", SearchOption.AllDirectories).ToDictionary(f => f, File.ReadAllBytes);
            var run = ToolRun.Of("demo", capture, "--views", "4", "--size", "32");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("already holds files that nerf-dataset demo did not write"));
            var after = Directory.GetFiles(capture, "*", SearchOption.AllDirectories);
            Assert.That(after, Is.EquivalentTo(before.Keys));
            foreach (var file in after) Assert.That(File.ReadAllBytes(file), Is.EqualTo(before[file]), file);
        }

        [Test]
        public void ItReplacesAnEarlierDemoButNotOneWithAnExportInside()
        {
            var folder = Demo("again", "--views", "4", "--size", "32");
            Demo("again", "--views", "5", "--size", "32");
            Assert.That(File.Exists(Path.Combine(folder, "train", "r_4.png")), Is.True, "the second demo replaced the first");
            // An export inside the demo is the user's work: the replace refuses (the capture's own rule, OwnDataset).
            Assert.That(ToolRun.Of("convert", folder, "--to", "ngp").ExitCode, Is.EqualTo(0));
            var run = ToolRun.Of("demo", folder, "--views", "4", "--size", "32");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("is an export made with nerf-dataset convert"));
            Assert.That(File.Exists(Path.Combine(folder, "train", "r_4.png")), Is.True, "untouched");
        }

        [Test]
        public void TheFlowDemoWritesExactFlowAndTracksAndItsReplaceKnowsThem()
        {
            var folder = Demo("mono-flow", "--preset", "flow", "--views", "12", "--size", "32");
            var record = FlowRecord.Read(folder);
            Assert.That(record.Tracks.Select(t => t.QueryFrame), Is.EqualTo(Enumerable.Range(0, 10)), "12 steps: tracks from the first 10 (every step)");
            Assert.That(record.Pairs.Count, Is.EqualTo(22), "11 forward and 11 backward pairs");
            // flow/ is the plugin's (OwnDataset): a second demo replaces the first.
            Demo("mono-flow", "--preset", "flow", "--views", "12", "--size", "32");
            Assert.That(File.Exists(Path.Combine(folder, FlowLayout.RecordFile)), Is.True);
            Assert.That(ToolRun.Of("convert", folder, "--to", "shape-of-motion", "--out", _scratch.PathOf("mono-flow-som")).ExitCode, Is.EqualTo(0));
        }

        [Test]
        public void StandInRendersEvaluateWithAReportAndScoreHighButNotPerfectly()
        {
            var folder = Demo("scored", "--views", "10", "--size", "64");
            var renders = _scratch.PathOf("scored-renders");
            var run = ToolRun.Of("demo", renders, "--renders-for", folder);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.Contain("STAND-IN"));
            Assert.That(File.ReadAllText(Path.Combine(renders, DemoRenders.NoteFileName)), Does.StartWith("STAND-IN RENDERS, not a trained model's."));
            var tests = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_test.json")))["frames"].Count();
            Assert.That(Directory.GetFiles(renders, "r_*.png").Length, Is.EqualTo(tests));

            var evaluate = ToolRun.Of("evaluate", folder, "--renders", renders);
            Assert.That(evaluate.ExitCode, Is.EqualTo(0), evaluate.ToString());
            var output = Path.Combine(renders, "evaluation-test");
            Assert.That(File.Exists(Path.Combine(output, ReportHtml.FileName)), Is.True);
            var mean = JObject.Parse(File.ReadAllText(Path.Combine(output, MetricsJson.FileName)))["mean"];
            // The same scene at the same poses: far better than a wrong pose (~10–15 dB), never identical (a blur and noise).
            Assert.That((double)mean["psnr"], Is.InRange(22.0, 45.0), mean.ToString());
            Assert.That((int)mean["identical_views"], Is.EqualTo(0));

            var again = ToolRun.Of("demo", renders, "--renders-for", folder);
            Assert.That(again.ExitCode, Is.EqualTo(1), "never into a folder that is not empty");
            Assert.That(again.Err, Does.Contain("is not empty"));
        }

        [Test]
        public void StandInRendersExistOnlyForADemo()
        {
            var capture = AnalyticDataset.Write(_scratch.Root, "not-a-demo", new AnalyticDataset.Options { Train = 2, Val = 1, Test = 1, PointCloud = 0 });
            var renders = _scratch.PathOf("not-a-demo-renders");
            var run = ToolRun.Of("demo", renders, "--renders-for", capture);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("is not a dataset nerf-dataset demo wrote"));
            Assert.That(Directory.Exists(renders), Is.False);
        }

        [Test]
        public void MirroredPosesFailTheCheck()
        {
            // The world mirrored in x (S·M·S, still rigid and right-handed): a camera layout and scene with a mirror
            // symmetry would look the same, so the check passing the demo proves nothing unless this fails.
            var folder = Demo("mirrored", "--views", "8", "--size", "64");
            File.Delete(Path.Combine(folder, DatasetCheck.ReportFileName));
            var s = Matrix4x4d.FromRowMajor(-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
            DatasetFaults.EditPoses(folder, m => s * m * s);
            Assert.That(ToolRun.Of("validate", folder).ExitCode, Is.EqualTo(0), "the poses are valid ones");
            var check = ToolRun.Of("check", folder);
            Assert.That(check.ExitCode, Is.EqualTo(1), check.ToString());
            Assert.That(check.Out, Does.Contain("[multi-view geometry]"), check.ToString());
        }

        [Test]
        public void UsageMistakesNameTheOptionAndTheChoices()
        {
            var preset = ToolRun.Of("demo", _scratch.PathOf("x"), "--preset", "lables");
            Assert.That(preset.ExitCode, Is.EqualTo(2));
            Assert.That(preset.Err, Does.Contain("--preset = lables: is not a demo preset.").And.Contain("static, dynamic, labels, lens, exposure, blur").And.Contain("labels"));
            var views = ToolRun.Of("demo", _scratch.PathOf("x"), "--views", "3");
            Assert.That(views.Err, Does.Contain("--views 3: give the train views, a whole number from 4 to 2000."));
            var lens = ToolRun.Of("demo", _scratch.PathOf("x"), "--preset", "lens", "--size", "64");
            Assert.That(lens.Err, Does.Contain("--size 64: the lens preset needs 128 px or more"));
            var both = ToolRun.Of("demo", _scratch.PathOf("x"), "--renders-for", _scratch.PathOf("y"), "--views", "8");
            Assert.That(both.Err, Does.Contain("--renders-for renders the views the demo dataset already has"));
            Assert.That(Directory.Exists(_scratch.PathOf("x")), Is.False, "nothing written on a usage error");
        }

        [Test]
        public void ItPrintsTheNextCommandsForItsFolder()
        {
            var run = ToolRun.Of("demo", _scratch.PathOf("next"), "--preset", "labels", "--views", "4", "--size", "32");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var next = run.Out.Split('\n').SkipWhile(l => l != "next:").Skip(1).Select(l => l.Trim()).Where(l => l.Length > 0).ToList();
            var folder = _scratch.PathOf("next");
            Assert.That(next, Has.Member("nerf-dataset check " + folder));
            foreach (var target in new[] { "nerfstudio", "colmap", "ngp", "gaussian-grouping" })
                Assert.That(next, Has.Member("nerf-dataset convert " + folder + " --to " + target + " --out " + folder + "-" + target));
            Assert.That(next.Where(l => l.Contains("train")), Has.All.StartWith("# "), "training runs on a GPU machine: shown, not run");
            Assert.That(next, Has.Some.StartWith("nerf-dataset demo " + folder + "-renders --renders-for " + folder));
            Assert.That(next, Has.Some.StartWith("nerf-dataset evaluate " + folder + " --renders " + folder + "-renders"));
        }
    }
}
