using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>
    /// A package installed from git is immutable: Unity ignores every file or folder without a committed .meta.
    /// These checks keep Assets/ (the plugin and the sample project) and the assembled upm tree importable.
    /// </summary>
    [TestFixture]
    public class MetaFileTests
    {
        static readonly string[] PackageRootFiles = { "package.json", "README.md", "CHANGELOG.md", "LICENSE" };

        static IEnumerable<string> AllRepositoryMetas() =>
            MetaFiles.MetaFilesBelow(RepositoryPaths.Combine("Assets"))
                .Concat(PackageRootFiles.Select(f => RepositoryPaths.Combine(f + ".meta")));

        [Test]
        public void EveryImportedFileAndFolderUnderAssetsHasAMeta()
        {
            var missing = MetaFiles.MissingMetas(RepositoryPaths.Combine("Assets"));
            Assert.That(missing, Is.Empty, "Run .ci/make-metas to create them:\n" + string.Join("\n", missing));
        }

        [Test]
        public void NoMetaUnderAssetsIsOrphaned()
        {
            Assert.That(MetaFiles.OrphanedMetas(RepositoryPaths.Combine("Assets")), Is.Empty);
        }

        [Test]
        public void EachPackageRootFileHasItsMeta([ValueSource(nameof(PackageRootFiles))] string file)
        {
            Assert.That(File.Exists(RepositoryPaths.Combine(file)), Is.True, file + " is missing");
            Assert.That(File.Exists(RepositoryPaths.Combine(file + ".meta")), Is.True, file + ".meta is missing");
        }

        [Test]
        public void EveryGuidIs32LowercaseHexDigits()
        {
            var bad = AllRepositoryMetas().Where(m => !MetaFiles.IsValidGuid(MetaFiles.GuidOf(m))).ToList();
            Assert.That(bad, Is.Empty);
        }

        [Test]
        public void EveryGuidIsUnique()
        {
            var duplicates = AllRepositoryMetas()
                .GroupBy(MetaFiles.GuidOf)
                .Where(g => g.Count() > 1)
                .Select(g => g.Key + ": " + string.Join(", ", g))
                .ToList();
            Assert.That(duplicates, Is.Empty);
        }

        [Test]
        public void EveryMetaStartsWithFileFormatVersion2()
        {
            var bad = AllRepositoryMetas().Where(m => !File.ReadAllText(m).StartsWith("fileFormatVersion: 2\n", StringComparison.Ordinal)).ToList();
            Assert.That(bad, Is.Empty);
        }

        [Test]
        public void FolderMetasDeclareAFolderAsset()
        {
            var bad = AllRepositoryMetas()
                .Where(m => Directory.Exists(m.Substring(0, m.Length - 5)))
                .Where(m => !File.ReadAllText(m).Contains("folderAsset: yes"))
                .ToList();
            Assert.That(bad, Is.Empty);
        }

        [Test]
        public void TheUpmTreeIsAPackageWithAMetaForEverything()
        {
            var tree = Path.Combine(Path.GetTempPath(), "nerf-upm-" + Guid.NewGuid().ToString("N"));
            try
            {
                RunAssembleScript(tree);
                Assert.That(File.Exists(Path.Combine(tree, "package.json")), Is.True);
                foreach (var projectFolder in new[] { "Assets", "Packages", "ProjectSettings", "Tests" + Path.DirectorySeparatorChar + "Core.Tests" })
                    Assert.That(Directory.Exists(Path.Combine(tree, projectFolder)), Is.False, projectFolder + " must not be in the package");
                Assert.That(MetaFiles.MissingMetas(tree), Is.Empty);
                Assert.That(MetaFiles.OrphanedMetas(tree), Is.Empty);
                Assert.That(File.Exists(Path.Combine(tree, "package.json.meta")), Is.True);
                Assert.That(Directory.Exists(Path.Combine(tree, "Core")), Is.True, "the plugin's Core folder sits at the package root");
                // The sample is imported by Package Manager into Assets/, so it needs its .metas too.
                var sample = Path.Combine(tree, "Samples~", "NeRFSample");
                Assert.That(File.Exists(Path.Combine(sample, "NeRFSample.unity")), Is.True);
                Assert.That(MetaFiles.MissingMetas(sample), Is.Empty);
                var declared = Newtonsoft.Json.Linq.JObject.Parse(File.ReadAllText(Path.Combine(tree, "package.json")))["samples"][0]["path"];
                Assert.That(Directory.Exists(Path.Combine(tree, (string)declared)), Is.True, "package.json's sample path exists in the package");
            }
            finally
            {
                if (Directory.Exists(tree)) Directory.Delete(tree, true);
            }
        }

        static void RunAssembleScript(string outDir)
        {
            var start = new ProcessStartInfo("bash", "\"" + RepositoryPaths.Combine(".ci", "assemble-upm") + "\" \"" + outDir + "\"")
            {
                RedirectStandardOutput = true,
                RedirectStandardError = true,
                UseShellExecute = false,
            };
            using var process = Process.Start(start);
            var stderr = process.StandardError.ReadToEnd();
            process.StandardOutput.ReadToEnd();
            process.WaitForExit();
            Assert.That(process.ExitCode, Is.EqualTo(0), "assemble-upm failed: " + stderr);
        }
    }
}
