using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to dycheck</c>: a dynamic capture as DyCheck's iPhone sequences (<see cref="DyCheck"/>):
    /// <c>camera/</c>, <c>rgb/1x/</c> (RGB over the protocol background, alpha 255: every rendered pixel is valid),
    /// <c>depth/1x/*.npy</c> (exact), <c>splits/</c>, <c>dataset.json</c>, <c>metadata.json</c>, <c>scene.json</c>,
    /// <c>extra.json</c> (factor 1). Train → split "train", test → split "val" (iPhone's validation cameras).
    /// With flow/, also <c>covisible/</c> and <c>keypoint/</c>, exact (<see cref="DyCheckFlowFiles"/>); without, both readers
    /// run without them (datasets/nerfies.py:575–581; 4DGaussians hyper_loader.py:102–105).
    /// </summary>
    public static class DyCheckExport
    {
        public static ConversionResult Write(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged)
        {
            if (scene.Lens != null)
                throw NerfiesViews.Refuse("--to", "dycheck",
                    "cannot hold this dataset's lens (" + scene.Lens.Describe() + "): Shape of Motion's iPhone reader builds K from focal_length and principal_point alone (flow3d/data/iphone_dataset.py:119–127), so the distortion would be lost.",
                    "Undistort the images to a pinhole first, or convert to nerfstudio or colmap, which carry the lens.");
            var views = NerfiesViews.Of(scene, ExportTarget.Dycheck, true, out var grid, out var dropped);
            var train = views.Where(v => v.Train).ToList();
            var val = views.Where(v => !v.Train).ToList();
            var noDepth = views.FirstOrDefault(v => v.Frame.DepthPath == null);
            if (noDepth != null)
                throw NerfiesViews.Refuse("depth", noDepth.Frame.ImagePath,
                    "has no depth map, and --to dycheck writes depth/1x/<id>.npy for every image (DyCheck trains with it, iphone.py:1044–1051).",
                    "Capture with depth (depth: png in the train and test splits).");
            InvalidParameterException.ThrowIfAny(
                Consecutive("time_ids", DyCheck.Gap(train.Select(v => v.TimeId))),
                Consecutive("camera_ids", DyCheck.Gap(train.Select(v => v.CameraId))),
                DyCheck.TimeIdsPastFrameCount("train", train),
                DyCheck.TimeIdsPastFrameCount("val", val));
            if (dropped > 0)
                warnings.Add(new ValidationProblem("test", dropped + " views",
                    "are not exported: their times lie between train times (a monocular capture's test views), and DyCheck's time ids index the train frames (a view is found by time id and camera id, datasets/nerfies.py:89–93).",
                    "Capture in multi-view mode for test cameras at the train times."));
            var valFrames = scene.Split("val").Count();
            if (valFrames > 0)
                warnings.Add(new ValidationProblem("val", valFrames + " frames",
                    "are not exported: the layout has a train split and a val split (here the test split).",
                    "Nothing to do, or capture the views to evaluate as the test split."));
            outDir = Path.GetFullPath(outDir);
            var written = WriteLayout(scene, views, "dycheck", outDir, staged, warnings, grid, out var datasetFile);
            written.AddRange(DyCheckFlowFiles.Write(scene, views, outDir, staged, warnings));
            var name = ExportPaths.RunName(outDir, DyCheck.FolderName);
            return new ConversionResult(outDir, datasetFile, written, warnings, new[]
            {
                "copy " + outDir + " to dycheck/datasets/iphone/" + name + ", then: python tools/launch.py --gin_configs configs/iphone/tnerf/randbkgd_depth_dist.gin --gin_bindings 'Config.engine_cls=@Trainer' --gin_bindings 'SEQUENCE=\"" + name + "\"'   (DyCheck)",
            });
        }

        /// <summary>
        /// The iPhone layout's files for <paramref name="views"/> (train → splits/train.json, the others → splits/val.json):
        /// camera/, rgb/1x/, depth/1x/, splits/, scene.json, dataset.json, metadata.json, extra.json — each destination
        /// checked absent first. Shape of Motion's export writes the same files for its chosen frames.
        /// </summary>
        internal static List<string> WriteLayout(ExportScene scene, IReadOnlyList<NerfiesView> views, string target, string outDir, StagedOutput staged,
            List<ValidationProblem> warnings, int grid, out string datasetFile)
        {
            var train = views.Where(v => v.Train).ToList();
            var val = views.Where(v => !v.Train).ToList();
            var sceneInfo = NerfiesScene.Of(scene, views, target, warnings);
            var background = ProtocolBackground.For(scene.RootDirectory);
            var k = scene.Intrinsics;
            var files = new
            {
                Scene = Path.Combine(outDir, Nerfies.SceneFileName),
                Dataset = Path.Combine(outDir, Nerfies.DatasetFileName),
                Metadata = Path.Combine(outDir, Nerfies.MetadataFileName),
                Extra = Path.Combine(outDir, DyCheck.ExtraFileName),
                Splits = Path.Combine(outDir, DyCheck.SplitsFolder),
                Cameras = Path.Combine(outDir, Nerfies.CameraFolder),
                Rgb = Path.Combine(outDir, Nerfies.RgbFolder),
                Depth = Path.Combine(outDir, DyCheck.DepthFolder),
            };
            foreach (var path in new[] { files.Scene, files.Dataset, files.Metadata, files.Extra, files.Splits, files.Cameras, files.Rgb, files.Depth })
                DatasetConverter.EnsureAbsent(path);

            var written = new List<string>();
            var level = Nerfies.Level(DyCheck.Factor);
            foreach (var v in views)
            {
                var rgba = NerfiesImages.Opaque(NerfiesImages.Composited(scene, v.Frame, background.R, background.G, background.B));
                var image = Path.Combine(files.Rgb, level, v.Id + ".png");
                staged.WriteNewBytes(image, PngWriter.Encode(rgba, k.Width, k.Height, PngPixelFormat.Rgba8));
                var depth = Path.Combine(files.Depth, level, v.Id + ".npy");
                var steps = NerfiesScene.ReadDepthSteps(scene, v.Frame);
                staged.WriteNewBytes(depth, NumpyFiles.Float32Array(DyCheck.Depth(steps, scene.DepthUnitScale), k.Height, k.Width, 1));
                var camera = Path.Combine(files.Cameras, v.Id + ".json");
                staged.WriteNewText(camera, ExportJson.Serialise(NerfiesCamera.Json(v.Frame.CameraToWorld, k)));
                written.AddRange(new[] { image, depth, camera });
            }
            var trainSplit = Path.Combine(files.Splits, "train.json");
            var valSplit = Path.Combine(files.Splits, "val.json");
            staged.WriteNewText(trainSplit, ExportJson.Serialise(DyCheck.SplitJson(train)));
            staged.WriteNewText(valSplit, ExportJson.Serialise(DyCheck.SplitJson(val)));
            staged.WriteNewText(files.Scene, ExportJson.Serialise(sceneInfo.ToJson()));
            staged.WriteNewText(files.Dataset, ExportJson.Serialise(Nerfies.DatasetJson(views)));
            staged.WriteNewText(files.Metadata, ExportJson.Serialise(Nerfies.MetadataJson(views)));
            staged.WriteNewText(files.Extra, ExportJson.Serialise(Extra(sceneInfo, Fps(train, grid, warnings))));
            written.AddRange(new[] { trainSplit, valSplit, files.Scene, files.Dataset, files.Metadata, files.Extra });
            datasetFile = files.Dataset;
            return written;
        }

        /// <summary>
        /// Frames per second of the time ids: grid steps per second of content time, from the train views at the least
        /// and greatest time (their <c>time_seconds</c>); the grid itself (one second in all) with a warning when they have none.
        /// </summary>
        static double Fps(IReadOnlyList<NerfiesView> train, int grid, List<ValidationProblem> warnings)
        {
            var first = train.OrderBy(v => v.TimeId).First();
            var last = train.OrderBy(v => v.TimeId).Last();
            if (first.Frame.Timing.Seconds is double a && last.Frame.Timing.Seconds is double b && b > a)
                return (last.TimeId - first.TimeId) / (b - a);
            warnings.Add(new ValidationProblem("extra.json: fps", ValidationProblem.Format(grid),
                "assumes the capture lasts one second: the train frames have no time_seconds to say how long it is.",
                "Re-capture with this plugin's current version, which records time_seconds."));
            return grid;
        }

        static JObject Extra(NerfiesScene scene, double fps)
        {
            JArray Scaled(Vector3d p) => new JArray((p.X - scene.Center.X) * scene.Scale, (p.Y - scene.Center.Y) * scene.Scale, (p.Z - scene.Center.Z) * scene.Scale);
            return new JObject
            {
                ["factor"] = DyCheck.Factor,
                ["fps"] = fps,
                ["bbox"] = new JArray(Scaled(scene.Low), Scaled(scene.High)),
                // The output origin, where this plugin puts the target the cameras aim at; the world's up is +Z (Blender).
                ["lookat"] = Scaled(Vector3d.Zero),
                ["up"] = new JArray(0.0, 0.0, 1.0),
            };
        }

        static ValidationProblem Consecutive(string key, string gap) => gap == null ? null :
            new ValidationProblem("splits/train.json: " + key, gap,
                "are not 0, 1, 2, … without a gap, which DyCheck requires of a training split (datasets/base.py:71–75).",
                "Re-capture the train split so that every camera has an image at every step.");
    }
}
