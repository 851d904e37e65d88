using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to dynamic3dgs</c>: a multi-view dynamic dataset of this plugin as Dynamic 3D Gaussians reads a
    /// sequence (train.py:15–26, 37–55): <c>train_meta.json</c> with <c>w</c>, <c>h</c> and, per time step and camera,
    /// <c>k</c>, <c>w2c</c>, <c>fn</c>, <c>cam_id</c>; RGB images under <c>ims/</c>; 0/1 segmentation under <c>seg/</c>
    /// (same names); <c>init_pt_cld.npz</c>. The test split goes to <c>test_meta.json</c> in the same form (its cameras
    /// numbered after train's); the released train.py reads only train_meta.json. Rules: <see cref="Dynamic3DGaussians"/>.
    /// </summary>
    public static class Dynamic3DGaussiansExport
    {
        sealed class Grid
        {
            public ExportFrame[,] Frames; // [step, camera]
            public int Cameras;
            public int FirstId;
        }

        /// <param name="staged">The convert's working output: files go there and are moved into place together.</param>
        public static ConversionResult Write(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged)
        {
            var root = scene.RootDirectory;
            // A malformed config reads as none (the refusals below say so); an unreadable one fails the export.
            var config = DatasetConfig.Read(root).ThrowIfUnreadable().Config;
            var steps = MultiViewSteps(config, root);
            var train = ReadGrid(scene, DatasetSplit.Train, steps, 0);
            if (train == null)
                throw Refuse("splits.train", "0 frames", "Dynamic 3D Gaussians trains on the train split's cameras, and it is empty.", "Capture a train split.");
            if (train.Cameras > Dynamic3DGaussians.MaxCameras)
                throw Refuse("splits.train.count", train.Cameras.ToString(System.Globalization.CultureInfo.InvariantCulture),
                    "cameras, but Dynamic 3D Gaussians holds per-camera colour terms for at most " + Dynamic3DGaussians.MaxCameras + " (train.py:40, max_cams).",
                    "Capture at most " + Dynamic3DGaussians.MaxCameras + " train cameras.");
            var test = ReadGrid(scene, DatasetSplit.Test, steps, train.Cameras);
            if (scene.Split("val").Any())
                warnings.Add(new ValidationProblem("val", scene.Split("val").Count() + " frames",
                    "are not exported: the layout has a training sequence (train_meta.json) and, here, the test split as test_meta.json.",
                    "Nothing to do, or capture the views you want to evaluate as the test split."));
            if (scene.PointCloudPath == null)
                throw Refuse("points3d.ply", "missing", "holds the target's surface at the first time step, which init_pt_cld.npz is made from (train.py:38); this dataset has none of this plugin's.",
                    "Capture again with pointCloudPoints above 0 in the settings (the window's Outputs step: points3d.ply points), e.g. 100000.");
            var masks = scene.HasMasks;
            var background = Background(config, masks, warnings);

            var reach = scene.TargetReach;
            var surface = PlyReader.Read(Path.Combine(root, scene.PointCloudPath));
            var floor = reach.HasValue ? Dynamic3DGaussians.FloorUnder(reach.Value) : surface.Count > 0 ? surface.Min(p => p.Position.Z) : 0;
            if (!reach.HasValue)
                warnings.Add(new ValidationProblem("dataset_config.json: target", "missing", "does not say how far the target reaches, so the floor plane (y = 0, train.py:114) is put under the first step's points; content moving lower is pushed up by the floor loss.",
                    "Re-capture with this plugin's current version, which records the target's reach."));
            var world = Dynamic3DGaussians.World(floor);

            outDir = Path.GetFullPath(outDir);
            var trainMeta = Path.Combine(outDir, Dynamic3DGaussians.TrainMetaFileName);
            var testMeta = test == null ? null : Path.Combine(outDir, Dynamic3DGaussians.TestMetaFileName);
            var cloud = Path.Combine(outDir, Dynamic3DGaussians.PointCloudFileName);
            var ims = Path.Combine(outDir, Dynamic3DGaussians.ImagesFolder);
            var seg = Path.Combine(outDir, Dynamic3DGaussians.SegmentationFolder);
            foreach (var path in new[] { trainMeta, testMeta, cloud, ims, seg }.Where(p => p != null)) DatasetConverter.EnsureAbsent(path);

            var written = new List<string>();
            foreach (var grid in new[] { train, test }.Where(g => g != null))
                for (var t = 0; t < steps; t++)
                    for (var c = 0; c < grid.Cameras; c++)
                        written.AddRange(WriteImages(scene, grid.Frames[t, c], masks, Dynamic3DGaussians.FileName(grid.FirstId + c, t), ims, seg, staged));
            staged.WriteNewText(trainMeta, Meta(scene.Intrinsics, train, steps, world));
            written.Add(trainMeta);
            if (test != null)
            {
                staged.WriteNewText(testMeta, Meta(scene.Intrinsics, test, steps, world));
                written.Add(testMeta);
            }
            var centres = Enumerable.Range(0, train.Cameras).Select(c => world.MultiplyPoint(train.Frames[0, c].Centre)).ToList();
            var data = Dynamic3DGaussians.InitialCloud(surface, world, centres, background, out var rows);
            staged.WriteNewBytes(cloud, NumpyFiles.Npz(Dynamic3DGaussians.PointCloudKey, NumpyFiles.Float32Matrix(data, rows, 7)));
            written.Add(cloud);
            return new ConversionResult(outDir, trainMeta, written, warnings, new[]
            {
                "copy " + outDir + " to Dynamic3DGaussians/data/<sequence>/, put \"<sequence>\" in train.py's sequence list (line 223), then: python train.py",
            });
        }

        /// <summary>The recorded number of time steps of a multi-view capture; anything else is refused.</summary>
        static int MultiViewSteps(DatasetConfig config, string root)
        {
            var time = config?.Time;
            var mode = time?.Mode;
            if (mode != TimeModes.Name(TimeMode.MultiView) || !(time.Steps >= 1))
                throw Refuse(DatasetLayout.ConfigFileName + ": time.mode", ModeShown(config, time, mode),
                    "is not a multi-view capture: Dynamic 3D Gaussians fits each time step to every camera at that step (train.py:17, md['fn'][t]).",
                    "Capture with time.mode \"multi-view\" (see Documentation~/dynamic-capture.md).");
            return time.Steps.Value;
        }

        /// <summary>The capture's time mode as a user would write it: a dataset without a time record is static.</summary>
        static string ModeShown(DatasetConfig config, RecordedTime time, string mode)
        {
            if (mode != null) return "\"" + mode + "\"";
            if (config == null) return "unknown (no " + DatasetLayout.ConfigFileName + " of this plugin)";
            return time == null ? "\"" + TimeModes.Name(TimeMode.Static) + "\" (no time record: a still capture)" : "missing";
        }

        /// <summary>The split's frames by (time_step, camera_id) — each exactly once — or null for an empty split.</summary>
        static Grid ReadGrid(ExportScene scene, DatasetSplit split, int steps, int firstId)
        {
            var name = DatasetSplits.Name(split);
            var frames = scene.Split(name).ToList();
            if (frames.Count == 0) return null;
            var file = DatasetLayout.TransformsFileName(split);
            // BlenderDatasetLoader keeps every frame in file order or fails, with its time keys (ExportFrame.Timing).
            if (frames.Count % steps != 0)
                throw Refuse(file, frames.Count + " frames", "is not " + steps + " time steps × the same number of cameras.", "Re-capture the split in multi-view mode.");
            var grid = new Grid { Cameras = frames.Count / steps, FirstId = firstId };
            grid.Frames = new ExportFrame[steps, grid.Cameras];
            for (var i = 0; i < frames.Count; i++)
            {
                var t = frames[i].Timing;
                if (!(t.Step is int step) || !(t.Camera is int camera) || step < 0 || step >= steps ||
                    camera < 0 || camera >= grid.Cameras || grid.Frames[step, camera] != null)
                    throw Refuse(file + ": frames[" + i + "]", (t.StepText ?? "no time_step") + ", " + (t.CameraText ?? "no camera_id"),
                        "is not a new (time_step < " + steps + ", camera_id < " + grid.Cameras + ") pair; every camera must appear once at every step.",
                        "Re-capture the split (nerf-dataset validate lists what is missing).");
                grid.Frames[step, camera] = frames[i];
            }
            return grid;
        }

        /// <summary>The background for the shell points: black over a transparent capture (the images are composited on it), else the capture's colour.</summary>
        static Vector3d Background(DatasetConfig config, bool masks, List<ValidationProblem> warnings)
        {
            var text = config?.BackgroundText;
            var background = BackgroundSettings.Parse(text) ?? new BackgroundSettings();
            if (background.Transparent) return Vector3d.Zero;
            if (!masks)
                throw Refuse("settings.background", text, "is opaque, so the images' alpha does not tell the target from the background and there are no mask images to make seg/ from.",
                    "Capture with a transparent background or with masks in the train and test splits.");
            return new Vector3d(background.R, background.G, background.B);
        }

        static IEnumerable<string> WriteImages(ExportScene scene, ExportFrame frame, bool masks, string name, string ims, string seg, StagedOutput staged)
        {
            var image = Decode(scene.RootDirectory, frame.ImagePath);
            var mask = masks ? Decode(scene.RootDirectory, frame.MaskPath) : image;
            if (!masks && image.ColorType != PngInfo.ColorTypeRgba)
                throw Refuse("file_path", frame.ImagePath, "has no alpha and no mask image, so seg/ cannot be made.", "Capture with a transparent background or with masks.");
            var rgb = Path.Combine(ims, name);
            var segPath = Path.Combine(seg, name);
            staged.WriteNewBytes(rgb, PngWriter.Encode(Dynamic3DGaussians.RgbOverBlack(image), image.Width, image.Height, PngPixelFormat.Rgb8));
            staged.WriteNewBytes(segPath, PngWriter.Encode(Dynamic3DGaussians.Segmentation(mask), mask.Width, mask.Height, PngPixelFormat.Gray8));
            return new[] { rgb, segPath };
        }

        static PngImage Decode(string root, string relative)
        {
            try
            {
                var image = PngReader.Read(Path.Combine(root, relative));
                if (image.BitDepth != 8) throw new InvalidDataException(relative + " is " + image.BitDepth + "-bit; 8-bit images are expected.");
                return image;
            }
            catch (InvalidDataException e)
            {
                throw Refuse("file_path", relative, e.Message, "Re-capture the dataset with this plugin.");
            }
        }

        static string Meta(CameraIntrinsics intrinsics, Grid grid, int steps, Matrix4x4d world)
        {
            var k = Dynamic3DGaussians.K(intrinsics);
            var meta = new JObject
            {
                ["w"] = intrinsics.Width,
                ["h"] = intrinsics.Height,
                ["k"] = PerStep(grid, steps, (t, c) => Rows(k)),
                ["w2c"] = PerStep(grid, steps, (t, c) => Rows(Dynamic3DGaussians.WorldToCamera(grid.Frames[t, c].CameraToWorld, world).ToRows())),
                ["fn"] = PerStep(grid, steps, (t, c) => Dynamic3DGaussians.FileName(grid.FirstId + c, t)),
                ["cam_id"] = PerStep(grid, steps, (t, c) => grid.FirstId + c),
            };
            return meta.ToString(Formatting.None);
        }

        static JArray PerStep(Grid grid, int steps, Func<int, int, JToken> value)
        {
            var all = new JArray();
            for (var t = 0; t < steps; t++)
            {
                var step = new JArray();
                for (var c = 0; c < grid.Cameras; c++) step.Add(value(t, c));
                all.Add(step);
            }
            return all;
        }

        static JArray Rows(double[][] rows) => new JArray(rows.Select(r => new JArray(r.Select(v => (object)v).ToArray())).ToArray<object>());

        static InvalidParameterException Refuse(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
