using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 32 item 3: a recovery in another process removes an empty working folder without a journal as a run killed at
    /// birth, so no run may ever show one. Looked at before every file operation of a plan's, a convert's and a merge's
    /// start: every folder under a working folder's name already holds a journal naming this process. (Before, the folder
    /// was made first and its journal written after: a second plan started in between deleted the live plan's folder.)
    /// The real second process (a live <c>sleep</c> owning a still-empty folder) is <c>Tests/Tool.Tests/DataSafetyTests</c>.
    /// </summary>
    [TestFixture]
    // Sets FileOps.Faults, which every file operation of the process sees: never beside another fixture (dotnet runs
    // fixtures side by side, Tests/Core.Tests/ParallelFixtures.cs).
    [Parallelizable(ParallelScope.None)]
    public class WorkingFolderBirthTests
    {
        TempFolder _temp;

        [SetUp] public void SetUp() => _temp = new TempFolder();

        [TearDown]
        public void TearDown()
        {
            FileOps.Faults = null;
            _temp.Dispose();
        }

        /// <summary>What a recovery in another process would see of <paramref name="output"/>'s working folders: each one's name and whether it has an owner.</summary>
        static IEnumerable<string> OwnerlessWorkingFolders(string output) =>
            WorkingFolders.Of(output).Where(w => OperationJournal.Load(w)?.Owner == null).Select(Path.GetFileName);

        /// <summary>Runs <paramref name="start"/> once per file operation it makes, looking at <paramref name="output"/> just before that operation.</summary>
        static void LookBeforeEveryStep(string output, Action start, Action reset)
        {
            var counting = FileFaultPlan.Counting();
            FileOps.Faults = counting;
            start();
            FileOps.Faults = null;
            var steps = counting.Count;
            Assert.That(steps, Is.GreaterThan(1));
            for (var n = 1; n <= steps; n++)
            {
                reset();
                var seen = new List<string>();
                FileOps.Faults = FileFaultPlan.Killing(n, () => seen.AddRange(OwnerlessWorkingFolders(output)));
                start();
                FileOps.Faults = null;
                Assert.That(seen, Is.Empty, "before step " + n + " of " + steps + " (" + counting.Operations[n - 1] + ")");
            }
        }

        [Test]
        public void APlansWorkingFolderIsBornWithItsOwner()
        {
            var output = _temp.Combine("lego");
            DatasetWriteSession session = null;
            LookBeforeEveryStep(output,
                () => session = DatasetWriteSession.Begin(output, OverwritePolicy.Never, rendersImages: false),
                () =>
                {
                    if (session != null) OperationOwner.Release(session.WorkingFolder);
                    foreach (var dir in Directory.GetDirectories(_temp.Path)) Directory.Delete(dir, true);
                });
            Assert.That(OperationJournal.Load(session.WorkingFolder).Owner.ProcessId, Is.EqualTo(OperationOwner.Current.ProcessId));
            Assert.That(Directory.GetDirectories(_temp.Path).Select(Path.GetFileName), Is.EqualTo(new[] { Path.GetFileName(session.WorkingFolder) }), "no birth folder is left");
        }

        [Test]
        public void AConvertsWorkingFolderIsBornWithItsOwner()
        {
            var output = _temp.Combine("export");
            StagedOutput staged = null;
            LookBeforeEveryStep(output,
                () => staged = StagedOutput.Begin(output, "convert"),
                () =>
                {
                    if (staged != null) OperationOwner.Release(staged.Working);
                    if (Directory.Exists(output)) Directory.Delete(output, true);
                });
            Assert.That(Directory.GetDirectories(output).Select(Path.GetFileName), Is.EqualTo(new[] { Path.GetFileName(staged.Working) }));
        }

        [Test]
        public void ABirthFolderOfAnEndedRunIsRemovedAndALiveOnesIsKept()
        {
            // Runs killed while their working folder was being born: the birth name names the run.
            var output = _temp.Combine("lego");
            OperationOwner self;
            using (var process = System.Diagnostics.Process.GetCurrentProcess())
                self = new OperationOwner(Environment.MachineName, process.Id, process.StartTime.ToUniversalTime());
            var ended = new OperationOwner(self.Host, self.ProcessId, self.ProcessStart.Value.AddHours(-1)); // this id, reused since
            var otherMachine = new OperationOwner("render-farm-7", self.ProcessId, self.ProcessStart);
            string Birth(OperationOwner owner) =>
                _temp.Combine("." + Path.GetFileName(WorkingFolders.NewPartial(output, DateTime.UtcNow)) + ".birth-" + owner.NameTag + "~");
            var endedBirth = Birth(ended);
            var remoteBirth = Birth(otherMachine);
            var lookalike = _temp.Combine(".lego.partial-20261206-120000-abcdef12~.birth-mine~");
            foreach (var dir in new[] { endedBirth, remoteBirth, lookalike }) Directory.CreateDirectory(dir);
            new OperationJournal { Operation = "write", Output = output, Owner = ended }.Save(endedBirth);

            Assert.That(WorkingFolders.KindOf(Path.GetFileName(endedBirth)), Is.Null, "a birth folder is no working folder");
            Assert.That(WorkingFolders.BirthsOf(output), Is.EqualTo(new[] { endedBirth, remoteBirth }.OrderBy(d => d, StringComparer.Ordinal)));
            Recovery.Run(output);
            Assert.That(Directory.Exists(endedBirth), Is.False, "its run has ended: removed");
            Assert.That(Directory.Exists(remoteBirth), Is.True, "another machine's run may be alive");
            Assert.That(Directory.Exists(lookalike), Is.True, "a name the tool does not write is never taken for ours");
        }
    }
}
