using System;
using System.Collections.Generic;
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
    }
}
