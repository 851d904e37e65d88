using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The cameras of a transforms file: nerf_synthetic / this plugin's <c>transforms_&lt;split&gt;.json</c>,
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
        static readonly string[] DistortionKeys = { "k1", "k2", "k3", "k4", "p1", "p2" };

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
            JObject root;
            try
            {
                root = JToken.Parse(text ?? "") as JObject;
            }
            catch (JsonReaderException e)
            {
                throw Fail(sourceName, "", "is not valid JSON: " + e.Message, "Give a transforms file written by Blender, nerfstudio, instant-ngp or this plugin.");
            }
            if (root == null) throw Fail(sourceName, "", "is not a JSON object { … }.", "Give a transforms file.");
            if (IsTrue(root["from_mitsuba"]) || root["normal_mts_args"] != null)
                throw Fail(sourceName + ".from_mitsuba", "true",
                    "marks a Mitsuba export, whose matrices use other camera axes (instant-ngp flips their x and z columns instead).",
                    "Export the cameras in the NeRF (OpenGL) convention, or import its COLMAP model.");

            var warnings = new List<ValidationProblem>();
            var problems = new List<ValidationProblem>();
            var nerfstudio = root["camera_model"] != null || DatasetSplits.Names.Any(s => root[s + "_filenames"] != null);
            var normalisation = placement;
            if (root[BlenderTransformsWriter.SceneNormalisationKey] != null)
            {
                normalisation = SceneNormalisation.FromJson(root[BlenderTransformsWriter.SceneNormalisationKey]);
                if (placement != null && !(placement.Scale.Equals(normalisation.Scale) && placement.Centre.Equals(normalisation.Centre)))
                    warnings.Add(new ValidationProblem(sourceName + ".scene_normalisation", normalisation.ToString(),
                        "is the file's own record and is used instead of the placement given.", "Remove the placement, or the record if it is wrong."));
            }
            var fileSplit = SplitOfFileName(sourceName);
            var splitOfPath = new Dictionary<string, string>(StringComparer.Ordinal);
            foreach (var split in DatasetSplits.Names)
                if (root[split + "_filenames"] is JArray names)
                    foreach (var name in names.Where(n => n.Type == JTokenType.String))
                        splitOfPath[Canonical((string)name)] = split;

            if (!(root["frames"] is JArray frames) || frames.Count == 0)
                throw Fail(sourceName + ".frames", root["frames"] == null ? "missing" : root["frames"].ToString(Formatting.None),
                    "must list at least one frame.", "Give a transforms file with frames.");
            var distortion = new HashSet<string>();
            var cameras = new List<ImportedCamera>();
            for (var i = 0; i < frames.Count; i++)
            {
                var field = sourceName + ".frames[" + i + "]";
                if (!(frames[i] is JObject frame)) { problems.Add(new ValidationProblem(field, frames[i].ToString(Formatting.None), "is not an object.", "Write {\"file_path\": …, \"transform_matrix\": …}.")); continue; }
                var name = frame["file_path"]?.Type == JTokenType.String ? (string)frame["file_path"] : "";
                // instant-ngp reads transform_matrix_start when a frame has one (nerf_loader.cu, rolling shutter).
                var matrixToken = frame["transform_matrix"] ?? frame["transform_matrix_start"];
                if (!TryMatrix(matrixToken, out var c2w))
                {
                    problems.Add(new ValidationProblem(field + ".transform_matrix", matrixToken?.ToString(Formatting.None) ?? "missing", "must be a 4×4 array of numbers.", "Write a 4×4 camera-to-world matrix."));
                    continue;
                }
                var poseProblem = PosePlacement.Problem(c2w);
                if (poseProblem != null) { problems.Add(new ValidationProblem(field + ".transform_matrix", c2w.ToString().Replace("\n", " "), poseProblem, "Write a rigid camera-to-world matrix.")); continue; }
                foreach (var key in DistortionKeys)
                    if (Number(frame, root, key) is double d && d != 0) distortion.Add(key);
                var intrinsics = Intrinsics(frame, root, field, problems);
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

        static ImportedIntrinsics Intrinsics(JObject frame, JObject root, string field, List<ValidationProblem> problems)
        {
            var w = Number(frame, root, "w");
            var h = Number(frame, root, "h");
            var flX = Number(frame, root, "fl_x");
            var flY = Number(frame, root, "fl_y");
            var angleX = Number(frame, root, "camera_angle_x");
            var angleY = Number(frame, root, "camera_angle_y");
            if (w is double width && h is double height && width >= 1 && height >= 1 && width == Math.Floor(width) && height == Math.Floor(height))
            {
                double? fx = flX ?? (angleX is double ax ? 0.5 * width / Math.Tan(0.5 * ax) : (double?)null);
                double? fy = flY ?? (angleY is double ay ? 0.5 * height / Math.Tan(0.5 * ay) : fx);
                if (fx is double x && fy is double y && x > 0 && y > 0 && !double.IsInfinity(x) && !double.IsInfinity(y))
                    return new ImportedIntrinsics(2 * Math.Atan(0.5 * width / x), (int)width, (int)height, x, y,
                        Number(frame, root, "cx") ?? width / 2, Number(frame, root, "cy") ?? height / 2);
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

        /// <summary>A number of the frame, else of the file (nerfstudio and instant-ngp let frames override the shared camera).</summary>
        static double? Number(JObject frame, JObject root, string key)
        {
            var t = frame[key] ?? root[key];
            return t != null && (t.Type == JTokenType.Float || t.Type == JTokenType.Integer) ? (double)t : (double?)null;
        }

        static bool IsTrue(JToken t) => t != null && t.Type == JTokenType.Boolean && (bool)t;

        static bool TryMatrix(JToken token, out Matrix4x4d matrix)
        {
            matrix = Matrix4x4d.Identity;
            if (!(token is JArray rows) || rows.Count != 4) return false;
            var values = new double[16];
            for (var r = 0; r < 4; r++)
            {
                if (!(rows[r] is JArray row) || row.Count != 4) return false;
                for (var c = 0; c < 4; c++)
                {
                    if (row[c].Type != JTokenType.Float && row[c].Type != JTokenType.Integer) return false;
                    values[r * 4 + c] = (double)row[c];
                }
            }
            matrix = Matrix4x4d.FromRowMajor(values);
            return true;
        }

        /// <summary><c>transforms_test.json</c> → <c>test</c>; null for any other name.</summary>
        static string SplitOfFileName(string sourceName)
        {
            var file = Path.GetFileName(sourceName ?? "");
            foreach (var split in DatasetSplits.Names)
                if (string.Equals(file, DatasetLayout.TransformsFileName(split), StringComparison.OrdinalIgnoreCase)) return split;
            return null;
        }

        static string Canonical(string path) => ExportPaths.Normalise(path);

        static InvalidParameterException Fail(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
