namespace NerfDatasetCreator
{
    /// <summary>The three splits of a Blender-format dataset, in the order the preview draws and lists them.</summary>
    public enum PreviewSplit
    {
        Train = 0,
        Val = 1,
        Test = 2,
    }
}
