using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Recovery and clean act only on the working folders of runs that have ended: a convert, merge or clean started
    /// while a capture or another convert writes the same output leaves that run's files alone. Runs in Unity's Test
    /// Runner too, where the Editor's capture and its tools window share one process.
    /// </summary>
    [TestFixture]
    // Sets FileOps.Faults, which every file operation of the process sees: never beside another fixture (dotnet runs
    // fixtures side by side, Tests/Core.Tests/ParallelFixtures.cs).
    [Parallelizable(ParallelScope.None)]
    public class OperationOwnerTests
    {
        TempFolder _temp;
        string _output;

        [SetUp]
        public void SetUp()
        {
            _temp = new TempFolder();
            _output = _temp.Combine("lego");
            Directory.CreateDirectory(_output);
            File.WriteAllText(Path.Combine(_output, "transforms_train.json"), "{}");
        }

        [TearDown]
        public void TearDown() => _temp.Dispose();

        /// <summary>A convert's working folder with one staged file and a journal naming <paramref name="owner"/>.</summary>
        string ConvertFolderOf(OperationOwner owner)
        {
            var working = WorkingFolders.NewConvert(_output, new DateTime(2026, 11, 27, 12, 0, 0, DateTimeKind.Utc));
            Directory.CreateDirectory(working);
            File.WriteAllText(Path.Combine(working, "transforms.json"), "{ \"frames\": [] }");
            new OperationJournal { Operation = "convert", Output = _output, Owner = owner }.Save(working);
            return working;
        }

        static DateTime StartOfThisProcess()
        {
            using (var self = Process.GetCurrentProcess()) return self.StartTime.ToUniversalTime();
        }

        [Test]
        public void AJournalNamesTheMachineAndTheProcessThatWroteIt()
        {
            var folder = _temp.Combine("working");
            Directory.CreateDirectory(folder);
            new OperationJournal { Operation = "convert", Output = _output }.Save(folder);

            var json = JObject.Parse(File.ReadAllText(OperationJournal.PathIn(folder)));
            int pid;
            using (var self = Process.GetCurrentProcess()) pid = self.Id;
            Assert.That((int)json["owner"]["pid"], Is.EqualTo(pid));
            Assert.That((string)json["owner"]["host"], Is.EqualTo(Environment.MachineName));
            var loaded = OperationJournal.Load(folder);
            Assert.That(loaded.Owner.ProcessId, Is.EqualTo(pid));
            Assert.That(loaded.Owner.ProcessStart.HasValue, Is.True);
            Assert.That((loaded.Owner.ProcessStart.Value - StartOfThisProcess()).Duration().TotalSeconds, Is.LessThan(2));
        }

        [Test]
        public void AConvertStillRunningInThisProcessIsLeftAloneUntilItEnds()
        {
            var staged = StagedOutput.Begin(_output, "convert");
            staged.WriteNewText(Path.Combine(_output, "transforms.json"), "{}");

            var notes = Recovery.Run(_output);
            Assert.That(notes.Count, Is.EqualTo(1));
            Assert.That(notes[0].Running, Is.True);
            Assert.That(notes[0].Text, Does.Contain("left " + staged.Working + " alone").And.Contain("is still writing it"));
            Assert.That(File.Exists(Path.Combine(staged.Working, "transforms.json")), Is.True, "the live run's staged file is untouched");
            Assert.That(Leftover.Of(_output), Is.Empty, "a run in progress is not a leftover");

            // The run ends without committing (as after an exception nothing caught): the next recovery rolls it back.
            OperationOwner.Release(staged.Working);
            notes = Recovery.Run(_output);
            Assert.That(notes.Single().Text, Does.StartWith("rolled back the interrupted convert"));
            Assert.That(Directory.Exists(staged.Working), Is.False);
        }

        [Test]
        public void CleanKeepsTheFolderOfACaptureStillWritingAndRemovesItOnceTheRunEnded()
        {
            var capture = DatasetWriteSession.Begin(_temp.Combine("chair"), OverwritePolicy.Never);
            capture.WriteText("train/r_0.png", "pixels");

            var result = LeftoverCleaner.Clean(_temp.Path, dryRun: false);
            Assert.That(result.Removed, Is.Empty);
            Assert.That(result.Kept.Single(), Does.StartWith(capture.WorkingFolder + " (").And.Contain("that is not over: this process"));
            Assert.That(File.Exists(capture.PathOf("train/r_0.png")), Is.True);

            capture.End(); // failed or cancelled: its partial files are now a leftover
            result = LeftoverCleaner.Clean(_temp.Path, dryRun: false);
            Assert.That(result.Removed.Single(), Does.StartWith(capture.WorkingFolder + " ("));
            Assert.That(Directory.Exists(capture.WorkingFolder), Is.False);
        }

        [Test]
        public void ASecondCaptureOfTheSameOutputDoesNotReportTheFirstAsALeftoverWhileItRuns()
        {
            var target = _temp.Combine("chair");
            var first = DatasetWriteSession.Begin(target, OverwritePolicy.Never);
            var second = DatasetWriteSession.Begin(target, OverwritePolicy.Never);
            Assert.That(second.Leftovers, Is.Empty);
            Assert.That(second.Recovered.Single().Running, Is.True);

            first.End();
            second.End();
            var third = DatasetWriteSession.Begin(target, OverwritePolicy.Never);
            Assert.That(third.Leftovers.Select(l => l.Path), Is.EquivalentTo(new[] { first.WorkingFolder, second.WorkingFolder }));
            third.End();
        }

        [Test]
        public void AJournalOfAProcessThatNoLongerExistsIsRolledBack()
        {
            // No process ever has this id: above Linux's pid_max, and not a multiple of 4 as Windows' ids are.
            var working = ConvertFolderOf(new OperationOwner(Environment.MachineName, int.MaxValue - 1, DateTime.UtcNow));
            var notes = Recovery.Run(_output);
            Assert.That(notes.Single().Text, Does.StartWith("rolled back the interrupted convert"));
            Assert.That(Directory.Exists(working), Is.False);
        }

        [Test]
        public void AProcessIdReusedByAnotherProcessIsNotTakenForTheWriter()
        {
            int pid;
            using (var self = Process.GetCurrentProcess()) pid = self.Id;
            // This process's id, but a writer that started a day earlier: the writer ended and its id was given again.
            var working = ConvertFolderOf(new OperationOwner(Environment.MachineName, pid, StartOfThisProcess().AddDays(-1)));
            Assert.That(Recovery.Run(_output).Single().Text, Does.StartWith("rolled back the interrupted convert"));
            Assert.That(Directory.Exists(working), Is.False);
        }

        [Test]
        public void AnotherLiveProcessKeepsItsFolder()
        {
            var other = OtherProcessWithAStartTime();
            Assume.That(other, Is.Not.Null, "no other process whose start time can be read");
            var working = ConvertFolderOf(other);

            var notes = Recovery.Run(_output);
            Assert.That(notes.Single().Running, Is.True);
            Assert.That(notes.Single().Text, Does.Contain("process " + other.ProcessId + ", started "));
            Assert.That(File.Exists(Path.Combine(working, "transforms.json")), Is.True);
            var cleaned = LeftoverCleaner.Clean(_temp.Path, dryRun: false);
            Assert.That(cleaned.Removed, Is.Empty);
            Assert.That(cleaned.Kept.Single(), Does.Contain("may still be writing it"));
            Assert.That(Directory.Exists(working), Is.True);
        }

        [Test]
        public void ARunOnAnotherMachineIsLeftAloneWithWhatToDo()
        {
            var working = ConvertFolderOf(new OperationOwner("render-node-7", 4242, DateTime.UtcNow));
            var note = Recovery.Run(_output).Single();
            Assert.That(note.Running, Is.True);
            Assert.That(note.Text, Does.Contain("a run on \"render-node-7\"").And.Contain("remove the folder yourself"));
            Assert.That(Directory.Exists(working), Is.True);
        }

        [Test]
        public void AJournalFromBeforeOwnersAndOneWithAnUnreadableOwnerAreRecoveredAsBefore()
        {
            foreach (var owner in new JToken[] { null, new JObject { ["pid"] = "not a number" }, new JObject { ["pid"] = 10000000000L } })
            {
                var working = ConvertFolderOf(OperationOwner.Current);
                var journal = JObject.Parse(File.ReadAllText(OperationJournal.PathIn(working)));
                if (owner == null) journal.Remove("owner");
                else journal["owner"] = owner;
                File.WriteAllText(OperationJournal.PathIn(working), journal.ToString());

                Assert.That(OperationJournal.Load(working).Owner, Is.Null, owner?.ToString() ?? "no owner");
                Assert.That(Recovery.Run(_output).Single().Text, Does.StartWith("rolled back the interrupted convert"));
                Assert.That(Directory.Exists(working), Is.False);
            }
        }

        [Test]
        public void ASimulatedKillEndsEveryRunOfTheProcess()
        {
            var staged = StagedOutput.Begin(_output, "convert");
            Assert.That(OperationOwner.IsRunningHere(staged.Working), Is.True);
            FileOps.Faults = FileFaultPlan.StoppingAt(1);
            try
            {
                Assert.Throws<SimulatedStopException>(() => staged.WriteNewText(Path.Combine(_output, "transforms.json"), "{}"));
            }
            finally
            {
                FileOps.Faults = null;
            }
            Assert.That(OperationOwner.IsRunningHere(staged.Working), Is.False);
            Assert.That(Recovery.Run(_output).Single().Text, Does.StartWith("rolled back the interrupted convert"));
        }

        static OperationOwner OtherProcessWithAStartTime()
        {
            int self;
            using (var current = Process.GetCurrentProcess()) self = current.Id;
            foreach (var process in Process.GetProcesses())
                using (process)
                {
                    if (process.Id == self) continue;
                    try
                    {
                        return new OperationOwner(Environment.MachineName, process.Id, process.StartTime.ToUniversalTime());
                    }
                    catch (Exception e) when (e is InvalidOperationException || e is NotSupportedException || e is System.ComponentModel.Win32Exception)
                    {
                    }
                }
            return null;
        }
    }
}
