using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The keys motion blur adds to the transforms files. Per frame: <c>transform_matrix_start</c> and
    /// <c>transform_matrix_end</c> — instant-ngp's (NVlabs/instant-ngp src/nerf_loader.cu, where each frame's
    /// <c>jsonmatrix_start</c> / <c>jsonmatrix_end</c> fall back to <c>transform_matrix</c>) — the content times the
    /// shutter opens and closes (dynamic captures, this plugin's), and <c>sharp_path</c>. At the top:
    /// <c>rolling_shutter</c> [A, B, C, D] (instant-ngp's <c>read_lens</c>; without it instant-ngp trains every pixel at the
    /// start pose, t = 0) and this plugin's <c>motion_blur</c> record.
    /// </summary>
    public static class MotionBlurKeys
    {
        /// <summary>
        /// The view's shutter keys in a transforms frame — instant-ngp's transform_matrix_start / _end
        /// (src/nerf_loader.cu reads them per frame), and the content times — for a view with motion.
        /// </summary>
        internal static void WriteFrame(TransformsFramesText frame, PlannedView v)
        {
            var motion = v.Motion;
            if (motion == null) return;
            Matrix(frame, Start, motion.StartMatrix, v);
            Matrix(frame, End, motion.EndMatrix, v);
            if (motion.OpenSeconds.HasValue && motion.CloseSeconds.HasValue)
            {
                frame.NumberKey(OpenSeconds, motion.OpenSeconds.Value);
                frame.NumberKey(CloseSeconds, motion.CloseSeconds.Value);
            }
        }

        /// <summary>The view's sharp image's key, when it is written.</summary>
        internal static void WriteFrameFiles(TransformsFramesText frame, PlannedView v) => frame.FileKey(v, DatasetFileKind.SharpPng, SharpPath);

        static void Matrix(TransformsFramesText frame, string name, Matrix4x4d m, PlannedView v)
        {
            if (!m.IsFinite)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(DatasetSplits.Name(v.Split) + "[" + v.Index + "]." + name, m.ToString(),
                        "is not finite; JSON cannot hold it.", "Check the motion blur settings that moved this camera."),
                });
            frame.MatrixKey(name, m);
        }

        public const string Start = "transform_matrix_start";
        public const string End = "transform_matrix_end";
        public const string OpenSeconds = "shutter_open_seconds";
        public const string CloseSeconds = "shutter_close_seconds";
        public const string SharpPath = "sharp_path";
        public const string RollingShutter = "rolling_shutter";
        public const string Record = "motion_blur";

        /// <summary>
        /// Reads a frame's shutter poses and its (or its file's, <paramref name="top"/>) rolling shutter; <see cref="DatasetFolder"/>
        /// calls it for every frame. <c>sharp_path</c> is a file key, resolved with the frame's other files.
        /// </summary>
        public static FrameShutter Read(JObject top, JObject frame)
        {
            if (frame == null) return FrameShutter.None;
            var start = frame[Start];
            var end = frame[End];
            var rs = frame[RollingShutter] ?? top?[RollingShutter];
            if (rs != null && rs.Type == JTokenType.Null) rs = null;
            if (start == null && end == null && rs == null) return FrameShutter.None;
            var shutter = new FrameShutter { HasStart = start != null, HasEnd = end != null };
            if (JsonMatrix.TryRead(start, out var s)) shutter.Start = s;
            if (JsonMatrix.TryRead(end, out var e)) shutter.End = e;
            if (rs != null)
            {
                shutter.RollingShutterProblem = RollingShutterProblem(rs);
                if (shutter.RollingShutterProblem == null) shutter.RollingShutter = RollingShutterValues((JArray)rs);
            }
            return shutter;
        }

        /// <summary>
        /// The one rule for a <c>rolling_shutter</c> value (at the top of a transforms file or in a frame): what instant-ngp's
        /// read_lens (src/nerf_loader.cu) reads — [A, B, C] or [A, B, C, D], finite numbers, t = A + B·u + C·v + D·r.
        /// Null when it is one; else the reason, naming the key and the value. Check, validate and <c>convert --to ngp</c>
        /// refuse what it refuses (a malformed value used to pass both and be rewritten or dropped by the export).
        /// </summary>
        public static string RollingShutterProblem(JToken value)
        {
            if (value == null || value.Type == JTokenType.Null) return null;
            var ok = value is JArray list && (list.Count == 3 || list.Count == 4) &&
                     list.All(v => JsonValues.TryNumber(v, out var x) && !double.IsNaN(x) && !double.IsInfinity(x));
            if (ok) return null;
            var text = value.ToString(Newtonsoft.Json.Formatting.None);
            if (text.Length > 80) text = text.Substring(0, 80) + "…";
            return RollingShutter + " = " + text + " is not [A, B, C] or [A, B, C, D] of finite numbers (instant-ngp's t = A + B·u + C·v + D·r).";
        }

        /// <summary>A valid <c>rolling_shutter</c>'s four numbers, D = 0 when only three are given (instant-ngp's default).</summary>
        static double[] RollingShutterValues(JArray list)
        {
            var values = new double[4];
            for (var i = 0; i < list.Count; i++) JsonValues.TryNumber(list[i], out values[i]);
            return values;
        }
    }
}
