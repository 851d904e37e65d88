using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// How many views each split of a plan has. Views are numbered globally in the plan's order — train 0…T−1,
    /// then val, then test — which is the order shard assignment walks.
    /// </summary>
    [Serializable]
    public sealed class ViewCounts
    {
        /// <summary>The split names as the dataset files spell them, in plan order.</summary>
        public static readonly IReadOnlyList<string> SplitNames = DatasetSplits.Names;

        public ViewCounts(int train, int val, int test)
        {
            InvalidParameterException.ThrowIfAny(
                ValidationProblem.OutsideRange("views.train", train, 0, int.MaxValue / 4),
                ValidationProblem.OutsideRange("views.val", val, 0, int.MaxValue / 4),
                ValidationProblem.OutsideRange("views.test", test, 0, int.MaxValue / 4));
            Train = train;
            Val = val;
            Test = test;
        }

        public int Train { get; }
        public int Val { get; }
        public int Test { get; }
        public int Total => Train + Val + Test;

        public int Of(string split)
        {
            switch (split)
            {
                case "train": return Train;
                case "val": return Val;
                case "test": return Test;
                default: throw new ArgumentException("Unknown split '" + split + "': use train, val or test.", nameof(split));
            }
        }

        /// <summary>The global index of the split's first view.</summary>
        public int OffsetOf(string split)
        {
            switch (split)
            {
                case "train": return 0;
                case "val": return Train;
                case "test": return Train + Val;
                default: throw new ArgumentException("Unknown split '" + split + "': use train, val or test.", nameof(split));
            }
        }

        public override string ToString() => string.Format(CultureInfo.InvariantCulture, "train {0}, val {1}, test {2}", Train, Val, Test);
    }
}
