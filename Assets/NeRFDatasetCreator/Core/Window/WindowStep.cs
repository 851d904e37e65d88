namespace NerfDatasetCreator
{
    /// <summary>The window's steps, in the order of the work; every setting belongs to exactly one.</summary>
    public enum WindowStep
    {
        Target = 1,
        Camera = 2,
        Rig = 3,
        Outputs = 4,
        OutputFolder = 5,
        Create = 6,
    }
}
