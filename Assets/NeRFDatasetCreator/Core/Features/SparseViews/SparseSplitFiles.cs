using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes <c>splits/sparse_&lt;n&gt;.json</c> files into a finished dataset (<c>nerf-dataset splits</c>). Never
    /// overwrites: a file that already holds the same text is left as it is ("unchanged"), one that differs is refused.
    /// </summary>
    public static class SparseSplitFiles
    {
        /// <summary>The view count written when none is asked for: the papers' 8.</summary>
        public const int DefaultViews = 8;

        public sealed class Outcome
        {
            public SparseSplit Split;
            public string Path;
            public bool Unchanged;
        }

        /// <summary>Builds every split first (all refusals before the first byte), then writes each new file.</summary>
        public static IReadOnlyList<Outcome> Write(string datasetFolder, IReadOnlyList<int> counts)
        {
            if (string.IsNullOrEmpty(datasetFolder) || !Directory.Exists(datasetFolder))
                throw new InvalidParameterException(new[] { new ValidationProblem("<dataset>", datasetFolder ?? "", "is not an existing folder.", "Pass the dataset folder (the one holding transforms_train.json).") });
            var root = Path.GetFullPath(datasetFolder);
            var views = SparseSplits.ReadViews(root);
            var outcomes = new List<Outcome>();
            foreach (var n in counts.Distinct())
            {
                var split = SparseSplits.Build(views.Train, views.Test, n);
                var path = Path.Combine(root, SparseSplit.FolderName, split.Name + ".json");
                var unchanged = false;
                if (File.Exists(path) || Directory.Exists(path))
                {
                    if (File.Exists(path) && FileOps.ReadText(path) == split.ToJson()) unchanged = true;
                    else
                        throw new InvalidParameterException(new[]
                        {
                            new ValidationProblem(SparseSplit.RelativePath(split.Name), path, "already exists with other lists (another rule, or written before the dataset changed); splits never overwrites a file.",
                                "Move it away and run again, or keep it."),
                        });
                }
                outcomes.Add(new Outcome { Split = split, Path = path, Unchanged = unchanged });
            }
            foreach (var o in outcomes.Where(o => !o.Unchanged))
            {
                FileOps.CreateDirectory(Path.GetDirectoryName(o.Path));
                FileOps.WriteNewText(o.Path, o.Split.ToJson());
            }
            return outcomes;
        }

        /// <summary>A capture's or plan's split files (the config's <c>sparseViews</c>), written beside its transforms files.</summary>
        public static void Write(DatasetWriteSession session, CapturePlan plan)
        {
            var counts = plan.Settings.SparseViews;
            if (counts == null || counts.Length == 0) return;
            var views = SparseSplits.PlannedViews(plan);
            foreach (var n in counts.Distinct())
            {
                var split = SparseSplits.Build(views.Train, views.Test, n);
                session.WriteText(SparseSplit.RelativePath(split.Name), split.ToJson());
            }
        }

        /// <summary>Parses <c>--views 8</c> or <c>--views 3,6,9</c>; null with the reason otherwise.</summary>
        public static int[] ParseCounts(string text, out string problem)
        {
            problem = null;
            var parts = (text ?? "").Split(',');
            var counts = new List<int>();
            foreach (var part in parts)
            {
                if (!int.TryParse(part.Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out var n) || n < 1)
                {
                    problem = "--views = " + text + ": give the train view counts as whole numbers ≥ 1, e.g. --views 8 or --views 3,6,9.";
                    return null;
                }
                counts.Add(n);
            }
            return counts.ToArray();
        }
    }
}
