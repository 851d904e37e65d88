using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Makes a dataset's sparse-view split files: nerf_synthetic's rig (<see cref="NerfSyntheticRig"/>) with 8 views gets
    /// the papers' lists (<see cref="SparseViewLists"/>); every other rig or view count gets <see cref="FarthestViews"/>
    /// and every test view. Written by <c>nerf-dataset splits</c> for any dataset, and by a capture or <c>plan</c> for
    /// the counts of the config's <c>sparseViews</c>; read by <c>evaluate --split sparse_&lt;n&gt;</c>.
    /// </summary>
    public static class SparseSplits
    {
        /// <summary>One view of a split: its <c>file_path</c> and camera centre (output frame).</summary>
        public struct View
        {
            public View(string filePath, Vector3d centre)
            {
                FilePath = filePath;
                Centre = centre;
            }

            public string FilePath { get; }
            public Vector3d Centre { get; }
        }

        /// <summary>The split of <paramref name="views"/> train views (1 ≤ n &lt; train count) for these train and test views.</summary>
        public static SparseSplit Build(IReadOnlyList<View> train, IReadOnlyList<View> test, int views)
        {
            if (views < 1 || views >= train.Count)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("--views", views.ToString(System.Globalization.CultureInfo.InvariantCulture),
                        "must be at least 1 and fewer than the dataset's " + train.Count + " train views (a sparse split leaves views out).",
                        train.Count > 1 ? "Pick a number from 1 to " + (train.Count - 1) + ", e.g. 8." : "Capture more train views."),
                });
            var centres = train.Select(v => v.Centre).ToList();
            if (views == SparseViewLists.DietNerfTrain8.Count && NerfSyntheticRig.Matches(centres, test.Count))
            {
                var paperTest = SparseViewLists.EveryNth(test.Count, SparseViewLists.DietNerfTestSkip);
                return new SparseSplit(views, SparseViewLists.DietNerfRule, SparseViewLists.DietNerfSource,
                    SparseViewLists.DietNerfTrain8, SparseViewLists.DietNerfTrain8.Select(i => train[i].FilePath).ToList(),
                    paperTest, paperTest.Select(i => test[i].FilePath).ToList());
            }
            var chosen = FarthestViews.Select(centres, views);
            var allTest = Enumerable.Range(0, test.Count).ToList();
            return new SparseSplit(views, FarthestViews.Rule, null, chosen, chosen.Select(i => train[i].FilePath).ToList(),
                allTest, allTest.Select(i => test[i].FilePath).ToList());
        }

        /// <summary>A dataset's train and test views as its transforms files hold them (strict read: a broken file is refused naming it).</summary>
        public static (IReadOnlyList<View> Train, IReadOnlyList<View> Test) ReadViews(string root)
        {
            return (Views(root, "train"), Views(root, "test"));
        }

        static IReadOnlyList<View> Views(string root, string split)
        {
            var path = DatasetFolder.SplitPath(root, split);
            if (!File.Exists(path))
            {
                if (split == "test") return new View[0];
                throw new InvalidParameterException(new[] { new ValidationProblem("<dataset>", root, "has no " + DatasetLayout.TransformsFileName(split) + ".", "Pass a Blender-format dataset folder.") });
            }
            DatasetSplitFile doc;
            try { doc = DatasetFolder.ReadSplit(root, split, DatasetReadMode.Strict); }
            catch (SettingsFormatException e) { throw new InvalidParameterException(new[] { new ValidationProblem(DatasetLayout.TransformsFileName(split), path, e.Message, "Fix or regenerate the file.") }); }
            var views = new List<View>();
            foreach (var f in doc.Frames)
            {
                if (f.TransformMatrix == null || f.FilePath == null)
                    throw new InvalidParameterException(new[] { new ValidationProblem(DatasetLayout.TransformsFileName(split) + " frame " + f.Index, path, "has no file_path or transform_matrix.", "Run nerf-dataset validate on the dataset and fix what it reports.") });
                views.Add(new View(f.FilePath, f.TransformMatrix.Value.Translation));
            }
            return views;
        }

        /// <summary>The planned views of a capture or plan, as its transforms files will name them.</summary>
        public static (IReadOnlyList<View> Train, IReadOnlyList<View> Test) PlannedViews(CapturePlan plan) =>
            (plan.ViewsOf(DatasetSplit.Train).Select(v => new View(DatasetLayout.FramePath(DatasetSplit.Train, v.Index), v.TransformMatrix.Translation)).ToList(),
             plan.ViewsOf(DatasetSplit.Test).Select(v => new View(DatasetLayout.FramePath(DatasetSplit.Test, v.Index), v.TransformMatrix.Translation)).ToList());

        /// <summary>The split files named in <paramref name="root"/>/splits, sorted, without the extension (for refusals).</summary>
        public static IReadOnlyList<string> Available(string root)
        {
            var folder = Path.Combine(root, SparseSplit.FolderName);
            if (!Directory.Exists(folder)) return new string[0];
            return Directory.GetFiles(folder, "*.json").Select(Path.GetFileNameWithoutExtension).OrderBy(n => n, FileNameOrder.Instance).ToList();
        }

        /// <summary>
        /// The split file <paramref name="name"/> of the dataset, checked against its transforms files (each index in range,
        /// each file_path the frame's). Refused, naming the files there are, when it does not exist.
        /// </summary>
        public static SparseSplit Find(string root, string name)
        {
            var path = Path.Combine(root, SparseSplit.FolderName, name + ".json");
            if (!File.Exists(path))
            {
                var available = Available(root);
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("--split", name, "is not train, val, test or a split file of the dataset (" +
                        (available.Count == 0 ? "it has no " + SparseSplit.FolderName + "/ files" : SparseSplit.FolderName + "/ holds " + string.Join(", ", available)) + ").",
                        "Write one with nerf-dataset splits " + root + " --views <n>, or pass one of the names listed."),
                });
            }
            var split = SparseSplit.Read(path);
            var views = ReadViews(root);
            Check(path, split.Train, split.TrainFiles, views.Train, "train");
            Check(path, split.Test, split.TestFiles, views.Test, "test");
            return split;
        }

        static void Check(string path, IReadOnlyList<int> ids, IReadOnlyList<string> files, IReadOnlyList<View> views, string split)
        {
            for (var i = 0; i < ids.Count; i++)
                if (ids[i] >= views.Count || !string.Equals(views[ids[i]].FilePath, files[i], StringComparison.Ordinal))
                    throw new InvalidParameterException(new[]
                    {
                        new ValidationProblem("--split", path, split + " index " + ids[i] + " names " + files[i] + ", but " +
                            (ids[i] >= views.Count ? "transforms_" + split + ".json has only " + views.Count + " frames" : "that frame of transforms_" + split + ".json is " + views[ids[i]].FilePath) +
                            ": the file was written for another dataset or before the dataset changed.",
                            "Write it again with nerf-dataset splits <dataset> --views <n> (it refuses to overwrite, so move the old file away first)."),
                    });
        }
    }
}
