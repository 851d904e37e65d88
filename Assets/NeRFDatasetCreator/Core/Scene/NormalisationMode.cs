namespace NerfDatasetCreator
{
    /// <summary>How the output world is placed relative to the capture target (see Documentation~/exports.md).</summary>
    public enum NormalisationMode
    {
        /// <summary>Unity's world, only relabelled into Blender axes. Off-origin targets break the loaders.</summary>
        None,

        /// <summary>Default: the target's centre moves to the origin; distances are kept (1 Unity unit = 1 output unit).</summary>
        Recentre,

        /// <summary>Recentre and scale by s = 4 / R (R = mean camera distance), so the cameras sit ≈ 4 units out as in nerf_synthetic.</summary>
        NerfSyntheticScale,

        /// <summary>Recentre and scale so the target's bounding sphere gets a chosen radius (s = radius / b).</summary>
        FitTargetRadius,
    }
}
