using System.IO;
using System.Linq;
using System.Reflection;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// Per-command help, usage errors that print only the command's usage, and <c>--version</c> from package.json
    /// (issue 33: "no --version or per-command help (every usage error prints the whole usage)"; "dotnet tool update
    /// keeps the old build because the version is always 0.1.0").
    /// </summary>
    [TestFixture]
    public class HelpAndVersionTests
    {
        static string PackageVersion =>
            (string)JObject.Parse(File.ReadAllText(Path.Combine(InstalledTool.RepositoryRoot, "package.json")))["version"];

        [Test]
        public void ACommandsHelpPrintsOnlyThatCommandsUsageAndOptions()
        {
            var run = ToolRun.Of("check", "--help");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var lines = run.Out.TrimEnd('\n').Split('\n');
            Assert.That(lines[0], Is.EqualTo("usage: nerf-dataset check <dir> [--split S] [--json FILE] [--max-views N] [--model <dir>]"));
            Assert.That(lines, Has.Some.StartWith("  --split S "));
            Assert.That(lines, Has.Some.StartWith("  --json FILE "));
            Assert.That(lines, Has.Some.StartWith("  --max-views N "));
            Assert.That(run.Out, Does.Not.Contain("plan --config").And.Not.Contain("evaluate <dir>"));
            Assert.That(ToolRun.Of("help", "check").Out, Is.EqualTo(run.Out), "help check = check --help");
            Assert.That(ToolRun.Of("check", "somewhere", "--help").Out, Is.EqualTo(run.Out), "--help anywhere after the command");
        }

        [Test]
        public void AUsageMistakePrintsTheErrorAndOnlyThatCommandsUsage()
        {
            var run = ToolRun.Of("convert", "ds");
            Assert.That(run.ExitCode, Is.EqualTo(2));
            var lines = run.Err.TrimEnd('\n').Split('\n');
            Assert.That(lines[0], Does.StartWith("error: convert needs --to "));
            Assert.That(lines[1], Does.StartWith("usage: nerf-dataset convert <dir> --to "));
            Assert.That(run.Err, Does.Contain("  --to <format> ").And.Not.Contain("plan --config").And.Not.Contain("check <dir>"));
        }

        [Test]
        public void AnUnknownCommandPrintsTheWholeTableAndTheNearestCommand()
        {
            var run = ToolRun.Of("evalute", "ds");
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Err, Does.StartWith("error: unknown command 'evalute'. Did you mean \"evaluate\"?\nusage: nerf-dataset <command> [arguments]\n"));
        }

        [Test]
        public void VersionIsPackageJsonsAndSoIsTheToolAssemblys()
        {
            var run = ToolRun.Of("--version");
            Assert.That(run.ExitCode, Is.EqualTo(0));
            Assert.That(run.Out, Is.EqualTo("nerf-dataset " + PackageVersion + "\n"));
            // The csproj reads its <Version> from package.json: the built assembly carries it, so a bump reaches dotnet tool update.
            var assembly = typeof(Program).Assembly;
            Assert.That(assembly.GetName().Version.ToString(3), Is.EqualTo(PackageVersion));
            Assert.That(assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>().InformationalVersion.Split('+')[0], Is.EqualTo(PackageVersion));
        }

        [Test]
        public void TheInstalledCommandPrintsPackageJsonsVersion()
        {
            var run = InstalledTool.Run(InstalledTool.Path, "--version", Path.GetTempPath());
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out.Replace("\r\n", "\n"), Is.EqualTo("nerf-dataset " + PackageVersion + "\n"));
            Assert.That(InstalledTool.PackedPackage, Does.EndWith("NerfDatasetCreator.Tool." + PackageVersion + ".nupkg"), "the package dotnet tool update compares");
        }
    }
}
