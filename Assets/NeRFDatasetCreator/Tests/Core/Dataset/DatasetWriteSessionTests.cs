using System;
using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class DatasetWriteSessionTests
    {
        TempFolder _temp;
        string _final;

        [SetUp]
        public void SetUp()
        {
            _temp = new TempFolder();
            _final = _temp.Combine("datasets", "lego");
        }

        [TearDown]
        public void TearDown() => _temp.Dispose();

        [Test]
        public void FilesGoToATildeSiblingUntilCommit()
        {
            var session = DatasetWriteSession.Begin(_final, OverwritePolicy.Never);
            session.WriteText("train/note.txt", "x");
            Assert.That(Path.GetDirectoryName(session.WorkingFolder), Is.EqualTo(Path.GetDirectoryName(_final)));
            Assert.That(session.WorkingFolder, Does.EndWith("~"), "Unity ignores it even under Assets");
            Assert.That(Path.GetFileName(session.WorkingFolder), Does.StartWith("lego.partial-"));
            Assert.That(Directory.Exists(_final), Is.False, "nothing under the final name before the run is complete");
            session.Commit();
            Assert.That(File.ReadAllText(Path.Combine(_final, "train", "note.txt")), Is.EqualTo("x"));
            Assert.That(Directory.Exists(session.WorkingFolder), Is.False);
            Assert.That(session.PartialFolder, Is.Null);
        }

        [Test]
        public void AnUnfinishedRunLeavesNothingUnderTheFinalNameAndSaysWhereItsFilesAre()
        {
            var session = DatasetWriteSession.Begin(_final, OverwritePolicy.Never);
            session.WriteText("train/r_0.png", "partial");
            // The run is cancelled here: no Commit.
            Assert.That(Directory.Exists(_final), Is.False);
            Assert.That(session.PartialFolder, Is.EqualTo(session.WorkingFolder));
            Assert.That(session.DescribeAbandoned(), Does.Contain(session.WorkingFolder).And.Contain("nothing was written to " + _final));
            Assert.That(File.Exists(Path.Combine(session.WorkingFolder, "train", "r_0.png")), Is.True, "partial files are kept to inspect");
            session.DiscardPartialFiles();
            Assert.That(Directory.Exists(session.WorkingFolder), Is.False);
        }

        [Test]
        public void AnExistingDatasetIsRefusedUnderNever()
        {
            Directory.CreateDirectory(_final);
            File.WriteAllText(Path.Combine(_final, "transforms_train.json"), "old");
            var e = Assert.Throws<InvalidParameterException>(() => DatasetWriteSession.Begin(_final, OverwritePolicy.Never));
            Assert.That(e.Problems[0].Field, Is.EqualTo("overwrite"));
            Assert.That(File.ReadAllText(Path.Combine(_final, "transforms_train.json")), Is.EqualTo("old"));
        }

        [Test]
        public void ReplaceSwapsTheDatasetOnlyWhenTheNewOneIsComplete()
        {
            Directory.CreateDirectory(Path.Combine(_final, "train"));
            File.WriteAllText(Path.Combine(_final, "dataset_config.json"), "{ \"generator\": \"" + PluginInfo.Name + "\" }");
            File.WriteAllText(Path.Combine(_final, "transforms_train.json"), "old");
            File.WriteAllText(Path.Combine(_final, "train", "r_99.png"), "stale");
            var session = DatasetWriteSession.Begin(_final, OverwritePolicy.Replace);
            session.WriteText("transforms_train.json", "new");
            Assert.That(File.ReadAllText(Path.Combine(_final, "transforms_train.json")), Is.EqualTo("old"), "untouched until commit");
            session.Commit();
            Assert.That(File.ReadAllText(Path.Combine(_final, "transforms_train.json")), Is.EqualTo("new"));
            Assert.That(File.Exists(Path.Combine(_final, "train", "r_99.png")), Is.False, "no stale image survives (never appended)");
            Assert.That(Directory.GetDirectories(Path.GetDirectoryName(_final)), Is.EqualTo(new[] { _final }), "no leftovers beside it");
        }

        [Test]
        public void AFolderThatAppearedDuringTheRunIsNotOverwritten()
        {
            var session = DatasetWriteSession.Begin(_final, OverwritePolicy.Never);
            session.WriteText("transforms_train.json", "new");
            Directory.CreateDirectory(_final);
            File.WriteAllText(Path.Combine(_final, "mine.txt"), "someone else's");
            Assert.Throws<IOException>(() => session.Commit());
            Assert.That(File.ReadAllText(Path.Combine(_final, "mine.txt")), Is.EqualTo("someone else's"));
            Assert.That(File.Exists(Path.Combine(session.WorkingFolder, "transforms_train.json")), Is.True);
        }

        [TestCase("../escape.txt")]
        [TestCase("train/../../escape.txt")]
        public void PathsCannotLeaveTheDataset(string relative)
        {
            var session = DatasetWriteSession.Begin(_final, OverwritePolicy.Never);
            Assert.Throws<ArgumentException>(() => session.PathOf(relative));
        }

        [Test]
        public void CommitTwiceIsAnError()
        {
            var session = DatasetWriteSession.Begin(_final, OverwritePolicy.Never);
            session.Commit();
            Assert.Throws<InvalidOperationException>(() => session.Commit());
        }
    }
}
