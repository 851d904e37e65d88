using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>`nerf-dataset` as a real command: packed, installed into a clean folder, run by name.</summary>
    [TestFixture]
    public class InstalledToolTests
    {
        [Test]
        public void TheInstalledCommandAnswersHelpAsTheToolDoes()
        {
            var run = InstalledTool.Run(InstalledTool.Path, "--help", System.IO.Path.GetTempPath());
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out.Replace("\r\n", "\n"), Is.EqualTo(ToolRun.Of("--help").Out));
            Assert.That(run.Out, Does.StartWith("usage: nerf-dataset <command>"));
            // A figure, not an assertion: how long one call of the installed command takes here.
            TestContext.Progress.WriteLine("nerf-dataset --help (installed tool): {0:0.000} s", run.Seconds);
        }

        [Test]
        public void TheInstalledCommandReportsAUsageErrorWithExit2()
        {
            var run = InstalledTool.Run(InstalledTool.Path, "frobnicate", System.IO.Path.GetTempPath());
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("frobnicate"));
            Assert.That(run.Err, Does.Not.Contain("   at "), "no stack trace");
        }
    }
}
