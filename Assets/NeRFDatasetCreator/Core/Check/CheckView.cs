namespace NerfDatasetCreator
{
    /// <summary>
    /// One frame of a transforms file as the check sees it: a view over its <see cref="DatasetFrame"/> with the files the
    /// checks open (relative to the dataset, null when absent), the camera once the image size is known, and time.
    /// </summary>
    public sealed class CheckView
    {
        public string Split;

        /// <summary>The frame's index in its transforms file's <c>frames</c>.</summary>
        public int Frame;

        /// <summary>The frame as <see cref="DatasetFolder"/> read it: the features' keys and every file its keys name.</summary>
        public DatasetFrame Source;

        /// <summary>The colour image as <c>file_path</c> resolves (with ".png" appended when extensionless).</summary>
        public string ColourFile;
        public string DepthFile, NormalFile, MaskFile;

        /// <summary>The id maps named by <c>instance_path</c> / <c>semantic_path</c> (Documentation~/labels.md), or null.</summary>
        public string InstanceFile, SemanticFile;

        /// <summary>
        /// Motion blur: the blurred image <c>file_path</c> names, when the frame also names its sharp image
        /// (<c>sharp_path</c>), which is then <see cref="ColourFile"/> — the image the alpha checks compare with the mask
        /// and depth, both at the mid pose. Null without blur.
        /// </summary>
        public string BlurredFile;

        /// <summary>The image <c>file_path</c> names: the blurred one with motion blur, <see cref="ColourFile"/> otherwise.</summary>
        public string FrameImageFile => BlurredFile ?? ColourFile;

        /// <summary>Motion blur: <c>transform_matrix_start</c> and <c>_end</c> (each null when absent).</summary>
        public Matrix4x4d? ShutterStart, ShutterEnd;

        /// <summary>instant-ngp's <c>rolling_shutter</c> [A, B, C, D] of the frame's file, or null.</summary>
        public double[] RollingShutter;

        /// <summary>Set once the colour image's size is known.</summary>
        public CheckCamera Camera;

        public Matrix4x4d CameraToWorld;

        /// <summary>The frame's <c>time</c> (dynamic datasets), or null.</summary>
        public double? Time;

        /// <summary>The lens of the frame's transforms file (<see cref="TransformsLens"/>), or null for a pinhole.</summary>
        public LensDistortion Lens;

        /// <summary>Output units per step of the depth PNG (<c>integer_depth_scale</c>).</summary>
        public double DepthScale;

        // The split's intrinsics keys, until the image size is known (CheckDatasetReader.Complete).
        internal double PendingAngle;
        internal double? PendingCx, PendingCy, PendingFlX;

        /// <summary>Position in the checked list.</summary>
        public int Number;

        public string Name => "./" + Split + "/" + System.IO.Path.GetFileName(ColourFile);
    }
}
