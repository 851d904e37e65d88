using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>The three splits of a Blender-format dataset, in the order they are planned and written.</summary>
    public enum DatasetSplit
    {
        Train = 0,
        Val = 1,
        Test = 2,
    }

    /// <summary>
    /// The one source of split names: lowercase everywhere (folders, <c>file_path</c>, file names, settings keys).
    /// The original plugin wrote images to <c>Train/</c> while its JSON said <c>./train/</c>, which breaks on
    /// case-sensitive file systems.
    /// </summary>
    public static class DatasetSplits
    {
        public static readonly IReadOnlyList<DatasetSplit> All = new[] { DatasetSplit.Train, DatasetSplit.Val, DatasetSplit.Test };

        /// <summary>The names of <see cref="All"/>, in the same order: "train", "val", "test".</summary>
        public static readonly IReadOnlyList<string> Names = new[] { Name(DatasetSplit.Train), Name(DatasetSplit.Val), Name(DatasetSplit.Test) };

        public static string Name(DatasetSplit split)
        {
            switch (split)
            {
                case DatasetSplit.Train: return "train";
                case DatasetSplit.Val: return "val";
                case DatasetSplit.Test: return "test";
                default: throw new ArgumentOutOfRangeException(nameof(split), split, "not a dataset split");
            }
        }

        public static bool TryParse(string name, out DatasetSplit split)
        {
            foreach (var s in All)
                if (string.Equals(Name(s), name, StringComparison.Ordinal))
                {
                    split = s;
                    return true;
                }
            split = DatasetSplit.Train;
            return false;
        }
    }
}
