namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-frame key of a view with a linear HDR image: <c>hdr_path</c>, <c>./train/r_7_hdr.exr</c>. No Blender-format
    /// loader reads linear colour from a transforms file, so the name is ours, in the snake_case of the other file keys.
    /// </summary>
    public static class HdrKeys
    {
        public const string HdrPath = "hdr_path";

        internal static void WriteFrameFiles(TransformsFramesText frame, PlannedView v) => frame.FileKey(v, DatasetFileKind.HdrExr, HdrPath);
    }
}
