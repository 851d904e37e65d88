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
        /// <summary>
        /// instant-ngp's lens keys (src/nerf_loader.cu <c>read_lens</c>): <c>is_fisheye</c> picks OpenCVFisheye, and each
        /// of k1, k2, k3, k4 then p1, p2 is stored in <c>lens.params</c> at 0, 1, 2, 3, 2, 3 — p1 and p2 OVERWRITE k3 and k4,
        /// and the lens stays a pinhole unless some coefficient is non-zero. So OPENCV writes k1 k2 p1 p2 (no k3: ngp's
        /// OpenCV has none, <see cref="Refusal"/>), and a fisheye writes <c>is_fisheye</c> with k1…k4 and never p1/p2.
        /// </summary>
        public static void AddLens(JObject json, LensDistortion lens)
        {
            if (lens == null) return;
            var refusal = Refusal(lens);
            if (refusal != null) throw new InvalidParameterException(new[] { refusal });
            json["k1"] = lens.K1;
            json["k2"] = lens.K2;
            if (lens.Model == LensModel.OpenCvFisheye)
            {
                json["is_fisheye"] = true;
                json["k3"] = lens.K3;
                json["k4"] = lens.K4;
                return;
            }
            json["p1"] = lens.P1;
            json["p2"] = lens.P2;
        }

        /// <summary>Why instant-ngp cannot hold <paramref name="lens"/>, or null when it can.</summary>
        public static ValidationProblem Refusal(LensDistortion lens)
        {
            if (lens == null) return null;
            if (lens.Model == LensModel.OpenCv && lens.K3 != 0)
                return new ValidationProblem("k3", ValidationProblem.Format(lens.K3),
                    "cannot be carried to instant-ngp: its OpenCV lens has only k1, k2, p1, p2 (nerf_loader.cu read_lens stores p1 where k3 would go).",
                    "Convert to nerfstudio or colmap (FULL_OPENCV), which hold k3, or undistort the images first.");
            if (lens.Model == LensModel.OpenCvFisheye && lens.K1 == 0 && lens.K2 == 0 && lens.K3 == 0 && lens.K4 == 0)
                return new ValidationProblem("camera_model", "OPENCV_FISHEYE with k1 = k2 = k3 = k4 = 0",
                    "cannot be carried to instant-ngp: it switches to its fisheye lens only when a coefficient is non-zero (nerf_loader.cu read_lens), so it would read a pinhole.",
                    "Convert to nerfstudio or colmap (OPENCV_FISHEYE), or undistort the images first.");
            return null;
        }

        public const string FolderName = "ngp";
        public const string FileName = "transforms.json";

        /// <summary>nerf_synthetic's ±1.5 box: the scene radius assumed when the target's size is unknown.</summary>
        public const double DefaultSceneRadius = AabbScale.DefaultSceneRadius;

        /// <param name="sceneRadius">
        /// The content's radius in output units when the caller knows it (a fresh capture: the target's reach);
        /// null takes the dataset's own <see cref="ExportScene.DeclaredAabbScale"/> and <see cref="ExportScene.TargetReach"/>
        /// (<see cref="AabbScale.ForDataset"/>).
        /// </param>
        /// <param name="references">How the dataset's files are named (<see cref="ExportImages"/>); null: by relative path.</param>
        public static JObject Build(ExportScene scene, string outputDirectory, double? sceneRadius = null,
            ICollection<ValidationProblem> warnings = null, ExportFileReferences references = null)
        {
            string Rel(string p) => references != null ? references.Reference(p) : ExportPaths.RelativeTo(outputDirectory, scene.RootDirectory, p);
            var k = scene.Intrinsics;
            var train = scene.Split("train").ToList();
            var depth = train.Count > 0 && train.All(f => f.DepthPath != null);
            var json = new JObject
            {
                ["camera_angle_x"] = k.CameraAngleX,
                ["camera_angle_y"] = k.CameraAngleY,
            };
            ExportJson.AddPixelIntrinsics(json, k);
            AddLens(json, scene.Lens);
            json["aabb_scale"] = sceneRadius.HasValue
                ? AabbScale.ForRadius(sceneRadius.Value, warnings)
                : AabbScale.ForDataset(scene.DeclaredAabbScale, scene.TargetReach, warnings);
            if (depth) json["integer_depth_scale"] = scene.DepthUnitScale;
            if (scene.Normalisation != null) json["scene_normalisation"] = scene.Normalisation.ToJson();
            if (scene.UnityFrame != null) json[UnityFrameRecord.Key] = scene.UnityFrame.DeepClone(); // carried for place-splat; instant-ngp ignores it
            var frames = new JArray();
            foreach (var f in train)
            {
                var frame = new JObject
                {
                    ["file_path"] = Rel(f.ImagePath),
                    ["transform_matrix"] = ExportJson.Matrix(f.CameraToWorld),
                };
                if (depth) frame["depth_path"] = Rel(f.DepthPath);
                MotionBlurExports.AddToNgpFrame(frame, f);
                frames.Add(frame);
            }
            MotionBlurExports.AddToNgpFile(json, train);
            json["frames"] = frames;
            if (train.Count == 0)
                warnings?.Add(new ValidationProblem("frames", "0", "the dataset has no train frames; instant-ngp stops with \"No training images were found\".", "Capture at least one train view."));
            return json;
        }
    }
}
