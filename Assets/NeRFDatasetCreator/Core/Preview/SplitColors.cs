using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The colours that mark each split in the Scene-view preview and in the window's legend. They come from the
    /// Okabe–Ito palette, chosen to stay distinguishable for the common colour-vision deficiencies and against
    /// both the light and the dark Scene-view background: sky blue, orange and reddish purple.
    /// </summary>
    public static class SplitColors
    {
        /// <summary>Okabe–Ito "sky blue" (86, 180, 233).</summary>
        public static readonly RgbaColor Train = RgbaColor.FromBytes(86, 180, 233);

        /// <summary>Okabe–Ito "orange" (230, 159, 0).</summary>
        public static readonly RgbaColor Val = RgbaColor.FromBytes(230, 159, 0);

        /// <summary>Okabe–Ito "reddish purple" (204, 121, 167).</summary>
        public static readonly RgbaColor Test = RgbaColor.FromBytes(204, 121, 167);

        /// <summary>The target's bounds and the distance sphere: neutral, so they never read as a split.</summary>
        public static readonly RgbaColor Guides = new RgbaColor(0.85f, 0.85f, 0.85f, 0.6f);

        public static RgbaColor Of(PreviewSplit split)
        {
            switch (split)
            {
                case PreviewSplit.Train: return Train;
                case PreviewSplit.Val: return Val;
                case PreviewSplit.Test: return Test;
                default: throw new ArgumentOutOfRangeException(nameof(split), split, "Not a dataset split.");
            }
        }

        /// <summary>The split's name as the dataset files spell it: "train", "val", "test".</summary>
        public static string NameOf(PreviewSplit split)
        {
            switch (split)
            {
                case PreviewSplit.Train: return "train";
                case PreviewSplit.Val: return "val";
                case PreviewSplit.Test: return "test";
                default: throw new ArgumentOutOfRangeException(nameof(split), split, "Not a dataset split.");
            }
        }
    }
}
