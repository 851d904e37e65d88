using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset clean &lt;folder&gt;</c>: finishes or rolls back every interrupted operation on the outputs in
    /// <paramref name="folder"/> (the folder itself, its sub-folders, and those the working folders in it belong to),
    /// then removes the leftovers (<see cref="Leftover"/>) — or, with <c>dryRun</c>, only lists them. It removes only
    /// what it can prove the tool wrote (<see cref="Leftover.NotOurs"/>); a folder whose name merely resembles a working
    /// folder, or whose contents do not prove it, is listed as not ours and left alone.
    /// </summary>
    public static class LeftoverCleaner
    {
        public sealed class Result
        {
            public readonly List<string> Recovered = new List<string>();
            public readonly List<string> Removed = new List<string>();
            public readonly List<string> Kept = new List<string>();

            /// <summary>Recovery's refusals of journals naming paths outside what their operation owns (<see cref="JournalPaths"/>): nothing was changed.</summary>
            public readonly List<string> Refused = new List<string>();

            /// <summary>Folders named like working folders that the tool cannot prove it wrote: listed, never touched.</summary>
            public readonly List<string> LeftAlone = new List<string>();
        }

        public static Result Clean(string folder, bool dryRun)
        {
            var root = Path.GetFullPath(folder).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            if (!Directory.Exists(root))
                throw new InvalidParameterException(new[] { new ValidationProblem("folder", root, "is not an existing folder.", "Pass the folder that holds the datasets (e.g. NeRFDatasets) or a dataset folder.") });
            var result = new Result();
            var seen = new HashSet<string>(StringComparer.Ordinal);
            var outputs = Outputs(root);
            foreach (var output in outputs)
            {
                if (!dryRun)
                    foreach (var note in Recovery.Run(output))
                        if (!note.Running) // a run still writing is listed once, below, as kept
                            (note.Refused ? result.Refused : result.Recovered).Add(note.Text);
                foreach (var leftover in Leftover.All(output))
                {
                    seen.Add(leftover.Path);
                    if (leftover.NotOurs != null) result.LeftAlone.Add(leftover.ToString());
                    else if (leftover.Refused != null)
                    {
                        if (dryRun) result.Kept.Add(leftover + " Not removed."); // without a dry run, recovery's refusal said it
                    }
                    else if (!leftover.Removable) result.Kept.Add(leftover + " Not removed.");
                    else
                    {
                        if (!dryRun) FileOps.DeleteDirectory(leftover.Path);
                        result.Removed.Add(leftover.ToString());
                    }
                }
            }
            foreach (var lookalike in Lookalikes(root, outputs).Where(d => !seen.Contains(d)))
                result.LeftAlone.Add(lookalike + " (" + WorkingFolders.DescribeSize(lookalike) + "): its name only resembles the tool's working folders (" +
                                     WorkingFolders.NameFormats + ").");
            return result;
        }

        /// <summary>The outputs whose working folders may be in or under <paramref name="root"/>.</summary>
        static List<string> Outputs(string root)
        {
            var outputs = new SortedSet<string>(StringComparer.Ordinal) { root };
            foreach (var dir in Directory.EnumerateDirectories(root))
            {
                var name = Path.GetFileName(dir);
                var kind = WorkingFolders.KindOf(name);
                if (kind == null)
                {
                    if (!WorkingFolders.LooksLikeOne(name)) outputs.Add(dir);
                }
                else if (kind != "convert") outputs.Add(WorkingFolders.OutputOf(dir));
            }
            return outputs.Select(o => Path.GetFullPath(o).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar)).Distinct().ToList();
        }

        /// <summary>Folders in <paramref name="root"/> and in the outputs whose names carry a working folder's marker without being one the tool writes.</summary>
        static IEnumerable<string> Lookalikes(string root, IEnumerable<string> outputs)
        {
            var found = new SortedSet<string>(StringComparer.Ordinal);
            foreach (var folder in new[] { root }.Concat(outputs).Where(Directory.Exists).Distinct())
                foreach (var dir in Directory.EnumerateDirectories(folder))
                    if (WorkingFolders.LooksLikeOne(Path.GetFileName(dir))) found.Add(dir);
            return found;
        }
    }
}
