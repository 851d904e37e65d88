namespace NerfDatasetCreator.Editor
{
    /// <summary>What the capture camera sees. Both modes render copies in an editor preview scene; the user's scene is never modified.</summary>
    public enum CaptureIsolation
    {
        /// <summary>A copy of the target and its children only, lit by copies of the scene's enabled lights (object datasets).</summary>
        TargetOnly = 0,
        /// <summary>Copies of every root object of every loaded scene (scene-level datasets; the mask then covers all geometry).</summary>
        WholeScene = 1,
    }
}
