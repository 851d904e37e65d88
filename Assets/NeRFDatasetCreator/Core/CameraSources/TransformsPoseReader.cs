using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The cameras of a transforms file (read by <see cref="DatasetFolder"/>, lenient): nerf_synthetic / this plugin's <c>transforms_&lt;split&gt;.json</c>,
    /// nerfstudio's <c>transforms.json</c> and instant-ngp's. All three hold OpenGL camera-to-world matrices
    /// (x right, y up, looking along −z) under <c>transform_matrix</c>: instant-ngp reads them with the same flip of
    /// the y and z columns for every file (nerf_loader.h <c>nerf_matrix_to_ngp</c>), and its colmap2nerf.py writes
    /// them that way (c2w[0:3,2] *= −1; c2w[0:3,1] *= −1). Only Mitsuba-exported files (<c>from_mitsuba</c> /
    /// <c>normal_mts_args</c>) use other camera axes there, and they are refused. What tools do to the WORLD before
    /// writing (colmap2nerf's reorientation, recentring and scaling to a mean camera distance of 4) is not recorded
    /// in the file, so such cameras are placed in the file's own world; this plugin's files record theirs under
    /// <c>scene_normalisation</c>, which is undone. Intrinsics: <c>fl_x</c>/<c>fl_y</c>/<c>cx</c>/<c>cy</c>/<c>w</c>/<c>h</c>
    /// at the top or per frame (per frame wins, as in nerfstudio and instant-ngp), else <c>camera_angle_x</c>.
    /// </summary>
    public static class TransformsPoseReader
    {
        public static ImportedPoses ReadFile(string path, SceneNormalisation placement = null)
        {
            string text;
            try { text = FileOps.ReadText(path); } // refuses a file beyond FileOps.MaxTextBytes by its size, naming it
            catch (FileTooLargeException e) { throw Fail("path", path, e.Reason, "Give the path of a transforms JSON file."); }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException || e is NotSupportedException)
            {
                throw Fail("path", path, "cannot be read: " + e.Message, "Give the path of a transforms JSON file.");
            }
            return Read(text, path, placement);
        }

        /// <param name="sourceName">The file's name or path: <c>transforms_test.json</c> puts its frames in the test split.</param>
        /// <param name="placement">The normalisation the matrices are in when the file records none (null: the file's world is the output world).</param>
        public static ImportedPoses Read(string text, string sourceName, SceneNormalisation placement = null)
        {
            DatasetSplitFile root;
            try
            {
                // Lenient: any tool's file (nerfstudio's has no camera_angle_x); what the cameras need is checked below.
                root = DatasetFolder.Read(text, sourceName, DatasetReadMode.Lenient);
            }
            catch (SettingsFormatException e)
            {
                throw Fail(sourceName, "", "is not valid JSON: line " + e.Line + ", column " + e.Column + ": " + e.Detail, "Give a transforms file written by Blender, nerfstudio, instant-ngp or this plugin.");
            }
            if (!root.IsObject) throw Fail(sourceName, "", "is not a JSON object { … }.", "Give a transforms file.");
            if (root.IsTrue("from_mitsuba") || root.Has("normal_mts_args"))
                throw Fail(sourceName + ".from_mitsuba", "true",
                    "marks a Mitsuba export, whose matrices use other camera axes (instant-ngp flips their x and z columns instead).",
                    "Export the cameras in the NeRF (OpenGL) convention, or import its COLMAP model.");

            var warnings = new List<ValidationProblem>();
            var problems = new List<ValidationProblem>();
            var nerfstudio = root.Has("camera_model") || DatasetSplits.Names.Any(s => root.Has(s + "_filenames"));
            var normalisation = placement;
            if (root.Has(BlenderTransformsWriter.SceneNormalisationKey))
            {
                normalisation = SceneNormalisation.FromJson(root.Value(BlenderTransformsWriter.SceneNormalisationKey));
                if (placement != null && !(placement.Scale.Equals(normalisation.Scale) && placement.Centre.Equals(normalisation.Centre)))
                    warnings.Add(new ValidationProblem(sourceName + ".scene_normalisation", normalisation.ToString(),
                        "is the file's own record and is used instead of the placement given.", "Remove the placement, or the record if it is wrong."));
            }
            var fileSplit = DatasetFolder.SplitOfFileName(sourceName);
            var splitOfPath = new Dictionary<string, string>(StringComparer.Ordinal);
            foreach (var split in DatasetSplits.Names)
                foreach (var name in root.Strings(split + "_filenames"))
                    splitOfPath[Canonical(name)] = split;

            if (!root.HasFrameList || root.FrameCount == 0)
                throw Fail(sourceName + ".frames", root.HasFrameList ? "[]" : root.FramesText,
                    "must list at least one frame.", "Give a transforms file with frames.");
            var distortion = new HashSet<string>();
            var cameras = new List<ImportedCamera>();
            foreach (var frame in root.Frames)
            {
                var field = sourceName + ".frames[" + frame.Index + "]";
                if (!frame.IsObject) { problems.Add(new ValidationProblem(field, frame.NotObjectText, "is not an object.", "Write {\"file_path\": …, \"transform_matrix\": …}.")); continue; }
                var name = frame.FilePath ?? "";
                // instant-ngp reads transform_matrix_start when a frame has one (nerf_loader.cu, rolling shutter).
                var matrixText = frame.Text("transform_matrix");
                var written = matrixText != null ? frame.TransformMatrix : frame.Shutter.Start;
                if (matrixText == null) matrixText = frame.Text(MotionBlurKeys.Start);
                if (!(written is Matrix4x4d c2w))
                {
                    problems.Add(new ValidationProblem(field + ".transform_matrix", matrixText ?? "missing", "must be a 4×4 array of numbers.", "Write a 4×4 camera-to-world matrix."));
                    continue;
                }
                var poseProblem = PosePlacement.Problem(c2w);
                if (poseProblem != null) { problems.Add(new ValidationProblem(field + ".transform_matrix", c2w.ToString().Replace("\n", " "), poseProblem, "Write a rigid camera-to-world matrix.")); continue; }
                distortion.UnionWith(frame.DistortionKeys);
                var intrinsics = Intrinsics(frame.Intrinsics, root.Intrinsics, field, problems);
                var split = splitOfPath.TryGetValue(Canonical(name), out var s) ? s : fileSplit ?? (nerfstudio ? null : PosePlacement.SplitFromName(name));
                cameras.Add(new ImportedCamera(name, split, c2w, PosePlacement.ToUnityPose(c2w, normalisation), intrinsics));
            }
            InvalidParameterException.ThrowIfAny(problems.ToArray());
            if (distortion.Count > 0)
                warnings.Add(new ValidationProblem(sourceName, string.Join(", ", distortion.OrderBy(k => k, StringComparer.Ordinal)),
                    "describes lens distortion, which a Unity camera does not reproduce: the poses and pinhole intrinsics are imported, the distortion is not.",
                    "Compare against undistorted images."));
            return new ImportedPoses(sourceName, nerfstudio ? "nerfstudio" : "transforms", cameras, normalisation, warnings);
        }

        /// <summary>The camera of a frame: its own keys first, then the file's (nerfstudio and instant-ngp let frames override the shared camera).</summary>
        static ImportedIntrinsics Intrinsics(FrameIntrinsics frame, FrameIntrinsics root, string field, List<ValidationProblem> problems)
        {
            var w = frame.W ?? root.W;
            var h = frame.H ?? root.H;
            var flX = frame.FlX ?? root.FlX;
            var flY = frame.FlY ?? root.FlY;
            var angleX = frame.AngleX ?? root.AngleX;
            var angleY = frame.AngleY ?? root.AngleY;
            if (w is double width && h is double height && width >= 1 && height >= 1 && width == Math.Floor(width) && height == Math.Floor(height))
            {
                double? fx = flX ?? (angleX is double ax ? 0.5 * width / Math.Tan(0.5 * ax) : (double?)null);
                double? fy = flY ?? (angleY is double ay ? 0.5 * height / Math.Tan(0.5 * ay) : fx);
                if (fx is double x && fy is double y && x > 0 && y > 0 && !double.IsInfinity(x) && !double.IsInfinity(y))
                    return new ImportedIntrinsics(2 * Math.Atan(0.5 * width / x), (int)width, (int)height, x, y,
                        frame.Cx ?? root.Cx ?? width / 2, frame.Cy ?? root.Cy ?? height / 2);
            }
            if (angleX is double angle)
            {
                if (angle > 0 && angle < Math.PI) return ImportedIntrinsics.AngleOnly(angle);
                problems.Add(new ValidationProblem(field + ".camera_angle_x", ValidationProblem.Format(angle), "must be the horizontal field of view in radians, in (0, π).", "Fix the file."));
                return null;
            }
            problems.Add(new ValidationProblem(field, "no intrinsics", "has neither fl_x with w and h nor camera_angle_x.", "Write camera_angle_x, or fl_x, fl_y, cx, cy, w, h."));
            return null;
        }

        static string Canonical(string path) => ExportPaths.Normalise(path);

        static InvalidParameterException Fail(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
