using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A working folder that is still there after <see cref="Recovery"/>: an unfinished plan or capture, the old
    /// dataset of a replace whose new one is in place, a merge or convert folder without a journal (written before
    /// journals existed). Every command that writes an output reports those of its output; <c>nerf-dataset clean</c>
    /// removes them (<see cref="LeftoverCleaner"/>) — but only what the tool can prove it wrote: the exact name it gives
    /// its working folders (<see cref="WorkingFolders.KindOf"/>) and, inside, its journal naming this output (or, for a
    /// dataset a replace moved aside, the plugin's own <c>dataset_config.json</c> and nothing else, <see cref="OwnDataset"/>).
    /// </summary>
    public sealed class Leftover
    {
        public string Path;

        /// <summary>"write", "replaced", "merge" or "convert" (<see cref="WorkingFolders.KindOf"/>).</summary>
        public string Kind;

        /// <summary>The output it belongs to.</summary>
        public string Output;

        public string Size;

        /// <summary>False for a folder clean keeps: a merge folder without journal may hold the only copy of images an older merge moved.</summary>
        public bool Removable;

        /// <summary>Null when the tool can prove it wrote the folder; otherwise why not (clean lists it as not ours and leaves it alone).</summary>
        public string NotOurs;

        /// <summary>A complete plan or capture that recovery could not move into place: kept, never removed.</summary>
        public bool Complete;

        /// <summary>Why recovery refused the folder's journal (<see cref="JournalPaths"/>), or null.</summary>
        public string Refused;

        /// <summary>Why the run that writes the folder may still be running (<see cref="OperationOwner"/>), or null: such a folder is no leftover, and clean keeps it.</summary>
        public string Running;

        public string What
        {
            get
            {
                if (NotOurs != null) return NotOurs;
                if (Running != null) return "the working folder of a " + Kind + " into " + Output + " that is not over: " + Running;
                if (Refused != null) return "the working folder of an interrupted " + Kind + " into " + Output + ", kept: recovery refused it because " + Refused;
                if (Complete) return "a complete dataset for " + Output + " that could not be moved into place because something else is under that name (rename one of the two yourself)";
                switch (Kind)
                {
                    case "write": return "the partial files of a plan or capture of " + Output + " that did not finish";
                    case "replaced": return "the previous dataset of " + Output + ", left by a replace that completed";
                    case "convert": return "the partial files of a convert into " + Output + " that did not finish";
                    default:
                        return Removable ? "the working folder of a merge into " + Output
                            : "the working folder of an older merge into " + Output + " without a journal; it may hold images that merge --files move took from the shards (move them back into the shards' split folders, then delete it)";
                }
            }
        }

        public override string ToString() => Path + " (" + Size + "): " + What + ".";

        /// <summary>The leftovers of <paramref name="output"/> the tool wrote, except <paramref name="exclude"/> (the running operation's own folder).</summary>
        public static IReadOnlyList<Leftover> Of(string output, string exclude = null) => All(output, exclude).Where(l => l.NotOurs == null && l.Running == null).ToList();

        /// <summary>Every folder named as a working folder of <paramref name="output"/>, each with whether the tool can prove it wrote it (<see cref="NotOurs"/>).</summary>
        public static IReadOnlyList<Leftover> All(string output, string exclude = null)
        {
            output = System.IO.Path.GetFullPath(output).TrimEnd(System.IO.Path.DirectorySeparatorChar, System.IO.Path.AltDirectorySeparatorChar);
            var list = new List<Leftover>();
            foreach (var dir in WorkingFolders.Of(output))
            {
                if (exclude != null && WorkingFolders.SamePath(dir, exclude)) continue;
                var kind = WorkingFolders.KindOf(System.IO.Path.GetFileName(dir));
                // A replaced folder whose output is missing is restored by Recovery, never removed.
                if (kind == "replaced" && !Directory.Exists(output)) continue;
                var leftover = new Leftover { Path = dir, Kind = kind, Output = output, Size = WorkingFolders.DescribeSize(dir) };
                Prove(leftover);
                list.Add(leftover);
            }
            return list;
        }

        /// <summary>Sets <see cref="Removable"/>, <see cref="NotOurs"/> and <see cref="Refused"/> from what is inside the folder.</summary>
        static void Prove(Leftover leftover)
        {
            var dir = leftover.Path;
            if (leftover.Kind == "replaced")
            {
                // The dataset a replace moved aside: the plugin's config, and nothing the plugin does not write.
                leftover.NotOurs = OwnDataset.WhyNotOurs(dir);
                leftover.Removable = leftover.NotOurs == null;
                return;
            }
            var journal = OperationJournal.Load(dir);
            if (journal == null)
            {
                // Killed between creating the folder and writing its journal: no file in it, nothing to lose.
                if (OperationOwner.IsRunningHere(dir)) leftover.Running = "this process is still writing it";
                else if (WorkingFolders.HoldsNoFile(dir)) leftover.Removable = true;
                else if (leftover.Kind == "merge") leftover.Removable = false; // an older merge's: kept, with what to do
                else leftover.NotOurs = "it holds no journal (" + OperationJournal.FileName + ") the tool wrote";
                return;
            }
            if (journal.Operation != leftover.Kind || !WorkingFolders.SamePath(journal.Output, leftover.Output))
            {
                leftover.NotOurs = "its journal " + OperationJournal.PathIn(dir) + " is not a " + leftover.Kind + " into " + leftover.Output;
                return;
            }
            leftover.Running = OperationOwner.WhyMayBeRunning(journal.Owner, dir);
            if (leftover.Running != null) return; // not removable: another run (or this one) is writing it
            leftover.Refused = JournalPaths.WhyRefused(dir, journal, leftover.Output);
            // A complete dataset recovery could not move into place (something else took its name) may be the only copy of a capture.
            leftover.Complete = leftover.Kind == "write" && journal.State == OperationJournal.Committing;
            leftover.Removable = leftover.Refused == null && !leftover.Complete;
        }
    }
}
