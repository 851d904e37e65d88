using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>A transforms file as read, tolerant of mistakes: what could not be read is null and listed in <see cref="Problems"/>.</summary>
    public sealed class TransformsDocument
    {
        public double? CameraAngleX { get; internal set; }
        public double? CameraAngleY { get; internal set; }
        public int? W { get; internal set; }
        public int? H { get; internal set; }
        public double? IntegerDepthScale { get; internal set; }
        public double? DepthUnitScaleFactor { get; internal set; }
        public List<TransformsFrame> Frames { get; } = new List<TransformsFrame>();

        /// <summary>How many entries <c>frames</c> has (also when they were streamed rather than kept in <see cref="Frames"/>).</summary>
        public int FrameCount { get; internal set; }

        /// <summary>Problems with the document's structure, e.g. "camera_angle_x is missing".</summary>
        public List<string> Problems { get; } = new List<string>();
    }

    /// <summary>One entry of <c>frames</c>.</summary>
    public sealed class TransformsFrame
    {
        /// <summary>The frame's position in <c>frames</c>.</summary>
        public int Index { get; internal set; }

        public string FilePath { get; internal set; }
        public double? Rotation { get; internal set; }

        /// <summary>The matrix when it had 4 rows of 4 numbers (not checked further), else null.</summary>
        public Matrix4x4d? TransformMatrix { get; internal set; }

        /// <summary>Per-frame file keys (<c>depth_path</c>, <c>depth_file_path</c>, <c>normal_path</c>, <c>mask_path</c>) present as strings.</summary>
        public SortedDictionary<string, string> ExtraFiles { get; } = new SortedDictionary<string, string>(System.StringComparer.Ordinal);

        /// <summary>Problems with this frame's structure, e.g. "transform_matrix has 3 rows".</summary>
        public List<string> Problems { get; } = new List<string>();
    }
}
