namespace NerfDatasetCreator
{
    /// <summary>The window's steps, in the order of the work; every setting belongs to exactly one.</summary>
    public enum WindowStep
    {
        Target = 1,
        Camera = 2,
        Rig = 3,
        Time = 4,
        Outputs = 5,
        OutputFolder = 6,
        Create = 7,
    }
}
