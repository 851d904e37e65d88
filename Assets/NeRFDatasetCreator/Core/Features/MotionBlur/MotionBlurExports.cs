using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What <c>convert</c> does with a motion-blurred dataset. <b>instant-ngp</b> reads the blur: each frame's
    /// <c>transform_matrix_start</c> / <c>_end</c> and the file's <c>rolling_shutter</c> are carried as they are
    /// (src/nerf_loader.cu; <see cref="MotionBlurKeys"/>). <b>nerfstudio</b>, <b>COLMAP</b> (and 3DGS, which reads it) and
    /// <b>Dynamic 3D Gaussians</b> hold one pose per image: the keys are dropped with a warning, since those trainers
    /// would fit the blurred images as if they were sharp at the mid pose.
    /// </summary>
    public static class MotionBlurExports
    {
        /// <summary>Carries a frame's motion keys (<see cref="MotionBlurKeys.Read"/>) into <paramref name="frame"/>: finite shutter poses and the rolling shutter.</summary>
        public static void Read(FrameShutter shutter, ExportFrame frame)
        {
            if (shutter.Start is Matrix4x4d start && start.IsFinite) frame.ShutterStart = start;
            if (shutter.End is Matrix4x4d end && end.IsFinite) frame.ShutterEnd = end;
            if (shutter.RollingShutter != null) frame.RollingShutter = shutter.RollingShutter;
            frame.RollingShutterProblem = shutter.RollingShutterProblem;
        }

        /// <summary>
        /// The refusal of <c>--to ngp</c>, which carries <c>rolling_shutter</c>, when a frame's is malformed (before
        /// anything is written: the export used to pad it with zeros or drop it); null otherwise.
        /// </summary>
        public static ValidationProblem Refusal(ExportScene scene, ExportTarget target)
        {
            if (target != ExportTarget.Ngp) return null;
            var frame = scene.Frames.FirstOrDefault(f => f.RollingShutterProblem != null);
            if (frame == null) return null;
            return new ValidationProblem("--to ngp", frame.ImagePath, frame.RollingShutterProblem,
                "Write rolling_shutter as [0, 0, ρ, 1 − ρ] (ρ the readout fraction; [0, 0, 0, 1] for a global shutter) or remove it — see Documentation~/motion-blur.md.");
        }

        static bool Blurred(ExportScene scene) => scene.Frames.Any(f => f.ShutterStart != null || f.ShutterEnd != null);

        /// <summary>The converter's warnings for <paramref name="target"/>: <see cref="Warning"/>'s, if any.</summary>
        public static IEnumerable<ValidationProblem> Warnings(ExportScene scene, ExportTarget target)
        {
            var warning = Warning(scene, target);
            if (warning != null) yield return warning;
        }

        /// <summary>The warning for a target that cannot hold the blur, or null.</summary>
        public static ValidationProblem Warning(ExportScene scene, ExportTarget target)
        {
            if (target == ExportTarget.Ngp || !Blurred(scene)) return null;
            return new ValidationProblem("transform_matrix_start/_end", "per-frame shutter poses",
                "are dropped: " + ExportTargets.Name(target) + "'s format holds one pose per image, so its trainers fit the motion-blurred images as if they were sharp at transform_matrix (the mid pose).",
                "Train on the blur with instant-ngp (convert --to ngp carries the keys) or a deblurring method that reads start/end poses; or train on the sharp images (sharp_path) — see Documentation~/motion-blur.md.");
        }

        public static void AddToNgpFrame(JObject json, ExportFrame f)
        {
            if (f.ShutterStart != null) json[MotionBlurKeys.Start] = ExportJson.Matrix(f.ShutterStart.Value);
            if (f.ShutterEnd != null) json[MotionBlurKeys.End] = ExportJson.Matrix(f.ShutterEnd.Value);
        }

        /// <summary>The file's <c>rolling_shutter</c>, from its train frames (this plugin writes one per dataset).</summary>
        public static void AddToNgpFile(JObject json, IReadOnlyList<ExportFrame> train)
        {
            var first = train.FirstOrDefault(f => f.RollingShutter != null);
            if (first == null) return;
            json[MotionBlurKeys.RollingShutter] = new JArray(first.RollingShutter.Select(v => (object)v).ToArray());
        }
    }
}
