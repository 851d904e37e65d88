namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-frame keys of a transforms file that name a view's id maps, written after <c>mask_path</c> like the other
    /// file keys (paths relative to the transforms file): <c>"instance_path": "./train/r_7_instance_0000.png"</c>.
    /// </summary>
    public static class LabelFrameKeys
    {
        /// <summary>The view's id-map keys in a transforms frame, for the maps it writes.</summary>
        internal static void WriteFrameFiles(TransformsFramesText frame, PlannedView v)
        {
            frame.FileKey(v, DatasetFileKind.InstancePng, Instance);
            frame.FileKey(v, DatasetFileKind.SemanticPng, Semantic);
        }

        public const string Instance = "instance_path";
        public const string Semantic = "semantic_path";
    }
}
