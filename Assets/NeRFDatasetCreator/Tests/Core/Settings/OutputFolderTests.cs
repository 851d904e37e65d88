using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class OutputFolderTests
    {
        TempFolder _temp;
        string _project;

        [SetUp]
        public void SetUp()
        {
            _temp = new TempFolder();
            _project = _temp.Combine("MyProject");
            Directory.CreateDirectory(Path.Combine(_project, "Assets"));
            Directory.CreateDirectory(Path.Combine(_project, "ProjectSettings"));
        }

        [TearDown]
        public void TearDown() => _temp.Dispose();

        string[] Fields(string folder, OverwritePolicy policy = OverwritePolicy.Never, string projectRoot = null) =>
            SafeOutput.CheckOutputFolder(folder, projectRoot ?? _project, policy).Select(p => p.Field).ToArray();

        [Test]
        public void DefaultFolderIsNeRFDatasetsBesideAssets()
        {
            var folder = SafeOutput.ResolveOutputFolder(new DatasetSettings { Name = "lego" }, _project);
            Assert.That(folder, Is.EqualTo(Path.Combine(_project, "NeRFDatasets", "lego")));
            Assert.That(Fields(folder), Is.Empty);
        }

        [Test]
        public void RelativeOutputFolderIsRelativeToTheProject()
        {
            var folder = SafeOutput.ResolveOutputFolder(new DatasetSettings { Name = "lego", OutputFolder = "../data" }, _project);
            Assert.That(folder, Is.EqualTo(_temp.Combine("data", "lego")));
        }

        [Test]
        public void FolderInsideAssetsIsRefused()
        {
            var problems = SafeOutput.CheckOutputFolder(Path.Combine(_project, "Assets", "Datasets", "lego"), _project, OverwritePolicy.Never);
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "outputFolder" }));
            Assert.That(problems[0].Fix, Does.Contain("~"));
        }

        [TestCase("assets")]
        [TestCase("ASSETS")]
        public void FolderInsideAssetsSpelledInAnotherCaseIsRefused(string spelling)
        {
            // On Windows and macOS (case-insensitive file systems) this is Unity's Assets folder.
            var problems = SafeOutput.CheckOutputFolder(Path.Combine(_project, spelling, "lego"), _project, OverwritePolicy.Never);
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "outputFolder" }));
        }

        [Test]
        public void FolderInsideAssetsIsRecognisedWithoutAProjectRoot()
        {
            var problems = SafeOutput.CheckOutputFolder(Path.Combine(_project, "Assets", "lego"), null, OverwritePolicy.Never);
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "outputFolder" }));
        }

        [TestCase("Datasets~", "lego")]
        [TestCase("Datasets", "lego~")]
        public void FolderInsideAssetsUnderATildeComponentIsAllowed(string parent, string name)
        {
            Assert.That(Fields(Path.Combine(_project, "Assets", parent, name)), Is.Empty);
        }

        [Test]
        public void AnAssetsFolderOutsideAUnityProjectIsJustAFolder()
        {
            Assert.That(Fields(_temp.Combine("Other", "Assets", "lego"), projectRoot: _project), Is.Empty);
        }

        [Test]
        public void FolderInsideAnExistingDatasetIsRefused()
        {
            var outer = _temp.Combine("outer");
            Directory.CreateDirectory(outer);
            File.WriteAllText(Path.Combine(outer, "transforms_train.json"), "{}");
            var problems = SafeOutput.CheckOutputFolder(Path.Combine(outer, "train", "inner"), _project, OverwritePolicy.Replace);
            Assert.That(problems.Select(p => p.Reason).Single(), Does.Contain("inside the existing dataset"));
        }

        [Test]
        public void ExistingDatasetNeedsTheReplacePolicy()
        {
            var folder = _temp.Combine("lego");
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, "transforms_test.json"), "{}");
            File.WriteAllText(Path.Combine(folder, "dataset_config.json"), "{ \"generator\": \"" + PluginInfo.Name + "\" }");
            Assert.That(Fields(folder), Is.EqualTo(new[] { "overwrite" }));
            Assert.That(Fields(folder, OverwritePolicy.Replace), Is.Empty);
        }

        [Test]
        public void ReplaceRefusesAFolderNothingProvesThisPluginWrote()
        {
            // The hostile-user case: one stray transforms file among the user's own files.
            var folder = _temp.Combine("mine");
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, "transforms_train.json"), "{}");
            File.WriteAllText(Path.Combine(folder, "thesis.tex"), "precious");
            var problem = SafeOutput.CheckOutputFolder(folder, _project, OverwritePolicy.Replace).Single();
            Assert.That(problem.Field, Is.EqualTo("overwrite"));
            Assert.That(problem.Reason, Does.Contain("no dataset_config.json"));
        }

        [Test]
        public void ReplaceRefusesOurDatasetHoldingAFileItDidNotWrite()
        {
            var folder = _temp.Combine("lego");
            Directory.CreateDirectory(Path.Combine(folder, "train"));
            File.WriteAllText(Path.Combine(folder, "dataset_config.json"), "{ \"generator\": \"" + PluginInfo.Name + "\" }");
            File.WriteAllText(Path.Combine(folder, "train", "r_0.png"), "x");
            Assert.That(Fields(folder, OverwritePolicy.Replace), Is.Empty, "only files the plugin writes");
            File.WriteAllText(Path.Combine(folder, "train", "notes.txt"), "mine");
            var problem = SafeOutput.CheckOutputFolder(folder, _project, OverwritePolicy.Replace).Single();
            Assert.That(problem.Reason, Does.Contain(Path.Combine(folder, "train", "notes.txt")).And.Contain("was not written by this plugin"));
        }

        [Test]
        public void ANameTooLongForTheWorkingFolderIsRefusedUpFrontNamingTheField()
        {
            // 230 bytes is a legal name, but "<name>.partial-yyyyMMdd-HHmmss-xxxxxxxx~" is not.
            var folder = _temp.Combine(new string('n', 230));
            var problem = SafeOutput.CheckOutputFolder(folder, _project, OverwritePolicy.Never).Single();
            Assert.That(problem.Field, Is.EqualTo("name"));
            Assert.That(problem.Reason, Does.Contain("230 bytes"));
            Assert.Throws<InvalidParameterException>(() => DatasetWriteSession.Begin(folder, OverwritePolicy.Never));
            Assert.That(Directory.GetFileSystemEntries(_temp.Path).Where(e => e.Contains("nnnn")), Is.Empty, "nothing was created");
        }

        [Test]
        public void AMountPointIsRefusedWithTheFolderToUseInstead()
        {
            const string mount = "/dev/shm";
            Assume.That(MountPoints.IsMountPoint(mount), Is.True, "needs a Linux mount point");
            var problem = SafeOutput.CheckOutputFolder(mount, _project, OverwritePolicy.Replace).First(p => p.Reason.Contains("mount point"));
            Assert.That(problem.Field, Is.EqualTo("outputFolder"));
            Assert.That(problem.Fix, Does.Contain(Path.Combine(mount, "dataset")));
        }

        [Test]
        public void FolderWithOtherFilesIsNeverReplaced()
        {
            var folder = _temp.Combine("photos");
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, "holiday.jpg"), "x");
            var problems = SafeOutput.CheckOutputFolder(folder, _project, OverwritePolicy.Replace);
            Assert.That(problems.Select(p => p.Reason).Single(), Does.Contain("not a dataset"));
        }

        [Test]
        public void EmptyExistingFolderIsFine()
        {
            var folder = _temp.Combine("empty");
            Directory.CreateDirectory(folder);
            Assert.That(Fields(folder), Is.Empty);
        }

        [Test]
        public void FolderUnderAFileIsNotWritable()
        {
            File.WriteAllText(_temp.Combine("afile"), "x");
            var problems = SafeOutput.CheckOutputFolder(_temp.Combine("afile", "lego"), _project, OverwritePolicy.Never);
            Assert.That(problems.Select(p => p.Reason).Single(), Does.Contain("is a file"));
        }

        [Test]
        public void ValidateWithAProjectRootChecksTheFolder()
        {
            var s = new DatasetSettings { Name = "lego", OutputFolder = "Assets" };
            Assert.That(SettingsValidator.Validate(s, _project).Select(p => p.Field), Is.EqualTo(new[] { "outputFolder" }));
            Assert.That(SettingsValidator.Validate(new DatasetSettings { Name = "lego" }, _project), Is.Empty);
        }
    }
}
