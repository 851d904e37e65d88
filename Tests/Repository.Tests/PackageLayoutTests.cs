using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Formats.Tar;
using System.IO;
using System.IO.Compression;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>
    /// The two installs that work before the repository is published (README, Install): Package Manager ▸ Add package
    /// from disk… on the folder <c>.ci/assemble-upm</c> writes, and ▸ Add package from tarball… on the <c>.tgz</c>
    /// <c>.ci/pack-upm</c> writes. Both are built here from the scripts and checked as Unity would see them: the package
    /// root is the package (package.json at its root; for the tarball, npm's layout with everything under
    /// <c>package/</c>), every file and folder Unity imports has its .meta, GUIDs are unique, no build output.
    /// </summary>
    [TestFixture]
    public class PackageLayoutTests
    {
        string _scratch, _folder, _extracted, _tarball;

        [OneTimeSetUp]
        public void BuildBothLayouts()
        {
            _scratch = Path.Combine(Path.GetTempPath(), "nerf-upm-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_scratch);
            _folder = Path.Combine(_scratch, "from-disk");
            Script("assemble-upm", _folder);
            var packed = Script("pack-upm", Path.Combine(_scratch, "tarball")).Trim();
            _tarball = packed;
            // Extracted with .NET's own gzip and tar readers, not with the tar that wrote it.
            _extracted = Path.Combine(_scratch, "extracted");
            Directory.CreateDirectory(_extracted);
            using (var file = File.OpenRead(_tarball))
            using (var gzip = new GZipStream(file, CompressionMode.Decompress))
                TarFile.ExtractToDirectory(gzip, _extracted, overwriteFiles: false);
        }

        [OneTimeTearDown]
        public void DeleteScratch()
        {
            if (_scratch != null && Directory.Exists(_scratch)) Directory.Delete(_scratch, true);
        }

        /// <summary>The package folder of each layout: the assembled folder itself, the tarball's <c>package/</c>.</summary>
        string PackageRoot(string layout) => layout == "folder" ? _folder : Path.Combine(_extracted, "package");

        static readonly string[] Layouts = { "folder", "tarball" };

        [Test]
        public void TheTarballIsNamedAsNpmPackNamesIt_AndHoldsOnlyThePackageFolder()
        {
            var manifest = JObject.Parse(File.ReadAllText(RepositoryPaths.Combine("package.json")));
            Assert.That(Path.GetFileName(_tarball), Is.EqualTo((string)manifest["name"] + "-" + (string)manifest["version"] + ".tgz"));
            Assert.That(Directory.EnumerateFileSystemEntries(_extracted).Select(Path.GetFileName), Is.EqualTo(new[] { "package" }));
            Assert.That(File.Exists(Path.Combine(_extracted, "package", "package.json")), Is.True);
        }

        [Test]
        public void TheTarballHoldsExactlyTheFromDiskFolder()
        {
            Assert.That(RelativeFiles(PackageRoot("tarball")), Is.EqualTo(RelativeFiles(_folder)));
            foreach (var file in RelativeFiles(_folder))
                Assert.That(File.ReadAllBytes(Path.Combine(PackageRoot("tarball"), file)), Is.EqualTo(File.ReadAllBytes(Path.Combine(_folder, file))), file);
        }

        [TestCaseSource(nameof(Layouts))]
        public void ThePackageRootIsThePackage(string layout)
        {
            var root = PackageRoot(layout);
            var manifest = JObject.Parse(File.ReadAllText(Path.Combine(root, "package.json")));
            Assert.That((string)manifest["name"], Is.EqualTo("com.nerfdatasetcreator.plugin"));
            foreach (var folder in new[] { "Core", "Editor", "Shaders", "Tests", "Tools~", "Documentation~" })
                Assert.That(Directory.Exists(Path.Combine(root, folder)), Is.True, folder + " at the package root");
            // A project folder inside a package is what Unity warns about and ignores; none may leak in.
            foreach (var projectFolder in new[] { "Assets", "Packages", "ProjectSettings", "UserSettings", "Library", ".ci", ".github" })
                Assert.That(Directory.Exists(Path.Combine(root, projectFolder)), Is.False, projectFolder + " must not be in the package");
            Assert.That(Directory.Exists(Path.Combine(root, "Tests", "Core.Tests")), Is.False, "the .NET solution's Tests/ must not be in the package");
            var sample = (string)manifest["samples"][0]["path"];
            Assert.That(File.Exists(Path.Combine(root, sample, "NeRFSample.unity")), Is.True, "package.json's sample path holds the sample scene");
        }

        [TestCaseSource(nameof(Layouts))]
        public void EveryFileAndFolderUnityImportsHasItsMeta(string layout)
        {
            var root = PackageRoot(layout);
            Assert.That(MetaFiles.MissingMetas(root).Select(p => Path.GetRelativePath(root, p)), Is.Empty);
            Assert.That(MetaFiles.OrphanedMetas(root).Select(p => Path.GetRelativePath(root, p)), Is.Empty);
            // Package Manager copies the sample into the user's Assets/, where it is imported too.
            var sample = Path.Combine(root, "Samples~", "NeRFSample");
            Assert.That(MetaFiles.MissingMetas(sample).Select(p => Path.GetRelativePath(root, p)), Is.Empty);
            Assert.That(MetaFiles.ImportedEntries(root).Count(), Is.GreaterThan(100), "the walk saw the plugin");
        }

        [TestCaseSource(nameof(Layouts))]
        public void EveryGuidIsValidAndUnique(string layout)
        {
            var root = PackageRoot(layout);
            var metas = MetaFiles.MetaFilesBelow(root).Concat(MetaFiles.MetaFilesBelow(Path.Combine(root, "Samples~", "NeRFSample"))).ToList();
            var guids = metas.Select(m => (Meta: Path.GetRelativePath(root, m), Guid: MetaFiles.GuidOf(m))).ToList();
            Assert.That(guids.Where(g => !MetaFiles.IsValidGuid(g.Guid)).Select(g => g.Meta), Is.Empty);
            var duplicates = guids.GroupBy(g => g.Guid).Where(g => g.Count() > 1).Select(g => g.Key + ": " + string.Join(", ", g.Select(x => x.Meta)));
            Assert.That(duplicates, Is.Empty);
        }

        [TestCaseSource(nameof(Layouts))]
        public void NoBuildOutputShips(string layout)
        {
            var root = PackageRoot(layout);
            var buildFolders = Directory.EnumerateDirectories(root, "*", SearchOption.AllDirectories)
                .Where(d => Path.GetFileName(d) == "bin" || Path.GetFileName(d) == "obj")
                .Select(d => Path.GetRelativePath(root, d));
            Assert.That(buildFolders, Is.Empty);
            Assert.That(Directory.EnumerateFiles(root, "*.nupkg", SearchOption.AllDirectories), Is.Empty);
            // The tool ships as source, which `dotnet pack` / `dotnet run` build on the user's machine.
            Assert.That(File.Exists(Path.Combine(root, "Tools~", "nerf-dataset", "nerf-dataset.csproj")), Is.True);
        }

        static List<string> RelativeFiles(string root) =>
            Directory.EnumerateFiles(root, "*", SearchOption.AllDirectories)
                .Select(f => Path.GetRelativePath(root, f).Replace('\\', '/'))
                .OrderBy(f => f, StringComparer.Ordinal).ToList();

        static string Script(string name, string argument)
        {
            var start = new ProcessStartInfo("bash") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            start.ArgumentList.Add(RepositoryPaths.Combine(".ci", name));
            start.ArgumentList.Add(argument);
            using var process = Process.Start(start);
            var stderr = process.StandardError.ReadToEndAsync();
            var stdout = process.StandardOutput.ReadToEnd();
            process.WaitForExit();
            Assert.That(process.ExitCode, Is.EqualTo(0), name + " failed: " + stderr.Result);
            return stdout;
        }
    }
}
