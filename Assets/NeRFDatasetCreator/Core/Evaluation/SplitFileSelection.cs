using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>evaluate --split sparse_&lt;n&gt;</c>: scores only the test views a split file lists (<see cref="SparseSplits.Find"/>).
    /// The renders may be of the whole test split (3DGS, nerfstudio and nerf-pytorch render every test view) — the
    /// listed ones are picked from them — or of exactly the listed views, in the file's order (a sparse-view trainer
    /// that rendered only its test list). Anything else is refused with both readings' reasons.
    /// </summary>
    public static class SplitFileSelection
    {
        /// <param name="read">Reads the renders for a list of frame paths (<see cref="RenderFolder.Read"/> with the options' folder and layout).</param>
        public static (EvaluationDataset Dataset, RenderSet Renders) Select(EvaluationDataset full, SparseSplit split, Func<IReadOnlyList<string>, RenderSet> read)
        {
            if (split.Test.Count == 0)
                throw new InvalidParameterException(new[] { new ValidationProblem("--split", split.Name, "lists no test views, so there is nothing to score.", "Capture test views and write the split again (nerf-dataset splits).") });
            var subset = full.Subset(split.Test);
            var listed = subset.Frames.Select(f => f.FilePath).ToList();
            RenderSet all;
            try
            {
                all = read(full.Frames.Select(f => f.FilePath).ToList());
            }
            catch (InvalidParameterException whole)
            {
                try
                {
                    return (subset, read(listed));
                }
                catch (InvalidParameterException)
                {
                    var problems = whole.Problems.ToList();
                    problems.Add(new ValidationProblem("--split", split.Name, "lists " + split.Test.Count + " test views, and the renders are neither of the whole test split (above) nor of just those views in the file's order.",
                        "Render the whole test split, or exactly the views " + SparseSplit.RelativePath(split.Name) + " lists."));
                    throw new InvalidParameterException(problems.ToArray());
                }
            }
            var byFrame = all.Views.ToDictionary(v => v.FrameIndex);
            var views = new List<RenderView>();
            for (var i = 0; i < split.Test.Count; i++)
            {
                var v = byFrame[split.Test[i]];
                views.Add(new RenderView(i, v.FramePath, v.ColourPath) { DepthPath = v.DepthPath, DepthFormat = v.DepthFormat, NormalPath = v.NormalPath, NormalFormat = v.NormalFormat });
            }
            return (subset, new RenderSet(all.Layout, all.Folder, views, all.Notes));
        }

        /// <summary>The note evaluate prints and writes: which views were scored and why.</summary>
        public static string Note(SparseSplit split, int testViews) =>
            "Scored the " + split.Test.Count + " of " + testViews + " test views that " + SparseSplit.RelativePath(split.Name) + " lists (" + split.Rule + ").";
    }
}
