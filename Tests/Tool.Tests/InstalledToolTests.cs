using System;
using System.IO;
using System.IO.Compression;
using System.Linq;
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
        public void TheToolPacksFromAnInstalledPackage_WhichHasNoTestsFolder()
        {
            // In a user's project the package has no Tests/Core project: the csproj compiles ../../Core/**/*.cs itself.
            var root = Path.Combine(Path.GetTempPath(), "nerf-package-pack-" + Guid.NewGuid().ToString("N"));
            try
            {
                Directory.CreateDirectory(root);
                var package = Path.Combine(root, "package");
                var assemble = InstalledTool.Run("bash", "\"" + Path.Combine(InstalledTool.RepositoryRoot, ".ci", "assemble-upm") + "\" \"" + package + "\"", root);
                Assert.That(assemble.ExitCode, Is.EqualTo(0), assemble.ToString());
                Assert.That(Directory.Exists(Path.Combine(package, "Tests", "Core")), Is.True, "the package's Unity tests");
                // Where the csproj looks for the repository's Core project (four folders up from Tools~/nerf-dataset).
                Assert.That(File.Exists(Path.Combine(package, "..", "..", "Tests", "Core", "NerfDatasetCreator.Core.csproj")), Is.False);

                var feed = Path.Combine(root, "feed");
                var pack = InstalledTool.Run("dotnet", "pack \"" + Path.Combine(package, "Tools~", "nerf-dataset") + "\" -o \"" + feed + "\" --nologo", root);
                Assert.That(pack.ExitCode, Is.EqualTo(0), pack.ToString());
                var nupkg = Directory.GetFiles(feed, "NerfDatasetCreator.Tool.*.nupkg").Single();
                // The installed package's csproj reads package.json two folders up, the package root's.
                var version = (string)Newtonsoft.Json.Linq.JObject.Parse(File.ReadAllText(Path.Combine(package, "package.json")))["version"];
                Assert.That(Path.GetFileName(nupkg), Is.EqualTo("NerfDatasetCreator.Tool." + version + ".nupkg"));
                using var zip = ZipFile.OpenRead(nupkg);
                var names = zip.Entries.Select(e => e.FullName).ToList();
                Assert.That(names, Does.Contain("tools/net10.0/any/nerf-dataset.dll").And.Contain("tools/net10.0/any/DotnetToolSettings.xml").And.Contain("tools/net10.0/any/Newtonsoft.Json.dll"));
                Assert.That(names, Does.Not.Contain("tools/net10.0/any/NerfDatasetCreator.Core.dll"), "Core compiled into the tool, not referenced");
            }
            finally
            {
                if (Directory.Exists(root)) Directory.Delete(root, true);
            }
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
