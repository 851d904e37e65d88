using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>Issue 23: the tool's messages name what the user typed (--out, a number for distance), not our internals.</summary>
    [TestFixture]
    public class MessageNameTests
    {
        Scratch _scratch;

        [SetUp]
        public void SetUp() => _scratch = new Scratch();

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        [Test]
        public void OutInsideAssetsIsReportedAsOut()
        {
            Directory.CreateDirectory(_scratch.PathOf("project", "Assets"));
            Directory.CreateDirectory(_scratch.PathOf("project", "ProjectSettings"));
            var config = _scratch.WriteText("c.json", "{}");
            var run = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("project", "Assets", "lego"));
            Assert.That(run.ExitCode, Is.EqualTo(Program.UsageError), run.ToString());
            Assert.That(run.Err, Does.StartWith("error: --out = " + _scratch.PathOf("project", "Assets", "lego") + ": is inside the Unity project's Assets folder"));
            Assert.That(run.Err, Does.Not.Contain("outputFolder"));
        }

        [Test]
        public void ASecondConvertNamesTheOutputNotOutDir()
        {
            var dataset = RenderedDataset.Create(_scratch, "ds");
            Assert.That(ToolRun.Of("convert", dataset, "--to", "nerfstudio").ExitCode, Is.EqualTo(Program.Success));
            var again = ToolRun.Of("convert", dataset, "--to", "nerfstudio");
            Assert.That(again.ExitCode, Is.EqualTo(Program.Failure), again.ToString());
            Assert.That(again.Err, Does.Contain("error: output = "));
            Assert.That(again.Err, Does.Contain("(--out <folder>)"));
            Assert.That(again.Err, Does.Not.Contain("outDir"));
        }

        [Test]
        public void AutoDistanceInTheToolAsksForANumber()
        {
            var config = _scratch.WriteText("c.json", "{ \"distance\": \"auto\" }");
            var run = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("out"));
            Assert.That(run.ExitCode, Is.EqualTo(Program.UsageError));
            Assert.That(run.Err, Does.Contain("distance = \"auto\": needs the target's bounds, which only Unity measures"));
            Assert.That(run.Err, Does.Not.Contain("renderers"));
        }

        [Test]
        public void AFolderAsConfigAndEveryTypeErrorAreOneLineEach()
        {
            Directory.CreateDirectory(_scratch.PathOf("configs"));
            var folder = ToolRun.Of("plan", "--config", _scratch.PathOf("configs"), "--out", _scratch.PathOf("out"));
            Assert.That(folder.ExitCode, Is.EqualTo(Program.UsageError));
            Assert.That(folder.Err, Does.StartWith("error: " + _scratch.PathOf("configs") + ": is a folder, not a config file."));

            var config = _scratch.WriteText("t.json", "{\n  \"width\": \"400\",\n  \"seed\": \"x\"\n}");
            var types = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("out"));
            Assert.That(types.Err.TrimEnd().Split('\n'), Is.EqualTo(new[]
            {
                "error: " + config + "(2,16): width: must be a whole number, not \"400\".",
                "error: " + config + "(3,13): seed: must be a whole number, not \"x\".",
            }));
        }

        [Test]
        public void AMisspelledExportFormatIsMatched()
        {
            var run = ToolRun.Of("convert", _scratch.Root, "--to", "colmp");
            Assert.That(run.ExitCode, Is.EqualTo(Program.UsageError));
            Assert.That(run.Err, Does.Contain("Did you mean \"colmap\"?"));
        }
    }
}
