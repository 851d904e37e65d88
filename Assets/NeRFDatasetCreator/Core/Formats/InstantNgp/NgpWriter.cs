using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// instant-ngp export: ONE json holding the TRAIN frames only, written into its own folder (default
    /// <c>&lt;dataset&gt;/ngp/transforms.json</c>). instant-ngp trains on every frame of every json it is given and
    /// loads every <c>*.json</c> of a folder it is pointed at, so a dedicated folder is safe to pass either way,
    /// whereas the dataset root would merge train, val, test (and nerfstudio's transforms.json) into training.
    /// Paths are relative to the json (<c>../train/r_0.png</c>). Keys: fl_x, fl_y, cx, cy with w, h (NGP divides cx
    /// by w), camera_angle_x/y, <c>aabb_scale</c> (the dataset's own, raised if its target needs more: see <see cref="AabbScale.ForDataset"/>), and with depth
    /// <c>integer_depth_scale</c> + per-frame <c>depth_path</c>. NGP's own <c>scale</c>/<c>offset</c> keys are left
    /// at their defaults (0.33, 0.5) on which aabb_scale is based; our record sits under <c>scene_normalisation</c>.
    /// Masks are not written: NGP's <c>dynamic_mask_*</c> has the opposite meaning (non-zero = exclude).
    /// </summary>
    public static class NgpWriter
    {
        public const string FolderName = "ngp";
        public const string FileName = "transforms.json";

        /// <summary>nerf_synthetic's ±1.5 box: the scene radius assumed when the target's size is unknown.</summary>
        public const double DefaultSceneRadius = AabbScale.DefaultSceneRadius;

        /// <param name="sceneRadius">
        /// The content's radius in output units when the caller knows it (a fresh capture: the target's reach);
        /// null takes the dataset's own <see cref="ExportScene.DeclaredAabbScale"/> and <see cref="ExportScene.TargetReach"/>
        /// (<see cref="AabbScale.ForDataset"/>).
        /// </param>
        public static JObject Build(ExportScene scene, string outputDirectory, double? sceneRadius = null,
            ICollection<ValidationProblem> warnings = null)
        {
            string Rel(string p) => ExportPaths.RelativeTo(outputDirectory, scene.RootDirectory, p);
            var k = scene.Intrinsics;
            var train = scene.Split("train").ToList();
            var depth = train.Count > 0 && train.All(f => f.DepthPath != null);
            var json = new JObject
            {
                ["camera_angle_x"] = k.CameraAngleX,
                ["camera_angle_y"] = k.CameraAngleY,
            };
            ExportJson.AddPixelIntrinsics(json, k);
            json["aabb_scale"] = sceneRadius.HasValue
                ? AabbScale.ForRadius(sceneRadius.Value, warnings)
                : AabbScale.ForDataset(scene.DeclaredAabbScale, scene.TargetReach, warnings);
            if (depth) json["integer_depth_scale"] = scene.DepthUnitScale;
            if (scene.Normalisation != null) json["scene_normalisation"] = scene.Normalisation.ToJson();
            var frames = new JArray();
            foreach (var f in train)
            {
                var frame = new JObject
                {
                    ["file_path"] = Rel(f.ImagePath),
                    ["transform_matrix"] = ExportJson.Matrix(f.CameraToWorld),
                };
                if (depth) frame["depth_path"] = Rel(f.DepthPath);
                frames.Add(frame);
            }
            json["frames"] = frames;
            if (train.Count == 0)
                warnings?.Add(new ValidationProblem("frames", "0", "the dataset has no train frames; instant-ngp stops with \"No training images were found\".", "Capture at least one train view."));
            return json;
        }
    }
}
