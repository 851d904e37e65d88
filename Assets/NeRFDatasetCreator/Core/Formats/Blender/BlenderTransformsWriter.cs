using System;
using System.Collections.Generic;
using Newtonsoft.Json;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes <c>transforms_&lt;split&gt;.json</c> in nerf_synthetic's shape and key order — <c>camera_angle_x</c>,
    /// then the keys instant-ngp and nerfstudio read (which the original loaders ignore), then <c>frames</c> of
    /// <c>file_path</c>, <c>rotation</c>, <c>transform_matrix</c> and the extra-file keys of files that are written.
    /// 4-space indentation like nerf_synthetic's files; numbers at round-trip precision, invariant culture.
    /// </summary>
    public static class BlenderTransformsWriter
    {
        /// <summary>
        /// Output units per step of a 16-bit depth PNG: thousandths of an output unit (millimetres when the scale is 1
        /// and a Unity unit is a metre); depth is written in output units, metric z × the normalisation scale.
        /// </summary>
        public const double DepthUnitScale = 0.001;

        /// <summary>The key of the <see cref="SceneNormalisation.ToJson"/> record in the transforms files and dataset_config.json.</summary>
        public const string SceneNormalisationKey = "scene_normalisation";

        /// <summary>
        /// The split's file. The depth scale keys follow the split's settings, not its frames: a shard that drew no
        /// view of a split still declares them, so all shards' files agree and merge.
        /// </summary>
        public static string Write(CapturePlan plan, DatasetSplit split)
        {
            using (var text = JsonNumbers.CreateText())
            {
                Write(plan, split, text);
                return text.ToString();
            }
        }

        /// <summary>The same text as <see cref="Write(CapturePlan, DatasetSplit)"/>, streamed into <paramref name="output"/> (a file: no string of the whole file is built).</summary>
        /// <remarks>Only the split's views are made (a plan makes them on demand), and the depth keys follow the split's settings
        /// alone: a plan's views of a split all write the files its settings name (<see cref="DatasetLayout.FileKinds"/>).</remarks>
        public static void Write(CapturePlan plan, DatasetSplit split, System.IO.TextWriter output) =>
            Write(plan.Intrinsics, plan.RotationOf(split), plan.ViewsOf(split), split,
                ExtraOutputs.HasPng(plan.Settings.Split(split).Depth), plan.AabbScale, plan.Normalisation, output, scanViewsForDepth: false, plan.Settings);

        /// <param name="aabbScale">instant-ngp's scene cube (<see cref="NerfDatasetCreator.AabbScale"/>); 1 for one object at nerf_synthetic's scale.</param>
        /// <param name="normalisation">Written as <c>scene_normalisation</c>, which every loader ignores; null writes none.</param>
        public static string Write(CameraIntrinsics intrinsics, double rotation, IReadOnlyList<PlannedView> views, bool declareDepthScale,
            int aabbScale, SceneNormalisation normalisation)
        {
            using (var text = JsonNumbers.CreateText())
            {
                Write(intrinsics, rotation, views, null, declareDepthScale, aabbScale, normalisation, text, scanViewsForDepth: true);
                return text.ToString();
            }
        }

        // The views of split (all views when null) among views: a plan's split is written without a list of its own.
        // settings (null: none) switch the optional outputs' keys on; each feature reads its own from them.
        static void Write(CameraIntrinsics intrinsics, double rotation, IReadOnlyList<PlannedView> views, DatasetSplit? split, bool declareDepthScale,
            int aabbScale, SceneNormalisation normalisation, System.IO.TextWriter text, bool scanViewsForDepth, DatasetSettings settings = null)
        {
            if (intrinsics == null) throw new ArgumentNullException(nameof(intrinsics));
            var anyDepthPng = declareDepthScale;
            for (var i = 0; scanViewsForDepth && i < views.Count && !anyDepthPng; i++)
                anyDepthPng = (split == null || views[i].Split == split.Value) && views[i].Writes(DatasetFileKind.DepthPng);
            using (var w = JsonNumbers.CreateWriter(text, 4))
            {
                // Newtonsoft writes the keys before "frames"; TransformsFramesText writes the frames and closes the object.
                w.CloseOutput = false;
                w.AutoCompleteOnClose = false;
                w.WriteStartObject();
                JsonNumbers.Number(w, "camera_angle_x", intrinsics.CameraAngleX);
                JsonNumbers.Number(w, "camera_angle_y", intrinsics.CameraAngleY);
                JsonNumbers.Number(w, "fl_x", intrinsics.FlX);
                JsonNumbers.Number(w, "fl_y", intrinsics.FlY);
                JsonNumbers.Number(w, "cx", intrinsics.Cx);
                JsonNumbers.Number(w, "cy", intrinsics.Cy);
                w.WritePropertyName("w"); w.WriteValue(intrinsics.Width);
                w.WritePropertyName("h"); w.WriteValue(intrinsics.Height);
                // The lens the images were taken through (none for a pinhole capture, whose files keep their keys).
                TransformsLensKeys.Write(w, settings);
                w.WritePropertyName("aabb_scale"); w.WriteValue(aabbScale);
                if (anyDepthPng)
                {
                    JsonNumbers.Number(w, "integer_depth_scale", DepthUnitScale);
                    JsonNumbers.Number(w, "depth_unit_scale_factor", DepthUnitScale);
                }
                MotionBlurRecord.WriteTopLevel(w, settings);
                if (normalisation != null)
                {
                    w.WritePropertyName(SceneNormalisationKey);
                    JsonNumbers.WriteToken(w, normalisation.ToJson());
                }
                w.Flush();
            }
            TransformsFramesText.Write(text, views, split, rotation, settings);
            text.Write("\n");
        }

        /// <summary>A 4×4 matrix as nested rows, <c>transform_matrix[row][column]</c>.</summary>
        public static void WriteMatrix(JsonWriter w, Matrix4x4d m)
        {
            w.WriteStartArray();
            for (var r = 0; r < 4; r++)
            {
                w.WriteStartArray();
                for (var c = 0; c < 4; c++) JsonNumbers.Write(w, m[r, c]);
                w.WriteEndArray();
            }
            w.WriteEndArray();
        }
    }
}
