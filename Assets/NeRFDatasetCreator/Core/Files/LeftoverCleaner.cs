using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset clean &lt;folder&gt;</c>: finishes or rolls back every interrupted operation on the outputs in
    /// <paramref name="folder"/> (the folder itself, its sub-folders, and those the working folders in it belong to),
    /// then removes the leftovers (<see cref="Leftover"/>) — or, with <c>dryRun</c>, only lists them.
    /// </summary>
    public static class LeftoverCleaner
    {
        public sealed class Result
        {
            public readonly List<string> Recovered = new List<string>();
            public readonly List<string> Removed = new List<string>();
            public readonly List<string> Kept = new List<string>();
        }

        public static Result Clean(string folder, bool dryRun)
        {
            var root = Path.GetFullPath(folder).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            if (!Directory.Exists(root))
                throw new InvalidParameterException(new[] { new ValidationProblem("folder", root, "is not an existing folder.", "Pass the folder that holds the datasets (e.g. NeRFDatasets) or a dataset folder.") });
            var result = new Result();
            foreach (var output in Outputs(root))
            {
                if (!dryRun) result.Recovered.AddRange(Recovery.Run(output).Select(n => n.Text));
                foreach (var leftover in Leftover.Of(output))
                {
                    if (!leftover.Removable)
                    {
                        result.Kept.Add(leftover + " Not removed.");
                        continue;
                    }
                    if (!dryRun) FileOps.DeleteDirectory(leftover.Path);
                    result.Removed.Add(leftover.ToString());
                }
            }
            return result;
        }

        /// <summary>The outputs whose working folders may be in or under <paramref name="root"/>.</summary>
        static IEnumerable<string> Outputs(string root)
        {
            var outputs = new SortedSet<string>(StringComparer.Ordinal) { root };
            foreach (var dir in Directory.EnumerateDirectories(root))
            {
                var name = Path.GetFileName(dir);
                var kind = WorkingFolders.KindOf(name);
                if (kind == null) outputs.Add(dir);
                else if (kind != "convert") outputs.Add(WorkingFolders.OutputOf(dir));
            }
            return outputs.Select(o => Path.GetFullPath(o).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar)).Distinct().ToList();
        }
    }
}
