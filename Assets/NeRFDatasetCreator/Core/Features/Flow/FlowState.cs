namespace NerfDatasetCreator
{
    /// <summary>What became of a pixel's surface point at the other time.</summary>
    public enum FlowState : byte
    {
        /// <summary>The pixel shows no target surface: no flow.</summary>
        NoSurface = 0,
        /// <summary>The point is in front of the other camera, inside its image and not hidden: the flow is where it is seen.</summary>
        Visible = 1,
        /// <summary>Inside the other image, but another part of the target is in front of it there (occluded).</summary>
        Hidden = 2,
        /// <summary>Outside the other image, or behind the other camera (flow is still given where it projects).</summary>
        OutsideImage = 3,
    }
}
