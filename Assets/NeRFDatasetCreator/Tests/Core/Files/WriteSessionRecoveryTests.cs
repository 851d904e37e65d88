using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The write session every capture and plan uses, stopped (as by a crash of the Editor) before each file operation of
    /// a replace: the next session on the same folder finishes or rolls it back, and the old or the new dataset is
    /// always complete under its name afterwards. Runs in Unity's Test Runner too.
    /// </summary>
    [TestFixture]
    // Sets FileOps.Faults, which every file operation of the process sees: never beside another fixture (dotnet runs
    // fixtures side by side, Tests/Core.Tests/ParallelFixtures.cs).
    [Parallelizable(ParallelScope.None)]
    public class WriteSessionRecoveryTests
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
        public void TearDown()
        {
            FileOps.Faults = null;
            _temp.Dispose();
        }

        void Write(string version)
        {
            var session = DatasetWriteSession.Begin(_final, OverwritePolicy.Replace);
            session.WriteText(DatasetLayout.ConfigFileName, "{ \"generator\": \"" + PluginInfo.Name + "\", \"v\": \"" + version + "\" }");
            session.WriteText("transforms_train.json", version);
            session.Commit();
        }

        string Version() => File.ReadAllText(Path.Combine(_final, "transforms_train.json"));

        [Test]
        public void AReplaceStoppedAtAnyStepIsFinishedOrLeftIntactByTheNextSession()
        {
            Write("old");
            var counting = FileFaultPlan.Counting();
            FileOps.Faults = counting;
            Write("new");
            FileOps.Faults = null;
            var steps = counting.Count;
            Assert.That(steps, Is.GreaterThan(8));

            for (var step = 1; step <= steps; step++)
            {
                Directory.Delete(_temp.Combine("datasets"), true);
                Write("old");
                FileOps.Faults = FileFaultPlan.StoppingAt(step);
                Assert.Throws<SimulatedStopException>(() => Write("new"), "step " + step);
                FileOps.Faults = null;

                var next = DatasetWriteSession.Begin(_final, OverwritePolicy.Replace);
                Assert.That(Version(), Is.EqualTo("old").Or.EqualTo("new"), "step " + step + ": a complete dataset is in place");
                var finished = next.Recovered.Any(n => n.Finished);
                if (finished) Assert.That(Version(), Is.EqualTo("new"), "step " + step);
                Assert.That(Directory.GetDirectories(_temp.Combine("datasets"), "lego.replaced-*"), Is.Empty, "step " + step);
                Assert.That(File.Exists(Path.Combine(_final, OperationJournal.FileName)), Is.False, "step " + step);
                Assert.That(next.Leftovers.All(l => l.Kind == "write"), Is.True, "step " + step + ": only a partial write is left over, and reported");
                next.DiscardPartialFiles();
            }
        }

        [Test]
        public void ADatasetMovedAsideWithoutAJournalIsRestored()
        {
            Write("old");
            Directory.Move(_final, _final + ".replaced-0123abcd~");
            var next = DatasetWriteSession.Begin(_final, OverwritePolicy.Replace);
            Assert.That(next.Recovered.Single().Text, Does.StartWith("rolled back an interrupted replace of " + _final));
            Assert.That(Version(), Is.EqualTo("old"));
            next.DiscardPartialFiles();
        }

        [Test]
        public void AFailedMoveIntoPlacePutsTheOldDatasetBack()
        {
            Write("old");
            var session = DatasetWriteSession.Begin(_final, OverwritePolicy.Replace);
            session.WriteText(DatasetLayout.ConfigFileName, "{ \"generator\": \"" + PluginInfo.Name + "\" }");
            FileOps.Faults = FileFaultPlan.FailingAt(1, (op, path) => new IOException("Device or resource busy"), path => path == session.WorkingFolder);
            Assert.Throws<IOException>(() => session.Commit());
            FileOps.Faults = null;
            Assert.That(Version(), Is.EqualTo("old"));
            Assert.That(Directory.Exists(session.WorkingFolder), Is.True, "the new files are kept to inspect");
        }
    }
}
