using System.Collections;
using System.IO;
using System.Text.RegularExpressions;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.TestTools;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// The Dataset Tools run the headless tool's commands inside the editor (no .NET SDK): the same lines as the tool,
    /// one Console entry, one command at a time, and a window that draws.
    /// </summary>
    [TestFixture]
    public class DatasetToolsTests
    {
        string _root;

        [SetUp]
        public void SetUp()
        {
            _root = Path.Combine(Path.GetTempPath(), "nerf-tools-test-" + System.Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_root);
        }

        [TearDown]
        public void TearDown()
        {
            if (Directory.Exists(_root)) Directory.Delete(_root, true);
        }

        [Test]
        public void EveryExportTargetIsOfferedOnceByAButtonOrTheMoreFormatsMenu()
        {
            var offered = new System.Collections.Generic.List<ExportTarget>();
            foreach (var e in DatasetToolsWindow.Exports) if (!offered.Contains(e.Target)) offered.Add(e.Target);
            offered.AddRange(DatasetToolsWindow.MoreExports);
            Assert.That(offered, Is.EquivalentTo((ExportTarget[])System.Enum.GetValues(typeof(ExportTarget))));
            Assert.That(DatasetToolsWindow.MoreExports, Has.No.Member(ExportTarget.Colmap), "a target with a button is not in the menu again");
        }

        /// <summary>A planned dataset (JSON files, no images), written by the tool's own plan command.</summary>
        string Planned()
        {
            var config = Path.Combine(_root, "c.json");
            File.WriteAllText(config, "{ \"splits\": { \"train\": { \"count\": 3 }, \"val\": { \"count\": 2 }, \"test\": { \"count\": 2 } } }");
            var folder = Path.Combine(_root, "planned");
            var plan = ToolTranscript.Run("plan", "--config", config, "--out", folder);
            Assert.That(plan.Succeeded, Is.True, string.Join("\n", plan.Lines));
            return folder;
        }

        static IEnumerator UntilDone()
        {
            for (var frames = 0; DatasetToolRunner.IsRunning && frames < 2000; frames++) yield return null;
            Assert.That(DatasetToolRunner.IsRunning, Is.False, "the command ended");
        }

        [UnityTest]
        public IEnumerator ConvertInTheEditorPrintsTheToolsLinesAndLogsThem()
        {
            var folder = Planned();
            var args = ConvertCommand.Arguments(folder, ExportTarget.Colmap);
            var expected = ToolTranscript.Run(args); // refused: a plan has no images
            Assume.That(expected.ExitCode, Is.EqualTo(ToolExitCodes.Failure));
            LogAssert.Expect(LogType.Error, new Regex("^NeRF Dataset Creator: nerf-dataset convert .* --to colmap \\(exit 1\\)"));

            Assert.That(DatasetToolRunner.Start("export for COLMAP", args), Is.True);
            Assert.That(DatasetToolRunner.Start("a second command", ValidateCommand.Arguments(folder)), Is.False, "one command at a time");
            yield return UntilDone();

            var last = DatasetToolRunner.Last;
            Assert.That(last.ExitCode, Is.EqualTo(ToolExitCodes.Failure));
            Assert.That(last.Errors, Is.EqualTo(expected.Errors), "the tool's messages, word for word");
            Assert.That(last.Errors, Does.Contain("this dataset was planned by nerf-dataset plan and has no images"));
            Assert.That(Directory.Exists(Path.Combine(folder, "colmap")), Is.False, "nothing written");
        }

        [UnityTest]
        public IEnumerator CleanInTheEditorSucceedsAndLogsAnInfoEntry()
        {
            Planned();
            LogAssert.Expect(LogType.Log, new Regex("^NeRF Dataset Creator: nerf-dataset clean .* --dry-run \\(exit 0\\)"));
            Assert.That(DatasetToolRunner.Start("clean --dry-run", CleanCommand.Arguments(_root, dryRun: true)), Is.True);
            yield return UntilDone();
            Assert.That(DatasetToolRunner.Last.Succeeded, Is.True);
            Assert.That(DatasetToolRunner.Last.Output, Does.StartWith("nothing to clean in "));
        }

        [UnityTest]
        public IEnumerator DemoInTheEditorWritesTheToolsCheckedDataset()
        {
            // The Demo button's command line, made small: the same command the tool runs, through the editor's runner.
            var folder = Path.Combine(_root, "demo");
            var button = DemoCommand.Arguments(folder, DemoPreset.Labels);
            Assert.That(button, Is.EqualTo(new[] { "demo", folder, "--preset", "labels" }));
            LogAssert.Expect(LogType.Log, new Regex("^NeRF Dataset Creator: nerf-dataset demo .* \\(exit 0\\)"));
            Assert.That(DatasetToolRunner.Start("demo", new[] { "demo", folder, "--preset", "labels", "--views", "4", "--size", "32" }), Is.True);
            yield return UntilDone();
            Assert.That(DatasetToolRunner.Last.Succeeded, Is.True, string.Join("\n", DatasetToolRunner.Last.Lines));
            Assert.That(DatasetToolRunner.Last.Output, Does.Contain("check: passed"));
            Assert.That(File.Exists(Path.Combine(folder, DatasetCheck.ReportFileName)), Is.True);
            Assert.That(File.Exists(Path.Combine(folder, DatasetLayout.LabelsFileName)), Is.True);
        }

        [UnityTest]
        public IEnumerator TheToolsWindowOpensOnAFolderAndDraws()
        {
            var window = DatasetToolsWindow.Open(_root);
            window.Repaint();
            yield return null;
            yield return null;
            window.Close();
        }
    }
}
