using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A split's cameras as a nerfstudio <c>camera_path.json</c> for <c>ns-render camera-path</c>, so a trained model
    /// renders exactly our ground-truth views, frame by frame. What nerfstudio reads (nerfstudio
    /// cameras/camera_paths.py <c>get_path_from_json</c>, lines 127–193 at 50e0e3c): <c>render_height</c>,
    /// <c>render_width</c>, <c>camera_type</c> ("perspective"), and per entry of <c>camera_path</c> a row-major flattened
    /// 4×4 <c>camera_to_world</c> (<c>torch.tensor(…).view(4, 4)[:3]</c>) and <c>fov</c>, the VERTICAL field of view in
    /// degrees (focal = (H/2) / tan(fov/2), viewer_legacy/server/utils.py line 51); cx, cy are W/2, H/2. render.py
    /// reads <c>seconds</c> (line 463) and renders at len(cameras)/seconds fps (line 101). <c>aspect</c> and <c>fps</c> are
    /// what the viewer writes (viewer/render_panel.py lines 1093–1116) and are only informative. For a dynamic capture
    /// every entry also carries <c>render_time</c>, the frame's <c>time</c>: get_path_from_json gives the cameras times
    /// only when ALL entries have it (camera_paths.py at 08816c7: <c>if all("render_time" in camera …)</c>).
    /// <para>The matrices are in the MODEL's frame: nerfstudio-data moves and scales the file's poses before training
    /// (nerfstudio_dataparser.py lines 237–249: orientation "up", centring "poses", auto scale) and saves that as
    /// <c>dataparser_transforms.json</c> ({"transform": 3×4, "scale": s}, base_dataparser.py lines 84–87). Pass it to
    /// map our poses: c2w_model = [T·c2w]₃ₓ₄ with its translation × s. Without it the path is in the file's frame,
    /// which is the model's only for <c>--orientation-method none --center-method none --auto-scale-poses False</c>.</para>
    /// </summary>
    public static class NerfstudioCameraPath
    {
        public const double DefaultFramesPerSecond = 24;

        public static JObject Build(IReadOnlyList<Matrix4x4d> cameraToWorld, CameraIntrinsics intrinsics, NerfstudioDataparserTransform dataparser = null,
            double framesPerSecond = DefaultFramesPerSecond, IReadOnlyList<double?> times = null)
        {
            // Times only when every camera has one: nerfstudio ignores a partial set anyway.
            var withTimes = times != null && times.Count == (cameraToWorld?.Count ?? -1) && times.All(t => t.HasValue);
            if (cameraToWorld == null || cameraToWorld.Count == 0) throw new ArgumentException("A camera path needs at least one camera.", nameof(cameraToWorld));
            if (intrinsics == null) throw new ArgumentNullException(nameof(intrinsics));
            InvalidParameterException.ThrowIfAny(ValidationProblem.OutsideRange("framesPerSecond", framesPerSecond, 0.001, 1000));
            var fov = intrinsics.CameraAngleY * 180 / Math.PI;
            var path = new JArray();
            for (var i = 0; i < cameraToWorld.Count; i++)
            {
                var m = cameraToWorld[i];
                var model = dataparser == null ? m : dataparser.Apply(m);
                var flat = new JArray();
                for (var r = 0; r < 4; r++)
                    for (var c = 0; c < 4; c++) flat.Add(model[r, c]);
                var entry = new JObject { ["camera_to_world"] = flat, ["fov"] = fov, ["aspect"] = (double)intrinsics.Width / intrinsics.Height };
                if (withTimes) entry["render_time"] = times[i].Value;
                path.Add(entry);
            }
            return new JObject
            {
                ["camera_type"] = "perspective",
                ["render_height"] = intrinsics.Height,
                ["render_width"] = intrinsics.Width,
                ["fps"] = framesPerSecond,
                ["seconds"] = cameraToWorld.Count / framesPerSecond,
                ["camera_path"] = path,
            };
        }

        /// <summary>What the path cannot carry: nerfstudio renders a path with a centred principal point and square pixels.</summary>
        public static IReadOnlyList<ValidationProblem> Warnings(CameraIntrinsics k)
        {
            var problems = new List<ValidationProblem>();
            if (Math.Abs(k.Cx - k.Width / 2.0) > 1e-6 || Math.Abs(k.Cy - k.Height / 2.0) > 1e-6 || Math.Abs(k.FlX - k.FlY) > 1e-9 * k.FlX)
                problems.Add(new ValidationProblem("camera_path", "cx " + ValidationProblem.Format(k.Cx) + ", cy " + ValidationProblem.Format(k.Cy),
                    "is off the image centre or the pixels are not square; nerfstudio renders a camera path with cx = W/2, cy = H/2 and one focal length, so its frames are shifted against ours.",
                    "Compare with ns-eval on the dataset's test split instead, which uses the dataset's intrinsics."));
            return problems;
        }
    }

    /// <summary>nerfstudio's <c>dataparser_transforms.json</c>: the 3×4 transform and scale applied to the file's poses before training.</summary>
    public sealed class NerfstudioDataparserTransform
    {
        public NerfstudioDataparserTransform(Matrix4x4d transform, double scale)
        {
            InvalidParameterException.ThrowIfAny(
                transform.IsFinite ? null : new ValidationProblem("transform", transform.ToString(), "is not finite.", "Use the file nerfstudio wrote."),
                ValidationProblem.OutsideRange("scale", scale, 1e-12, 1e12));
            Transform = transform;
            Scale = scale;
        }

        public Matrix4x4d Transform { get; }
        public double Scale { get; }

        /// <summary>nerfstudio_dataparser.py: poses = transform @ poses (auto_orient_and_center_poses), then poses[:, :3, 3] *= scale.</summary>
        public Matrix4x4d Apply(Matrix4x4d cameraToWorld)
        {
            var m = Transform * cameraToWorld;
            return Matrix4x4d.FromColumns(m.Column(0), m.Column(1), m.Column(2), m.Translation * Scale);
        }

        public static NerfstudioDataparserTransform FromJson(JToken token)
        {
            var rows = (token as JObject)?["transform"] as JArray;
            var scale = (token as JObject)?["scale"];
            if (rows == null || rows.Count != 3 || rows.Any(r => !(r is JArray a) || a.Count != 4 || a.Any(v => v.Type != JTokenType.Float && v.Type != JTokenType.Integer)) ||
                scale == null || (scale.Type != JTokenType.Float && scale.Type != JTokenType.Integer))
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("dataparser_transforms.json", token?.ToString(Newtonsoft.Json.Formatting.None) ?? "null",
                        "is not {\"transform\": 3×4 numbers, \"scale\": a number}.", "Pass the dataparser_transforms.json of the nerfstudio run (outputs/<name>/<method>/<time>/)."),
                });
            var v = new double[16];
            for (var r = 0; r < 3; r++)
                for (var c = 0; c < 4; c++) v[r * 4 + c] = (double)rows[r][c];
            v[15] = 1;
            return new NerfstudioDataparserTransform(Matrix4x4d.FromRowMajor(v), (double)scale);
        }
    }
}
