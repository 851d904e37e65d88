using System;
using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The views of a Blender-format dataset for <see cref="DatasetCheck"/>: every frame of the chosen splits with its
    /// colour image, the extra files its keys name (<c>depth_path</c> or <c>depth_file_path</c>, <c>normal_path</c>,
    /// <c>mask_path</c> — never guessed from file names: nerf_synthetic's own <c>_depth_0000.png</c> are 8-bit
    /// pictures, not depth), its pose, time and depth scale, all as <see cref="DatasetFolder"/> reads them. What cannot
    /// be read is a problem of the "dataset" check.
    /// </summary>
    public static class CheckDatasetReader
    {
        public const string CheckName = "dataset";

        /// <summary>
        /// Output units per depth step when a split names depth files but has no <c>integer_depth_scale</c>: the plugin's
        /// own scale (<see cref="BlenderTransformsWriter.DepthUnitScale"/>), which instant-ngp also assumes for ours.
        /// </summary>
        public const double DefaultDepthScale = BlenderTransformsWriter.DepthUnitScale;

        /// <summary>How far <c>fl_x</c> may be from the focal length <c>camera_angle_x</c> gives, relative (JSON keeps 17 digits; loaders differ on which they read).</summary>
        public const double FocalTolerance = 1e-4;

        public sealed class Result
        {
            public readonly List<CheckView> Views = new List<CheckView>();
            public readonly List<DatasetProblem> Problems = new List<DatasetProblem>();

            /// <summary>camera_angle_x per split (NeRF reads one; a difference is a problem).</summary>
            public double? CameraAngleX;
        }

        public static Result Read(string root, DatasetCheckOptions options)
        {
            var result = new Result();
            var splits = options?.Split == null ? DatasetSplits.Names : new[] { options.Split };
            foreach (var split in splits)
            {
                var file = DatasetLayout.TransformsFileName(split);
                var path = Path.Combine(root, file);
                if (!File.Exists(path))
                {
                    if (options?.Split != null) result.Problems.Add(new DatasetProblem(CheckName, file, -1, "is missing."));
                    continue;
                }
                DatasetSplitFile json;
                try { json = DatasetFolder.ReadSplit(root, split, DatasetReadMode.Strict); }
                catch (Exception e) when (e is SettingsFormatException || e is IOException || e is UnauthorizedAccessException)
                {
                    result.Problems.Add(new DatasetProblem(CheckName, file, -1, "cannot be read: " + e.Message));
                    continue;
                }
                if (!json.IsObject)
                {
                    result.Problems.Add(new DatasetProblem(CheckName, file, -1, "cannot be read: it is not a JSON object { … }."));
                    continue;
                }
                ReadSplit(split, file, json, options?.MaxViews ?? 0, result);
            }
            for (var i = 0; i < result.Views.Count; i++) result.Views[i].Number = i;
            return result;
        }

        static void ReadSplit(string split, string file, DatasetSplitFile json, int maxViews, Result result)
        {
            if (!(json.CameraAngleX is double angle) || !(angle > 0 && angle < Math.PI))
            {
                result.Problems.Add(new DatasetProblem(CheckName, file, -1, "has no camera_angle_x in (0, π); its views cannot be checked."));
                return;
            }
            if (result.CameraAngleX == null) result.CameraAngleX = angle;
            else if (Math.Abs(result.CameraAngleX.Value - angle) > 1e-9)
                result.Problems.Add(new DatasetProblem(CheckName, file, -1, "camera_angle_x " + DatasetCheckResult.Number(angle, "R") +
                    " differs from the other splits' " + DatasetCheckResult.Number(result.CameraAngleX.Value, "R") + "; NeRF reads one for all."));
            var depthScale = json.IntegerDepthScale is double ds && ds > 0 ? ds : DefaultDepthScale;
            // A malformed rolling_shutter (MotionBlurKeys' one rule) fails the check: instant-ngp would train on it.
            if (MotionBlurKeys.RollingShutterProblem(json.Top[MotionBlurKeys.RollingShutter]) is string fileShutter)
                result.Problems.Add(new DatasetProblem(CheckName, file, -1, fileShutter));
            // The lens the loaders read from this file (camera_model, is_fisheye, k1…p2): every projecting check uses it.
            if (json.LensProblems.Count > 0)
            {
                foreach (var p in json.LensProblems) result.Problems.Add(new DatasetProblem(CheckName, file, -1, p.Field + " = " + p.Value + ": " + p.Reason));
                return;
            }
            var lens = json.Lens;
            if (!json.HasFrameList) return;
            var picked = Pick(json.Frames.Count, maxViews);
            foreach (var index in picked)
            {
                var frame = json.Frames[index];
                if (frame.FilePath == null) { result.Problems.Add(new DatasetProblem(CheckName, file, index, "has no file_path.")); continue; }
                if (MotionBlurKeys.RollingShutterProblem(frame.Json?[MotionBlurKeys.RollingShutter]) is string frameShutter)
                    result.Problems.Add(new DatasetProblem(CheckName, file, index, frameShutter));
                var colour = frame.Existing("file_path");
                if (colour == null) { result.Problems.Add(new DatasetProblem(CheckName, frame.FilePath, index, "names no image inside the dataset (looked for the path and the path + \".png\").")); continue; }
                // Every other file the frame names (depth_path, sharp_path, clean_path, any *_path): a key naming a missing
                // file or one outside the dataset is a lost pass, never a view quietly checked without it.
                // One file under two keys (depth_path for instant-ngp, depth_file_path for nerfstudio) is one problem.
                var lostFiles = new HashSet<string>(StringComparer.Ordinal);
                foreach (var key in frame.FileKeys)
                    if (frame.Named(key.Key) is DatasetFile named && named.Problem is string lost && lostFiles.Add(named.Relative))
                        result.Problems.Add(new DatasetProblem(CheckName, frame.FilePath, index, lost + " " + LostFileFix(named)));
                if (!TryPose(frame.TransformMatrix, out var pose, out var why)) { result.Problems.Add(new DatasetProblem(CheckName, file, index, "transform_matrix " + why)); continue; }
                foreach (var poseProblem in DatasetValidator.PoseProblems(pose))
                    result.Problems.Add(new DatasetProblem(CheckName, file, index, poseProblem + (pose.Determinant3x3 < 0 ? " A mirrored rotation is a handedness slip: Unity's Y/Z not swapped, or one camera axis negated." : "")));
                var view = new CheckView
                {
                    Split = split, Frame = index, Source = frame, ColourFile = colour, CameraToWorld = pose, DepthScale = depthScale,
                    DepthFile = frame.Existing("depth_path") ?? frame.Existing("depth_file_path"),
                    NormalFile = frame.Existing("normal_path"),
                    MaskFile = frame.Existing("mask_path"),
                    InstanceFile = frame.Existing(LabelFrameKeys.Instance),
                    SemanticFile = frame.Existing(LabelFrameKeys.Semantic),
                    Time = frame.Time.Time,
                };
                MotionBlurCheck.ReadKeys(frame, view, file, index, result.Problems);
                result.Views.Add(view);
                SetCamera(view, json, angle);
                view.Lens = lens;
            }
        }

        /// <summary>What to do about a file a frame's key names that is missing or outside the dataset.</summary>
        internal static string LostFileFix(DatasetFile file) =>
            file.IsInside
                ? "Restore the file, or capture the dataset again (a frame's " + file.Key + " must name a file that is there)."
                : "Copy the file into the dataset folder and name it relative to it, or capture the dataset again.";

        /// <summary>The camera is completed once the image size is known (<see cref="Complete"/>); the split's keys are kept until then.</summary>
        static void SetCamera(CheckView view, DatasetSplitFile json, double angle)
        {
            view.PendingAngle = angle;
            view.PendingCx = json.Intrinsics.Cx;
            view.PendingCy = json.Intrinsics.Cy;
            view.PendingFlX = json.Intrinsics.FlX;
        }

        /// <summary>Builds the view's camera for an image of <paramref name="width"/>×<paramref name="height"/>; a problem when fl_x disagrees with camera_angle_x.</summary>
        public static DatasetProblem Complete(CheckView view, int width, int height)
        {
            var focal = CheckCamera.FocalOf(width, view.PendingAngle);
            view.Camera = new CheckCamera(view.CameraToWorld, width, height, focal, view.PendingCx ?? width / 2.0, view.PendingCy ?? height / 2.0, view.Lens);
            if (view.PendingFlX is double flX && Math.Abs(flX - focal) > FocalTolerance * focal)
                return new DatasetProblem(CheckName, DatasetLayout.TransformsFileName(view.Split), -1,
                    "fl_x = " + DatasetCheckResult.Number(flX) + " px but camera_angle_x gives " + DatasetCheckResult.Number(focal) +
                    " px for a " + width + "-pixel-wide image; NeRF's loaders read camera_angle_x, instant-ngp fl_x, so they see different cameras.");
            return null;
        }

        static IEnumerable<int> Pick(int count, int max)
        {
            if (max <= 0 || max >= count)
            {
                for (var i = 0; i < count; i++) yield return i;
                yield break;
            }
            for (var k = 0; k < max; k++) yield return (int)((long)k * count / max);
        }

        /// <summary>A pose the checks can project with: 4 rows of 4 finite numbers (rigidity is checked apart, by <see cref="DatasetValidator.PoseProblems"/>).</summary>
        internal static bool TryPose(Matrix4x4d? written, out Matrix4x4d pose, out string why)
        {
            pose = written ?? Matrix4x4d.Identity;
            why = "is not a 4×4 array of numbers.";
            return written.HasValue && written.Value.IsFinite;
        }
    }
}
