using System;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Which images a capture renders per view.</summary>
    [Flags]
    public enum CapturePasses
    {
        None = 0,
        /// <summary>
        /// The lit image, rendered twice at k×k supersampling, over black and over white; alpha and straight colour are
        /// solved from the pair (difference matting). The shaders' own alpha output is ignored (Documentation~/capture.md).
        /// </summary>
        Color = 1 << 0,
        /// <summary>Coverage of the target's geometry by the mask shader, at the colour resolution: the mask images.</summary>
        Mask = 1 << 1,
        /// <summary>Eye depth (distance along the camera axis) in Unity units, 32-bit float, 0 = no geometry.</summary>
        Depth = 1 << 2,
        /// <summary>Unit geometry normals in Unity's world frame, 32-bit float RGBA, (0,0,0,0) = no geometry.</summary>
        Normal = 1 << 3,
        /// <summary>
        /// Instance and class ids of the renderer covering each sample, at the colour resolution: 4 bytes per sample
        /// (instance id low, high byte; class id low, high byte), 0 = background. Drawn only when the capture is given
        /// ids (<see cref="CaptureOptions.Labels"/>); not part of <see cref="All"/>.
        /// </summary>
        Labels = 1 << 4,
        All = Color | Mask | Depth | Normal,
    }
}
