using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// nerfstudio's own format (<c>nerfstudio-data</c> dataparser): ONE <c>transforms.json</c> with shared PINHOLE
    /// intrinsics, frames whose <c>file_path</c> keeps its extension (the parser uses it as given), and explicit
    /// <c>train_filenames</c> / <c>val_filenames</c> / <c>test_filenames</c> so the nerf_synthetic splits survive.
    /// <para><c>applied_transform</c> is the 3×4 identity on purpose: nerfstudio multiplies the points of
    /// <c>ply_file_path</c> by it (and by <c>applied_scale</c>), treating the PLY as being in the pre-transform frame.
    /// Our PLY is already in the output frame, so writing the normalisation there would move the points twice; the
    /// normalisation is recorded under <c>scene_normalisation</c>, which nerfstudio ignores.</para>
    /// <para><c>depth_unit_scale_factor</c> documents the depth step; nerfstudio takes the value from its
    /// <c>--depth-unit-scale-factor</c> flag (default 1e-3), which matches <see cref="ExportScene.DefaultDepthUnitScale"/>.</para>
    /// </summary>
    public static class NerfstudioWriter
    {
        public const string FileName = "transforms.json";

        /// <summary>The JSON for a transforms.json written into <paramref name="outputDirectory"/>.</summary>
        /// <param name="references">How the dataset's files are named (<see cref="ExportImages"/>); null: by relative path.</param>
        public static JObject Build(ExportScene scene, string outputDirectory, ExportFileReferences references = null)
        {
            string Rel(string p) => references != null ? references.Reference(p) : ExportPaths.RelativeTo(outputDirectory, scene.RootDirectory, p);
            var k = scene.Intrinsics;
            var json = new JObject
            {
                ["camera_model"] = scene.Lens?.CameraModelName ?? "PINHOLE",
            };
            ExportJson.AddPixelIntrinsics(json, k);
            AddLens(json, scene.Lens);
            json["applied_transform"] = ExportJson.Matrix3x4(Matrix4x4d.Identity);
            if (scene.PointCloudPath != null) json["ply_file_path"] = Rel(scene.PointCloudPath);
            if (scene.HasDepth) json["depth_unit_scale_factor"] = scene.DepthUnitScale;
            if (scene.Normalisation != null) json["scene_normalisation"] = scene.Normalisation.ToJson();
            if (scene.UnityFrame != null) json[UnityFrameRecord.Key] = scene.UnityFrame.DeepClone(); // carried for place-splat; nerfstudio ignores it
            foreach (var split in DatasetSplits.Names)
                json[split + "_filenames"] = new JArray(scene.Split(split).Select(f => (object)Rel(f.ImagePath)).ToArray());

            var frames = new JArray();
            var depth = scene.HasDepth;
            var masks = scene.HasMasks;
            foreach (var f in scene.Frames)
            {
                var frame = new JObject
                {
                    ["file_path"] = Rel(f.ImagePath),
                    ["transform_matrix"] = ExportJson.Matrix(f.CameraToWorld),
                };
                // nerfstudio asserts "all frames or none" for both keys.
                if (depth) frame["depth_file_path"] = Rel(f.DepthPath);
                if (masks) frame["mask_path"] = Rel(f.MaskPath);
                frames.Add(frame);
            }
            json["frames"] = frames;
            return json;
        }

        /// <summary>
        /// The lens keys nerfstudio-data reads at the top of transforms.json (nerfstudio_dataparser.py: any of k1, k2, k3,
        /// p1, p2 makes the distortion shared; get_distortion_params(k1, k2, k3, k4, p1, p2)). OPENCV writes all six with
        /// k4 = 0 (nerfstudio's k4 is an r⁸ term OpenCV does not have); OPENCV_FISHEYE writes k1…k4, as ns-process-data does.
        /// </summary>
        public static void AddLens(JObject json, LensDistortion lens)
        {
            if (lens == null) return;
            json["k1"] = lens.K1;
            json["k2"] = lens.K2;
            json["k3"] = lens.K3;
            json["k4"] = lens.K4;
            if (lens.Model == LensModel.OpenCvFisheye) return;
            json["p1"] = lens.P1;
            json["p2"] = lens.P2;
        }

        /// <summary>Problems worth telling the user about before they train.</summary>
        public static IReadOnlyList<ValidationProblem> Warnings(ExportScene scene)
        {
            var problems = new List<ValidationProblem>();
            foreach (var split in DatasetSplits.Names)
                if (!scene.Split(split).Any())
                    problems.Add(new ValidationProblem(split + "_filenames", "[]",
                        $"is empty; nerfstudio needs frames in every split it loads (train, and val or test for evaluation).",
                        $"Capture at least one {split} view."));
            if (!scene.HasDepth && scene.Frames.Any(f => f.DepthPath != null))
                problems.Add(new ValidationProblem("depth_file_path", "some frames", "is missing on some frames; nerfstudio needs it on all or none, so depth was left out.", "Re-export with depth for every split."));
            if (!scene.HasMasks && scene.Frames.Any(f => f.MaskPath != null))
                problems.Add(new ValidationProblem("mask_path", "some frames", "is missing on some frames; nerfstudio needs it on all or none, so masks were left out.", "Re-export with masks for every split."));
            return problems;
        }
    }
}
