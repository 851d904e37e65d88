namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-frame keys of a view with exposure and white balance. No loader reads per-frame exposure from a
    /// transforms file (nerfstudio, instant-ngp and gsplat were searched; Documentation~/maintainers/exposure.md), so
    /// the names are ours, in the snake_case of the other per-frame keys.
    /// </summary>
    public static class ExposureKeys
    {
        /// <summary>The view's exposure and white balance in a transforms frame, when <paramref name="exposure"/> modifies its split.</summary>
        internal static void WriteFrame(TransformsFramesText frame, PlannedView v, ExposurePlan exposure)
        {
            if (exposure == null || !exposure.Applies(v.Split)) return;
            var e = exposure.For(v.Split, v.Index);
            frame.NumberKey(Ev, e.Ev);
            frame.TripleKey(WhiteBalance, e.R, e.G, e.B);
        }

        /// <summary>The view's unmodified image's key, when it is written.</summary>
        internal static void WriteFrameFiles(TransformsFramesText frame, PlannedView v) => frame.FileKey(v, DatasetFileKind.CleanColor, CleanPath);

        /// <summary>The view's exposure in stops (a number).</summary>
        public const string Ev = "exposure_ev";

        /// <summary>The view's white-balance gains, a list [r, g, b] of linear multipliers.</summary>
        public const string WhiteBalance = "white_balance";

        /// <summary>The unmodified image, <c>./train/r_7_clean.png</c>, when it is written.</summary>
        public const string CleanPath = "clean_path";
    }
}
