using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A working folder that is still there after <see cref="Recovery"/>: an unfinished plan or capture, the old
    /// dataset of a replace whose new one is in place, a merge or convert folder without a journal (written before
    /// journals existed). Every command that writes an output reports those of its output; <c>nerf-dataset clean</c>
    /// removes them (<see cref="LeftoverCleaner"/>).
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

        public string What
        {
            get
            {
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

        /// <summary>The leftovers of <paramref name="output"/>, except <paramref name="exclude"/> (the running operation's own folder).</summary>
        public static IReadOnlyList<Leftover> Of(string output, string exclude = null)
        {
            output = System.IO.Path.GetFullPath(output).TrimEnd(System.IO.Path.DirectorySeparatorChar, System.IO.Path.AltDirectorySeparatorChar);
            var list = new List<Leftover>();
            foreach (var dir in WorkingFolders.Of(output))
            {
                if (exclude != null && WorkingFolders.SamePath(dir, exclude)) continue;
                var kind = WorkingFolders.KindOf(System.IO.Path.GetFileName(dir));
                var journal = OperationJournal.Load(dir);
                // A replaced folder whose output is missing is restored by Recovery, never removed.
                if (kind == "replaced" && !Directory.Exists(output)) continue;
                list.Add(new Leftover
                {
                    Path = dir,
                    Kind = kind,
                    Output = output,
                    Size = WorkingFolders.DescribeSize(dir),
                    Removable = kind != "merge" || journal != null,
                });
            }
            return list;
        }
    }
}
