using System;
using System.Collections.Generic;
using System.IO;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The views of a Blender-format dataset for <see cref="DatasetCheck"/>: every frame of the chosen splits with its
    /// colour image, the extra files its keys name (<c>depth_path</c> or <c>depth_file_path</c>, <c>normal_path</c>,
    /// <c>mask_path</c> — never guessed from file names: nerf_synthetic's own <c>_depth_0000.png</c> are 8-bit
    /// pictures, not depth), its pose, time and depth scale. What cannot be read is a problem of the "dataset" check.
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
            public readonly List<DatasetCheckProblem> Problems = new List<DatasetCheckProblem>();

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
                    if (options?.Split != null) result.Problems.Add(new DatasetCheckProblem(CheckName, file, -1, "is missing."));
                    continue;
                }
                JObject json;
                try { json = JObject.Parse(File.ReadAllText(path)); }
                catch (Exception e) when (e is JsonException || e is IOException || e is UnauthorizedAccessException)
                {
                    result.Problems.Add(new DatasetCheckProblem(CheckName, file, -1, "cannot be read: " + e.Message));
                    continue;
                }
                ReadSplit(root, split, file, json, options?.MaxViews ?? 0, result);
            }
            for (var i = 0; i < result.Views.Count; i++) result.Views[i].Number = i;
            return result;
        }

        static void ReadSplit(string root, string split, string file, JObject json, int maxViews, Result result)
        {
            if (!JsonValues.TryNumber(json["camera_angle_x"], out var angle) || !(angle > 0 && angle < Math.PI))
            {
                result.Problems.Add(new DatasetCheckProblem(CheckName, file, -1, "has no camera_angle_x in (0, π); its views cannot be checked."));
                return;
            }
            if (result.CameraAngleX == null) result.CameraAngleX = angle;
            else if (Math.Abs(result.CameraAngleX.Value - angle) > 1e-9)
                result.Problems.Add(new DatasetCheckProblem(CheckName, file, -1, "camera_angle_x " + DatasetCheckResult.Number(angle, "R") +
                    " differs from the other splits' " + DatasetCheckResult.Number(result.CameraAngleX.Value, "R") + "; NeRF reads one for all."));
            var depthScale = JsonValues.TryNumber(json["integer_depth_scale"], out var ds) && ds > 0 ? ds : DefaultDepthScale;
            // The lens the loaders read from this file (camera_model, is_fisheye, k1…p2): every projecting check uses it.
            var lensProblems = new List<ValidationProblem>();
            var lens = TransformsLens.Read(json, file, lensProblems);
            if (lensProblems.Count > 0)
            {
                foreach (var p in lensProblems) result.Problems.Add(new DatasetCheckProblem(CheckName, file, -1, p.Field + " = " + p.Value + ": " + p.Reason));
                return;
            }
            if (!(json["frames"] is JArray frames)) return;
            var picked = Pick(frames.Count, maxViews);
            foreach (var index in picked)
            {
                var frame = frames[index] as JObject;
                var filePath = frame?["file_path"]?.Type == JTokenType.String ? (string)frame["file_path"] : null;
                if (filePath == null) { result.Problems.Add(new DatasetCheckProblem(CheckName, file, index, "has no file_path.")); continue; }
                var colour = Resolve(root, filePath, true);
                if (colour == null) { result.Problems.Add(new DatasetCheckProblem(CheckName, filePath, index, "names no image inside the dataset (looked for the path and the path + \".png\").")); continue; }
                if (!TryPose(frame["transform_matrix"], out var pose, out var why)) { result.Problems.Add(new DatasetCheckProblem(CheckName, file, index, "transform_matrix " + why)); continue; }
                foreach (var poseProblem in DatasetValidator.PoseProblems(pose))
                    result.Problems.Add(new DatasetCheckProblem(CheckName, file, index, poseProblem + (pose.Determinant3x3 < 0 ? " A mirrored rotation is a handedness slip: Unity's Y/Z not swapped, or one camera axis negated." : "")));
                var view = new CheckView
                {
                    Split = split, Frame = index, ColourFile = colour, CameraToWorld = pose, DepthScale = depthScale,
                    DepthFile = Extra(root, frame, "depth_path") ?? Extra(root, frame, "depth_file_path"),
                    NormalFile = Extra(root, frame, "normal_path"),
                    MaskFile = Extra(root, frame, "mask_path"),
                    InstanceFile = Extra(root, frame, LabelFrameKeys.Instance),
                    SemanticFile = Extra(root, frame, LabelFrameKeys.Semantic),
                };
                if (JsonValues.TryNumber(frame[TimeKeys.Time], out var t)) view.Time = t;
                MotionBlurCheck.ReadKeys(root, json, frame, view, file, index, result.Problems);
                result.Views.Add(view);
                SetCamera(view, json, angle);
                view.Lens = lens;
            }
        }

        /// <summary>The camera is completed once the image size is known (<see cref="Complete"/>); the split's keys are kept until then.</summary>
        static void SetCamera(CheckView view, JObject json, double angle)
        {
            view.PendingAngle = angle;
            view.PendingCx = JsonValues.TryNumber(json["cx"], out var cx) ? cx : (double?)null;
            view.PendingCy = JsonValues.TryNumber(json["cy"], out var cy) ? cy : (double?)null;
            view.PendingFlX = JsonValues.TryNumber(json["fl_x"], out var fx) ? fx : (double?)null;
        }

        /// <summary>Builds the view's camera for an image of <paramref name="width"/>×<paramref name="height"/>; a problem when fl_x disagrees with camera_angle_x.</summary>
        public static DatasetCheckProblem Complete(CheckView view, int width, int height)
        {
            var focal = CheckCamera.FocalOf(width, view.PendingAngle);
            view.Camera = new CheckCamera(view.CameraToWorld, width, height, focal, view.PendingCx ?? width / 2.0, view.PendingCy ?? height / 2.0, view.Lens);
            if (view.PendingFlX is double flX && Math.Abs(flX - focal) > FocalTolerance * focal)
                return new DatasetCheckProblem(CheckName, DatasetLayout.TransformsFileName(view.Split), -1,
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

        internal static string Extra(string root, JObject frame, string key) =>
            frame[key]?.Type == JTokenType.String ? Resolve(root, (string)frame[key], false) : null;

        /// <summary>The dataset-relative path of an existing file inside the dataset, or null.</summary>
        static string Resolve(string root, string filePath, bool appendPng)
        {
            var relative = ExportPaths.Normalise(filePath);
            if (PathSafety.Inside(root, relative, out _) == null) return null;
            if (File.Exists(Path.Combine(root, relative)) && Path.HasExtension(relative)) return relative;
            return appendPng && File.Exists(Path.Combine(root, relative + ".png")) ? relative + ".png" : null;
        }

        internal static bool TryPose(JToken token, out Matrix4x4d pose, out string why)
        {
            pose = Matrix4x4d.Identity;
            why = "is not a 4×4 array of numbers.";
            if (!(token is JArray rows) || rows.Count != 4) return false;
            var values = new double[16];
            for (var r = 0; r < 4; r++)
            {
                if (!(rows[r] is JArray row) || row.Count != 4) return false;
                for (var c = 0; c < 4; c++)
                    if (!JsonValues.TryNumber(row[c], out values[r * 4 + c]) || double.IsNaN(values[r * 4 + c]) || double.IsInfinity(values[r * 4 + c]))
                        return false;
            }
            pose = Matrix4x4d.FromRowMajor(values);
            return true;
        }
    }
}
