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
    /// Returns one sentence per operation, saying which it did. The folders of runs that may still be writing (another
    /// process, or this one: <see cref="OperationOwner"/>) are left alone, with a sentence saying so.
    /// </summary>
    public static class Recovery
    {
        public static IReadOnlyList<RecoveryNote> Run(string output)
        {
            output = Path.GetFullPath(output).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            var notes = new List<RecoveryNote>();
            var own = Directory.Exists(output) ? OperationJournal.Load(output) : null;
            var ownRunning = own == null ? null : OperationOwner.WhyMayBeRunning(own.Owner, output);
            if (own != null && own.State == OperationJournal.Committing && WorkingFolders.SamePath(own.Output, output) && ownRunning != null)
                notes.Add(Running(own.Operation, output, output, ownRunning));
            else if (own != null && own.State == OperationJournal.Committing && WorkingFolders.SamePath(own.Output, output))
            {
                var refused = JournalPaths.WhyRefused(output, own, output, asideOnly: true);
                if (refused != null) notes.Add(Refusal(own.Operation, output, refused));
                else
                {
                    // The operation had moved its complete folder into place; only its clean-up was left.
                    var foreign = own.Aside != null && Directory.Exists(own.Aside) ? OwnDataset.WhyNotOurs(own.Aside) : null;
                    var removed = own.Aside != null && Directory.Exists(own.Aside) && foreign == null;
                    if (removed) FileOps.DeleteDirectory(own.Aside);
                    OperationJournal.Delete(output);
                    notes.Add(new RecoveryNote(own.Operation, true, "finished the interrupted " + own.Operation + " of " + output + ": it was complete and in place" +
                              (removed ? "; removed the dataset it replaced (" + own.Aside + ")." :
                               foreign != null ? "; left " + own.Aside + " alone: " + foreign + "." : ".")));
                }
            }

            foreach (var working in WorkingFolders.Of(output))
            {
                var journal = OperationJournal.Load(working);
                if (journal == null && WorkingFolders.KindOf(Path.GetFileName(working)) != "replaced" && WorkingFolders.HoldsNoFile(working) && !OperationOwner.IsRunningHere(working) &&
                    OperationJournal.Load(working) == null) // read again: a live run rewriting its journal has it under one of two names at every instant
                {
                    // No run makes a working folder without its journal naming the run (WorkingFolders.Create): this one was
                    // killed at birth by an older version of the tool, or made by hand. Nothing to finish, nothing to keep.
                    FileOps.DeleteDirectory(working);
                    continue;
                }
                // Act only on a journal whose operation is the one the folder's name says and whose output is this one.
                if (journal == null || journal.Operation != WorkingFolders.KindOf(Path.GetFileName(working)) || !WorkingFolders.SamePath(journal.Output, output)) continue;
                // Another run may be writing this folder right now (a capture while a convert starts): its files are not ours to touch.
                var running = OperationOwner.WhyMayBeRunning(journal.Owner, working);
                if (running != null)
                {
                    notes.Add(Running(journal.Operation, output, working, running));
                    continue;
                }
                // A journal is a file anyone can edit: act on none of its paths unless all lie inside what the operation owns.
                var refused = JournalPaths.WhyRefused(working, journal, output);
                if (refused != null)
                {
                    notes.Add(Refusal(journal.Operation, output, refused));
                    continue;
                }
                switch (journal.Operation)
                {
                    case "write": Write(working, journal, output, notes); break;
                    case "merge": Merge(working, journal, output, notes); break;
                    case "convert": Convert(working, journal, output, notes); break;
                }
            }

            // A run killed while its working folder was being born (WorkingFolders.Create): the name proves whose it is, and
            // once that run has ended it holds nothing but perhaps its journal.
            foreach (var birth in WorkingFolders.BirthsOf(output))
            {
                var owner = WorkingFolders.BirthOwner(Path.GetFileName(birth));
                if (owner == null || PathSafety.IsLink(birth) || OperationOwner.WhyMayBeRunning(owner, birth) != null || !WorkingFolders.HoldsNoFile(birth)) continue;
                FileOps.DeleteDirectory(birth);
            }

            // A dataset moved aside by a replace whose journal is gone, with nothing under its name: put it back.
            if (!Directory.Exists(output) && !File.Exists(output))
            {
                // Only a folder that is provably this plugin's dataset: a user's folder that happens to have the name stays where it is.
                var aside = WorkingFolders.Of(output).FirstOrDefault(d => WorkingFolders.KindOf(Path.GetFileName(d)) == "replaced" && OwnDataset.WhyNotOurs(d) == null);
                if (aside != null)
                {
                    FileOps.MoveDirectory(aside, output);
                    notes.Add(new RecoveryNote("write", false, "rolled back an interrupted replace of " + output + ": restored the previous dataset from " + aside + "."));
                }
            }
            return notes;
        }

        static RecoveryNote Running(string operation, string output, string folder, string why) =>
            new RecoveryNote(operation, false, "left " + folder + " alone: " + why + "; it is the " + (operation ?? "operation") + " of " + output + ", and nothing of it was changed.", running: true);

        static RecoveryNote Refusal(string operation, string output, string why) =>
            new RecoveryNote(operation, false, "refused to recover the interrupted " + (operation ?? "operation") + " of " + output + ": " + why +
                             "; nothing was changed (a journal the tool wrote never does this: inspect that folder, and remove it yourself if it is not yours to keep).", refused: true);

        static void Write(string working, OperationJournal journal, string output, List<RecoveryNote> notes)
        {
            if (journal.State != OperationJournal.Committing) return; // unfinished files: a leftover, reported, never deleted silently
            var asideExists = journal.Aside != null && Directory.Exists(journal.Aside);
            if (Directory.Exists(output) || File.Exists(output))
            {
                // Killed before the old dataset was moved aside: finish only if it is still provably ours.
                if (asideExists || journal.Aside == null || OwnDataset.WhyNotReplaceable(output, !DatasetConfig.Read(working).IsPlanOnly) != null)
                {
                    notes.Add(new RecoveryNote("write", false, "could not finish the interrupted write of " + output + ": something else is under that name now; the complete new dataset stays in " + working + "."));
                    return;
                }
                FileOps.MoveDirectory(output, journal.Aside);
                asideExists = true;
            }
            // The old dataset the replace moved aside goes only while it is still provably this plugin's.
            var foreign = asideExists ? OwnDataset.WhyNotOurs(journal.Aside) : null;
            FileOps.MoveDirectory(working, output);
            if (asideExists && foreign == null) FileOps.DeleteDirectory(journal.Aside);
            OperationJournal.Delete(output);
            notes.Add(new RecoveryNote("write", true, "finished the interrupted write of " + output + ": moved the complete dataset from " + working + " into place" +
                      (!asideExists ? "." : foreign == null ? " and removed the dataset it replaced." : "; left " + journal.Aside + " alone: " + foreign + ".")));
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
                // Both ends were proved inside the working folder and a shard folder (JournalPaths) before anything was done.
                var staged = PathSafety.Inside(working, move.Value, out _);
                var from = JournalPaths.OwningShard(journal, move.Key);
                if (staged == null || from == null) continue;
                if (!File.Exists(staged) || File.Exists(from)) continue; // not moved yet, or the original is intact
                FileOps.CreateDirectory(Path.GetDirectoryName(from));
                FileOps.MoveFile(staged, from);
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
                    var from = PathSafety.Inside(working, file, out _);
                    var to = PathSafety.Inside(output, file, out _);
                    if (from == null || to == null) continue; // refused up front (JournalPaths)
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

