namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-frame keys of a transforms file that name a view's id maps, written after <c>mask_path</c> like the other
    /// file keys (paths relative to the transforms file): <c>"instance_path": "./train/r_7_instance_0000.png"</c>.
    /// </summary>
    public static class LabelFrameKeys
    {
        public const string Instance = "instance_path";
        public const string Semantic = "semantic_path";
    }
}
