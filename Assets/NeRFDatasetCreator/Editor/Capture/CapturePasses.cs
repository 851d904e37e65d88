using System;

namespace NerfDatasetCreator.Editor.Capture
{
    /// <summary>Which images a capture renders per view. Colour is always rendered with the mask: its alpha is the mask.</summary>
    [Flags]
    public enum CapturePasses
    {
        None = 0,
        /// <summary>The lit image, rendered at k×k supersampling; its own alpha is ignored (see Documentation~/capture.md).</summary>
        Color = 1 << 0,
        /// <summary>Coverage of the target's geometry, at the colour resolution: the source of the colour's alpha.</summary>
        Mask = 1 << 1,
        /// <summary>Eye depth (distance along the camera axis) in Unity units, 32-bit float, 0 = no geometry.</summary>
        Depth = 1 << 2,
        /// <summary>Unit geometry normals in Unity's world frame, 32-bit float RGBA, (0,0,0,0) = no geometry.</summary>
        Normal = 1 << 3,
        All = Color | Mask | Depth | Normal,
    }
}
