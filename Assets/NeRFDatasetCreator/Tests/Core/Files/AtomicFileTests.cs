using System;
using System.Diagnostics;
using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 32 item 4, the leftover rule: a report is written through a temporary file named for the run that writes it
    /// and renamed when complete; a later run removes only such a temporary file of an ended run (its own leftover), never
    /// a live run's, another machine's, one named otherwise, or the report itself. The end-to-end kill is
    /// <c>Tests/Tool.Tests/DataSafetyTests</c>.
    /// </summary>
    [TestFixture]
    // Sets FileOps.Faults, which every file operation of the process sees: never beside another fixture (dotnet runs
    // fixtures side by side, Tests/Core.Tests/ParallelFixtures.cs).
    [Parallelizable(ParallelScope.None)]
    public class AtomicFileTests
    {
        TempFolder _temp;
        string _report;

        [SetUp]
        public void SetUp()
        {
            _temp = new TempFolder();
            _report = _temp.Combine("report.json");
        }

        [TearDown]
        public void TearDown()
        {
            FileOps.Faults = null;
            _temp.Dispose();
        }

        static OperationOwner Self
        {
            get
            {
                using (var self = Process.GetCurrentProcess()) return new OperationOwner(Environment.MachineName, self.Id, self.StartTime.ToUniversalTime());
            }
        }

        /// <summary>This process's id, started an hour earlier: the process that wrote it has ended and its id was reused.</summary>
        static OperationOwner Ended => new OperationOwner(Environment.MachineName, Self.ProcessId, Self.ProcessStart.Value.AddHours(-1));

        [Test]
        public void AReportIsWrittenWholeAndTheTemporaryFileIsGone()
        {
            AtomicFile.WriteNewText(_report, "{ \"a\": 1 }\n");
            Assert.That(File.ReadAllText(_report), Is.EqualTo("{ \"a\": 1 }\n"));
            Assert.That(Directory.GetFileSystemEntries(_temp.Path), Is.EqualTo(new[] { _report }));
        }

        [Test]
        public void AStopBeforeTheRenameLeavesNothingUnderTheNameAndTheNextRunRemovesTheLeftover()
        {
            // Count the steps, then stop (as a kill would) before the last one, the rename.
            var counting = FileFaultPlan.Counting();
            FileOps.Faults = counting;
            AtomicFile.WriteNewText(_temp.Combine("trial.json"), "x");
            FileOps.Faults = FileFaultPlan.StoppingAt(counting.Count);
            Assert.That(() => AtomicFile.WriteNewText(_report, "{ \"complete\": true }\n"), Throws.TypeOf<SimulatedStopException>());
            FileOps.Faults = null;
            Assert.That(File.Exists(_report), Is.False, "no half-written report under its name");
            var leftover = AtomicFile.TempPath(_report, OperationOwner.Current);
            Assert.That(File.Exists(leftover), Is.True);

            // The stop ended this "run" (OperationOwner.EndAllHere): the rerun takes its temporary file for its own leftover.
            AtomicFile.WriteNewText(_report, "{ \"again\": true }\n");
            Assert.That(File.ReadAllText(_report), Is.EqualTo("{ \"again\": true }\n"));
            Assert.That(File.Exists(leftover), Is.False);
        }

        [Test]
        public void OnlyTheTemporaryFilesOfEndedRunsAreRemoved()
        {
            var ended = AtomicFile.TempPath(_report, Ended);
            var otherMachine = AtomicFile.TempPath(_report, new OperationOwner("render-farm-7", Self.ProcessId, Self.ProcessStart));
            var live = AtomicFile.TempPath(_report, Self);
            var lookalike = _temp.Combine(".report.json.writing-mine~");
            var otherName = AtomicFile.TempPath(_temp.Combine("other.json"), Ended);
            foreach (var f in new[] { ended, otherMachine, live, lookalike, otherName }) File.WriteAllText(f, "{");
            OperationOwner.Register(live); // this process writes it right now
            try
            {
                var removed = AtomicFile.RemoveLeftovers(_report);
                Assert.That(removed, Is.EqualTo(new[] { ended }));
                Assert.That(File.Exists(ended), Is.False);
                Assert.That(File.Exists(otherMachine), Is.True, "another machine's run may be alive");
                Assert.That(File.Exists(live), Is.True, "a live run's temporary file");
                Assert.That(File.Exists(lookalike), Is.True, "a name the tool does not write is never taken for ours");
                Assert.That(File.Exists(otherName), Is.True, "only the temporary files of the report being written");
            }
            finally
            {
                OperationOwner.Release(live);
            }
        }

        [Test]
        public void AnExistingReportIsNeverReplaced()
        {
            File.WriteAllText(_report, "the user's");
            Assert.That(() => AtomicFile.WriteNewText(_report, "ours"), Throws.TypeOf<IOException>().With.Message.Contains(_report + " already exists"));
            Assert.That(File.ReadAllText(_report), Is.EqualTo("the user's"));
            Assert.That(Directory.GetFileSystemEntries(_temp.Path), Is.EqualTo(new[] { _report }));
        }

        [Test]
        public void TheTemporaryNameRecordsTheRunAndReadsBack()
        {
            var owner = new OperationOwner("studio-7.local", 4242, new DateTime(2026, 12, 6, 22, 17, 5, DateTimeKind.Utc));
            var temp = AtomicFile.TempPath(_report, owner);
            Assert.That(Path.GetFileName(temp), Is.EqualTo(".report.json.writing-studio7local-4242-20261206221705~"));
            var read = AtomicFile.OwnerOf(temp, _report);
            Assert.That(read.ProcessId, Is.EqualTo(4242));
            Assert.That(read.ProcessStart, Is.EqualTo(new DateTime(2026, 12, 6, 22, 17, 5, DateTimeKind.Utc)));
            Assert.That(AtomicFile.OwnerOf(_temp.Combine(".report.json.writing-studio7local-4242-20261206221705"), _report), Is.Null, "without its '~' it is not ours");
            Assert.That(AtomicFile.OwnerOf(_temp.Combine(".report.json.writing-a-b-c~"), _report), Is.Null);
        }
    }
}
