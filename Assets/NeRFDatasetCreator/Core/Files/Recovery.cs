using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Finishes or rolls back the interrupted operations on one output, from their journals
    /// (<see cref="OperationJournal"/>): the first thing every run that writes an output does. An operation whose
    /// files were all complete (<see cref="OperationJournal.Committing"/>) is finished; one that was still producing
    /// them is rolled back — merge moves the shards' files back, convert removes its partial files — except a
    /// plan or capture's partial folder, which is kept (it may hold hours of rendering) and reported as a leftover.
    /// Returns one sentence per operation, saying which it did.
    /// </summary>
    public static class Recovery
    {
        public static IReadOnlyList<RecoveryNote> Run(string output)
        {
            output = Path.GetFullPath(output).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            var notes = new List<RecoveryNote>();
            var own = Directory.Exists(output) ? OperationJournal.Load(output) : null;
            if (own != null && own.State == OperationJournal.Committing && WorkingFolders.SamePath(own.Output, output))
            {
                if (own.Aside != null && !IsAsideOf(own.Aside, output)) own.Aside = null;
                // The operation had moved its complete folder into place; only its clean-up was left.
                var removed = own.Aside != null && Directory.Exists(own.Aside);
                if (removed) FileOps.DeleteDirectory(own.Aside);
                OperationJournal.Delete(output);
                notes.Add(new RecoveryNote(own.Operation, true, "finished the interrupted " + own.Operation + " of " + output + ": it was complete and in place" +
                          (removed ? "; removed the dataset it replaced (" + own.Aside + ")." : ".")));
            }

            foreach (var working in WorkingFolders.Of(output))
            {
                var journal = OperationJournal.Load(working);
                if (journal == null && HoldsNothing(working))
                {
                    // Killed between creating the folder and writing its journal: nothing to finish, nothing to keep.
                    FileOps.DeleteDirectory(working);
                    continue;
                }
                if (journal == null || !WorkingFolders.SamePath(journal.Output, output)) continue;
                // A journal only ever names this output's own replaced folder: never act on a path it did not create.
                if (journal.Aside != null && !IsAsideOf(journal.Aside, output)) journal.Aside = null;
                switch (journal.Operation)
                {
                    case "write": Write(working, journal, output, notes); break;
                    case "merge": Merge(working, journal, output, notes); break;
                    case "convert": Convert(working, journal, output, notes); break;
                }
            }

            // A dataset moved aside by a replace whose journal is gone, with nothing under its name: put it back.
            if (!Directory.Exists(output) && !File.Exists(output))
            {
                var aside = WorkingFolders.Of(output).FirstOrDefault(d => WorkingFolders.KindOf(Path.GetFileName(d)) == "replaced");
                if (aside != null)
                {
                    FileOps.MoveDirectory(aside, output);
                    notes.Add(new RecoveryNote("write", false, "rolled back an interrupted replace of " + output + ": restored the previous dataset from " + aside + "."));
                }
            }
            return notes;
        }

        /// <summary>True when <paramref name="folder"/> has no file but a half-written journal (a working folder killed at birth).</summary>
        static bool HoldsNothing(string folder) =>
            WorkingFolders.KindOf(Path.GetFileName(folder)) != "replaced" &&
            Directory.EnumerateFiles(folder, "*", SearchOption.AllDirectories)
                .All(f => Path.GetFileName(f).StartsWith(OperationJournal.FileName, System.StringComparison.Ordinal));

        static bool IsAsideOf(string aside, string output) =>
            WorkingFolders.KindOf(Path.GetFileName(aside)) == "replaced" && WorkingFolders.SamePath(WorkingFolders.OutputOf(aside), output);

        static void Write(string working, OperationJournal journal, string output, List<RecoveryNote> notes)
        {
            if (journal.State != OperationJournal.Committing) return; // unfinished files: a leftover, reported, never deleted silently
            var asideExists = journal.Aside != null && Directory.Exists(journal.Aside);
            if (Directory.Exists(output) || File.Exists(output))
            {
                // Killed before the old dataset was moved aside: finish only if it is still provably ours.
                if (asideExists || journal.Aside == null || OwnDataset.WhyNotOurs(output) != null)
                {
                    notes.Add(new RecoveryNote("write", false, "could not finish the interrupted write of " + output + ": something else is under that name now; the complete new dataset stays in " + working + "."));
                    return;
                }
                FileOps.MoveDirectory(output, journal.Aside);
                asideExists = true;
            }
            FileOps.MoveDirectory(working, output);
            if (asideExists) FileOps.DeleteDirectory(journal.Aside);
            OperationJournal.Delete(output);
            notes.Add(new RecoveryNote("write", true, "finished the interrupted write of " + output + ": moved the complete dataset from " + working + " into place" +
                      (asideExists ? " and removed the dataset it replaced." : ".")));
        }

        static void Merge(string working, OperationJournal journal, string output, List<RecoveryNote> notes)
        {
            if (journal.State == OperationJournal.Committing && !Directory.Exists(output) && !File.Exists(output))
            {
                FileOps.MoveDirectory(working, output);
                OperationJournal.Delete(output);
                notes.Add(new RecoveryNote("merge", true, "finished the interrupted merge into " + output + ": it was complete in " + working + " and is now in place."));
                return;
            }
            // Roll back: every file the merge took from a shard goes back; copies are simply dropped with the folder.
            var returned = 0;
            foreach (var move in journal.Moves)
            {
                var staged = Path.GetFullPath(Path.Combine(working, move.Value.Replace('/', Path.DirectorySeparatorChar)));
                if (!staged.StartsWith(working + Path.DirectorySeparatorChar, System.StringComparison.Ordinal)) continue;
                if (!File.Exists(staged) || File.Exists(move.Key)) continue; // not moved yet, or the original is intact
                FileOps.CreateDirectory(Path.GetDirectoryName(move.Key));
                FileOps.MoveFile(staged, move.Key);
                returned++;
            }
            FileOps.DeleteDirectory(working);
            notes.Add(new RecoveryNote("merge", false, "rolled back the interrupted merge into " + output + ": " +
                      (returned > 0 ? "moved " + returned + " file(s) back into the shard folders and " : "") + "removed " + working + "."));
        }

        static void Convert(string working, OperationJournal journal, string output, List<RecoveryNote> notes)
        {
            if (journal.State == OperationJournal.Committing)
            {
                var conflicts = new List<string>();
                foreach (var file in journal.Files)
                {
                    var from = Path.GetFullPath(Path.Combine(working, file.Replace('/', Path.DirectorySeparatorChar)));
                    var to = Path.GetFullPath(Path.Combine(output, file.Replace('/', Path.DirectorySeparatorChar)));
                    if (!from.StartsWith(working + Path.DirectorySeparatorChar, System.StringComparison.Ordinal) ||
                        !to.StartsWith(output + Path.DirectorySeparatorChar, System.StringComparison.Ordinal)) continue;
                    if (!File.Exists(from)) continue; // already in place
                    if (File.Exists(to) || Directory.Exists(to))
                    {
                        conflicts.Add(to);
                        continue;
                    }
                    FileOps.CreateDirectory(Path.GetDirectoryName(to));
                    FileOps.MoveFile(from, to);
                }
                if (conflicts.Count > 0)
                {
                    notes.Add(new RecoveryNote("convert", false, "could not finish the interrupted convert into " + output + ": " + conflicts[0] + " appeared meanwhile; the remaining files stay in " + working + "."));
                    return;
                }
                FileOps.DeleteDirectory(working);
                notes.Add(new RecoveryNote("convert", true, "finished the interrupted convert into " + output + ": moved its remaining files into place."));
                return;
            }
            FileOps.DeleteDirectory(working);
            if (journal.CreatedOutput && Directory.Exists(output) && !Directory.EnumerateFileSystemEntries(output).Any())
                FileOps.DeleteDirectory(output);
            notes.Add(new RecoveryNote("convert", false, "rolled back the interrupted convert into " + output + ": removed its partial files (" + working + ")."));
        }
    }
}

