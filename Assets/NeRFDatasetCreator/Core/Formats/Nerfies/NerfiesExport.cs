using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to nerfies</c>: a dynamic capture (monocular or multi-view) as Nerfies and HyperNeRF read a
    /// sequence, and 4DGaussians through its HyperNeRF reader: <c>scene.json</c> (<see cref="NerfiesScene"/>),
    /// <c>dataset.json</c> and <c>metadata.json</c> (<see cref="Nerfies"/>; train → train_ids, test → val_ids),
    /// <c>camera/&lt;id&gt;.json</c> (<see cref="NerfiesCamera"/>, the full-size camera: every reader scales it to its level),
    /// <c>rgb/&lt;k&gt;x/&lt;id&gt;.png</c> (<see cref="NerfiesImages"/>) and, from the dataset's <c>points3d.ply</c>,
    /// 4DGaussians' <c>points3D_downsample2.ply</c> (the target at time 0, in the cameras' world).
    /// </summary>
    public static class NerfiesExport
    {
        public static ConversionResult Write(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged)
        {
            if (scene.Lens != null)
                throw NerfiesViews.Refuse("--to", "nerfies",
                    "cannot hold this dataset's lens (" + scene.Lens.Describe() + "): 4DGaussians' reader takes the field of view from focal_length alone and ignores the distortion (scene/hyper_loader.py:161–164).",
                    "Undistort the images to a pinhole first, or convert to nerfstudio or colmap, which carry the lens.");
            var views = NerfiesViews.Of(scene, ExportTarget.Nerfies, false, out _, out _);
            Warn(scene, views, warnings);
            var sceneInfo = NerfiesScene.Of(scene, views, "nerfies", warnings);
            var background = ProtocolBackground.For(scene.RootDirectory);
            var k = scene.Intrinsics;
            var levels = NerfiesImages.Levels.Where(f => NerfiesImages.Fits(f, k.Width, k.Height)).ToList();
            if (!levels.Contains(Nerfies.FourDGaussiansLevel))
                warnings.Add(new ValidationProblem("rgb/2x", k.Width + " × " + k.Height,
                    "is not written: an odd side has no exact half size, and 4DGaussians loads only rgb/2x (scene/dataset_readers.py:374, hyper_loader.py:96).",
                    "Capture with even width and height for 4DGaussians; Nerfies and HyperNeRF read rgb/1x with image_scale = 1."));

            outDir = Path.GetFullPath(outDir);
            var sceneFile = Path.Combine(outDir, Nerfies.SceneFileName);
            var datasetFile = Path.Combine(outDir, Nerfies.DatasetFileName);
            var metadataFile = Path.Combine(outDir, Nerfies.MetadataFileName);
            var cameras = Path.Combine(outDir, Nerfies.CameraFolder);
            var rgb = Path.Combine(outDir, Nerfies.RgbFolder);
            var points = scene.PointCloudPath == null ? null : Path.Combine(outDir, Nerfies.PointCloudFileName);
            foreach (var path in new[] { sceneFile, datasetFile, metadataFile, cameras, rgb, points }.Where(p => p != null)) DatasetConverter.EnsureAbsent(path);

            var written = new List<string>();
            foreach (var v in views)
            {
                var image = NerfiesImages.Composited(scene, v.Frame, background.R, background.G, background.B);
                foreach (var factor in levels)
                {
                    var file = Path.Combine(rgb, Nerfies.Level(factor), v.Id + ".png");
                    staged.WriteNewBytes(file, PngWriter.Encode(NerfiesImages.Downscale(image, k.Width, k.Height, factor), k.Width / factor, k.Height / factor, PngPixelFormat.Rgb8));
                    written.Add(file);
                }
                var camera = Path.Combine(cameras, v.Id + ".json");
                staged.WriteNewText(camera, ExportJson.Serialise(NerfiesCamera.Json(v.Frame.CameraToWorld, k)));
                written.Add(camera);
            }
            staged.WriteNewText(sceneFile, ExportJson.Serialise(sceneInfo.ToJson()));
            staged.WriteNewText(datasetFile, ExportJson.Serialise(Nerfies.DatasetJson(views)));
            staged.WriteNewText(metadataFile, ExportJson.Serialise(Nerfies.MetadataJson(views)));
            written.AddRange(new[] { sceneFile, datasetFile, metadataFile });
            if (points != null)
            {
                staged.Copy(Path.Combine(scene.RootDirectory, scene.PointCloudPath), points);
                written.Add(points);
            }
            else
                warnings.Add(new ValidationProblem(Nerfies.PointCloudFileName, "missing",
                    "is not written: the dataset has no points3d.ply of this plugin, and 4DGaussians' reader opens it (scene/dataset_readers.py:384–385); Nerfies and HyperNeRF do not need it.",
                    "For 4DGaussians, capture again with pointCloudPoints above 0 (e.g. 100000)."));
            var name = ExportPaths.RunName(outDir, Nerfies.FolderName);
            return new ConversionResult(outDir, datasetFile, written, warnings, new[]
            {
                "python train.py -s " + outDir + " --port 6017 --expname \"hypernerf/" + name + "\" --configs arguments/hypernerf/default.py   (4DGaussians)",
                "python train.py --data_dir " + outDir + " --base_folder <experiment folder> --gin_configs configs/test_local.gin --gin_bindings \"ExperimentConfig.image_scale = 1\"   (Nerfies)",
                "python train.py --base_folder <experiment folder> --gin_bindings=\"data_dir='" + outDir + "'\" --gin_configs configs/test_local.gin   (HyperNeRF)",
            });
        }

        /// <summary>What the readers will do differently from the dataset, said before writing.</summary>
        static void Warn(ExportScene scene, IReadOnlyList<NerfiesView> views, List<ValidationProblem> warnings)
        {
            var val = scene.Split("val").Count();
            if (val > 0)
                warnings.Add(new ValidationProblem("val", val + " frames",
                    "are not exported: the layout has train_ids (the train split) and val_ids (the test split) only.",
                    "Nothing to do, or capture the views to evaluate as the test split."));
            var trainTimes = new HashSet<int>(views.Where(v => v.Train).Select(v => v.TimeId));
            var between = views.Count(v => !v.Train && !trainTimes.Contains(v.TimeId));
            if (between > 0)
                warnings.Add(new ValidationProblem("val_ids", between + " views",
                    "are at times no train view has (a monocular capture's test views sit between train steps), so they have warp_ids of their own: 4DGaussians reads warp_id / max as the time and renders them, HyperNeRF gets an untrained embedding, and Nerfies stops with a ValueError when it looks the id up among train's (nerfies/datasets/core.py:601).",
                    "For Nerfies itself, capture in multi-view mode (test cameras at the train times)."));
            var k = scene.Intrinsics;
            if (k.Cx != k.Width / 2.0 || k.Cy != k.Height / 2.0)
                warnings.Add(new ValidationProblem("principal_point", ValidationProblem.Format(k.Cx) + ", " + ValidationProblem.Format(k.Cy),
                    "is off the image centre (lens shift): Nerfies, HyperNeRF and DyCheck read it, but 4DGaussians builds its camera from focal_length alone (scene/hyper_loader.py:161–164), as if centred.",
                    "Capture without lens shift for 4DGaussians."));
        }
    }
}
