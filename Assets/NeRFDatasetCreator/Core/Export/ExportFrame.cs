using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One captured view as every exporter sees it: its split, its image path relative to the dataset root (forward
    /// slashes, WITH extension, e.g. <c>train/r_0.png</c>), its output camera-to-world matrix (Blender world,
    /// OpenGL camera axes, already normalised) and optional depth / mask images. Deliberately independent of the
    /// capture settings and the Blender writer so that the exporters work for a fresh capture and for a converted
    /// dataset alike.
    /// </summary>
    public sealed class ExportFrame
    {
        public ExportFrame(string split, string imagePath, Matrix4x4d cameraToWorld, string depthPath = null, string maskPath = null,
            double? time = null, ValidationProblem unusableDepth = null)
        {
            UnusableDepth = unusableDepth;
            if (string.IsNullOrEmpty(split)) throw new ArgumentException("A frame needs a split (train, val or test).", nameof(split));
            if (string.IsNullOrEmpty(imagePath)) throw new ArgumentException("A frame needs an image path.", nameof(imagePath));
            // nerfstudio and COLMAP use the path as given, so unlike the Blender files it must name the file exactly.
            if (!System.IO.Path.HasExtension(imagePath))
                throw new InvalidParameterException(new[] { new ValidationProblem("file_path", imagePath, "has no extension; exports need the exact file name.", "Pass e.g. train/r_0.png.") });
            if (!cameraToWorld.IsFinite)
                throw new InvalidParameterException(new[] { new ValidationProblem("transform_matrix", cameraToWorld.ToString(), "contains a non-finite number.", "Fix the camera pose.") });
            Split = split;
            ImagePath = ExportPaths.Normalise(imagePath);
            CameraToWorld = cameraToWorld;
            DepthPath = string.IsNullOrEmpty(depthPath) ? null : ExportPaths.Normalise(depthPath);
            MaskPath = string.IsNullOrEmpty(maskPath) ? null : ExportPaths.Normalise(maskPath);
            Time = time.HasValue && !double.IsNaN(time.Value) && !double.IsInfinity(time.Value) ? time : null;
        }

        /// <summary>The frame's <c>time</c> in [0, 1] of a dynamic capture (D-NeRF's key), or null for a still frame.</summary>
        public double? Time { get; }

        /// <summary><c>train</c>, <c>val</c> or <c>test</c>.</summary>
        public string Split { get; }

        /// <summary>Relative to the dataset root, forward slashes, with the extension.</summary>
        public string ImagePath { get; }

        /// <summary>Output c2w: Blender world (+Z up), OpenGL camera axes (looking along −Z), det +1.</summary>
        public Matrix4x4d CameraToWorld { get; }

        /// <summary>16-bit single-channel PNG of z-depth in steps of <see cref="ExportScene.DepthUnitScale"/> output units, 0 = no hit; or null.</summary>
        public string DepthPath { get; }

        /// <summary>
        /// A depth file beside the image that cannot be used (8-bit, another size, truncated, …): its path as the value and
        /// why as the reason; null when there is none or it is usable. <see cref="DepthPath"/> is then null.
        /// </summary>
        public ValidationProblem UnusableDepth { get; }

        /// <summary>8-bit single-channel PNG, black = ignore (nerfstudio's meaning); or null.</summary>
        public string MaskPath { get; }

        /// <summary>Motion blur: <c>transform_matrix_start</c> / <c>_end</c> as the dataset holds them, or null (<see cref="MotionBlurExports"/>).</summary>
        public Matrix4x4d? ShutterStart { get; set; }
        public Matrix4x4d? ShutterEnd { get; set; }

        /// <summary>Motion blur: instant-ngp's <c>rolling_shutter</c> [A, B, C, D] of the frame (its file's, or its own), or null.</summary>
        public double[] RollingShutter { get; set; }

        /// <summary>Why the frame's <c>rolling_shutter</c> is malformed (<see cref="MotionBlurKeys.RollingShutterProblem"/>), or null.</summary>
        public string RollingShutterProblem { get; set; }

        /// <summary>The frame's time keys as the dataset holds them (time_step and camera_id for Dynamic 3D Gaussians), or <see cref="FrameTime.None"/>.</summary>
        public FrameTime Timing { get; set; } = FrameTime.None;

        /// <summary>
        /// Labels: the instance map the frame's <c>instance_path</c> names, relative to the dataset root (inside it), or
        /// null when the frame names none (<see cref="LabelledDataset"/>; never guessed from the image's name).
        /// </summary>
        public string InstancePath { get; set; }

        /// <summary>Camera centre in the output world.</summary>
        public Vector3d Centre => CameraToWorld.Translation;

        /// <summary>Unit viewing direction in the output world: the camera's −Z axis.</summary>
        public Vector3d ViewDirection => -CameraToWorld.Column(2);
    }
}
