using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to dynerf</c>: a multi-view dynamic capture as 4DGaussians reads an N3DV scene (<see cref="Dynerf"/>):
    /// <c>poses_bounds.npy</c> (one row per camera, exact near / far over all its frames from the depth maps,
    /// <see cref="DepthBounds"/>), <c>camNN/images/0000.png</c> … (RGB over the protocol background), an empty
    /// <c>camNN.mp4</c> per camera and <c>points3D_downsample2.ply</c> (the capture's points3d.ply). cam00 is the test
    /// split's first camera (4DGaussians holds out camera 0); cam01 … are the train cameras.
    /// </summary>
    public static class DynerfExport
    {
        const string Target = "dynerf";

        public static ConversionResult Write(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged)
        {
            var k = scene.Intrinsics;
            InvalidParameterException.ThrowIfAny(Llff.LensRefusal(scene.Lens, Target), Llff.CameraRefusal(k, Target));
            var steps = MultiViewSteps(scene.RootDirectory);
            if (!Dynerf.FourByThree(k.Width, k.Height))
                throw Refuse("width × height", k.Width + " × " + k.Height,
                    "is not 4:3, and 4DGaussians resizes every N3DV image to " + Dynerf.LoaderWidth + " × " + Dynerf.LoaderHeight + " (scene/neural_3D_dataset_NDC.py:229–230), which would stretch it.",
                    "Capture at a 4:3 size, e.g. " + Dynerf.LoaderWidth + " × " + Dynerf.LoaderHeight + " or 1024 × 768.");
            if (steps > Dynerf.MaxFrames)
                throw Refuse(DatasetLayout.ConfigFileName + ": time.steps", steps.ToString(CultureInfo.InvariantCulture),
                    "time steps, but 4DGaussians reads at most " + Dynerf.MaxFrames + " images a camera (scene/neural_3D_dataset_NDC.py:310, 349) and would drop the rest.",
                    "Capture at most " + Dynerf.MaxFrames + " time steps.");
            var test = Grid(scene, "test", steps);
            if (test == null)
                throw Refuse("splits.test", "0 frames", "is empty, and 4DGaussians always holds out camera 0 of an N3DV scene as its test camera (scene/dataset_readers.py:453, 462, eval_index=0).",
                    "Capture a test split of at least one camera.");
            var train = Grid(scene, "train", steps);
            if (train == null)
                throw Refuse("splits.train", "0 frames", "is empty: 4DGaussians trains on every camera but cam00.", "Capture a train split.");
            if (scene.PointCloudPath == null)
                throw Refuse("points3d.ply", "missing", "is the target's surface at the first time step, which 4DGaussians reads as points3D_downsample2.ply (scene/dataset_readers.py:444, 469); this dataset has none of this plugin's.",
                    "Capture again with pointCloudPoints above 0 in the settings (the window's Outputs step), e.g. 100000.");
            // cam00 = the test split's first camera; cam01 … = the train cameras in camera_id order.
            var cameras = new List<ExportFrame[]> { test[0] };
            cameras.AddRange(train);
            if (test.Count > 1)
                warnings.Add(new ValidationProblem("splits.test", test.Count + " cameras",
                    "but 4DGaussians holds out camera 0 only: cam00 is test camera 0, and test cameras 1 … " + (test.Count - 1) + " are not exported (as train cameras they would be trained on).",
                    "Nothing to do, or capture one test camera."));
            if (scene.Split("val").Any())
                warnings.Add(new ValidationProblem("val", scene.Split("val").Count() + " frames", "are not exported: an N3DV scene is train cameras and one test camera.",
                    "Nothing to do, or capture the views you want to evaluate as the test split."));

            var all = cameras.SelectMany(c => c).ToList();
            var frameBounds = DepthBounds.Of(scene, all, Target, warnings);
            outDir = Path.GetFullPath(outDir);
            var posesFile = Path.Combine(outDir, Llff.PosesBoundsFileName);
            var ply = Path.Combine(outDir, Dynerf.PointCloudFileName);
            var names = Enumerable.Range(0, cameras.Count).Select(c => Dynerf.CameraName(c, cameras.Count)).ToList();
            var destinations = new List<string> { posesFile, ply };
            foreach (var name in names)
            {
                destinations.Add(Path.Combine(outDir, name + ".mp4"));
                destinations.Add(Path.Combine(outDir, name));
            }
            foreach (var path in destinations) DatasetConverter.EnsureAbsent(path);

            var background = ProtocolBackground.For(scene.RootDirectory);
            var values = new double[cameras.Count * 17];
            var written = new List<string>();
            var focal = Dynerf.FileFocal(k.FlX, k.Width);
            for (var c = 0; c < cameras.Count; c++)
            {
                var near = Enumerable.Range(c * steps, steps).Min(i => frameBounds[i].Near);
                var far = Enumerable.Range(c * steps, steps).Max(i => frameBounds[i].Far);
                var row = Llff.Row(cameras[c][0].CameraToWorld, Dynerf.FocalHeight, Dynerf.FocalWidth, focal, near, far);
                Array.Copy(row, 0, values, 17 * c, 17);
                var video = Path.Combine(outDir, names[c] + ".mp4");
                staged.WriteNewBytes(video, new byte[0]);
                written.Add(video);
                for (var t = 0; t < steps; t++)
                {
                    var to = Path.Combine(outDir, names[c], "images", Dynerf.ImageName(t));
                    ExportRgb.Write(scene.RootDirectory, cameras[c][t].ImagePath, to, (background.R, background.G, background.B), staged);
                    written.Add(to);
                }
            }
            staged.WriteNewBytes(posesFile, NumpyFiles.Float64Matrix(values, cameras.Count, 17));
            staged.Copy(Path.Combine(scene.RootDirectory, scene.PointCloudPath), ply);
            written.Add(posesFile);
            written.Add(ply);
            if (k.Width != Dynerf.LoaderWidth || k.Height != Dynerf.LoaderHeight)
                warnings.Add(new ValidationProblem("width × height", k.Width + " × " + k.Height,
                    "is resized by 4DGaussians to " + Dynerf.LoaderWidth + " × " + Dynerf.LoaderHeight + " (LANCZOS) as it loads each image (scene/neural_3D_dataset_NDC.py:371); the focal is written for that.",
                    "Nothing to do, or capture at " + Dynerf.LoaderWidth + " × " + Dynerf.LoaderHeight + " to train on the pixels as captured."));
            if (outDir.IndexOf('.') >= 0)
                warnings.Add(new ValidationProblem(ExportOutputField, outDir,
                    "contains a '.', and 4DGaussians finds each camera's images at video_path.split('.')[0] + \"/images\" (scene/neural_3D_dataset_NDC.py:321): it would look in the wrong folder.",
                    "Move the folder to a path without '.', and pass it to train.py without a leading ./"));
            warnings.Add(new ValidationProblem("time", steps + " time steps",
                "are read by 4DGaussians with time k / " + Dynerf.MaxFrames + " for image k (scene/neural_3D_dataset_NDC.py:356), not the capture's normalised time k / " + (steps - 1) + "; the camNN.mp4 files are empty placeholders (never opened while camNN/images exists).",
                "Nothing to do; keep the camNN/images folders beside the .mp4 files."));
            return new ConversionResult(outDir, posesFile, written, warnings, new[]
            {
                "4DGaussians: python train.py -s " + outDir + " --port 6017 --expname dynerf/<scene> --configs arguments/dynerf/default.py",
            });
        }

        const string ExportOutputField = DatasetConverter.ExportOutputField;

        /// <summary>The recorded number of time steps of a multi-view capture; a still or monocular capture is refused.</summary>
        static int MultiViewSteps(string root)
        {
            var config = DatasetConfig.Read(root).ThrowIfUnreadable().Config;
            var time = config?.Time;
            if (time?.Mode != TimeModes.Name(TimeMode.MultiView) || !(time.Steps >= 1))
                throw Refuse(DatasetLayout.ConfigFileName + ": time.mode", time?.Mode == null ? "\"static\" (no time record)" : "\"" + time.Mode + "\"",
                    "is not a multi-view capture: N3DV (dynerf) is one video per fixed camera, every camera at every time step.",
                    "Capture with time.mode \"multi-view\" (Documentation~/dynamic-capture.md), or convert a still capture to llff, neus or colmap.");
            return time.Steps.Value;
        }

        /// <summary>The split's cameras, each its frames by time step (every camera once at every step, fixed in place), or null for an empty split.</summary>
        static List<ExportFrame[]> Grid(ExportScene scene, string split, int steps)
        {
            var frames = scene.Split(split).ToList();
            if (frames.Count == 0) return null;
            var file = "transforms_" + split + ".json";
            if (frames.Count % steps != 0)
                throw Refuse(file, frames.Count + " frames", "is not " + steps + " time steps × the same number of cameras.", "Re-capture the split in multi-view mode.");
            var count = frames.Count / steps;
            var grid = Enumerable.Range(0, count).Select(_ => new ExportFrame[steps]).ToList();
            for (var i = 0; i < frames.Count; i++)
            {
                var t = frames[i].Timing;
                if (!(t.Step is int step) || !(t.Camera is int camera) || step < 0 || step >= steps || camera < 0 || camera >= count || grid[camera][step] != null)
                    throw Refuse(file + ": frames[" + i + "]", (t.StepText ?? "no time_step") + ", " + (t.CameraText ?? "no camera_id"),
                        "is not a new (time_step < " + steps + ", camera_id < " + count + ") pair; every camera must appear once at every step.",
                        "Re-capture the split (nerf-dataset validate lists what is missing).");
                grid[camera][step] = frames[i];
            }
            for (var c = 0; c < count; c++)
                for (var s = 1; s < steps; s++)
                    if (!SamePose(grid[c][0].CameraToWorld, grid[c][s].CameraToWorld))
                        throw Refuse(file + ": " + grid[c][s].ImagePath, "camera_id " + c + " at time_step " + s,
                            "has moved since time_step 0, and poses_bounds.npy holds one pose per N3DV camera.",
                            "Capture with fixed cameras (multi-view mode keeps each camera in place).");
            return grid;
        }

        static bool SamePose(Matrix4x4d a, Matrix4x4d b)
        {
            for (var r = 0; r < 3; r++)
                for (var c = 0; c < 4; c++)
                    if (Math.Abs(a[r, c] - b[r, c]) > 1e-9 * Math.Max(1, Math.Abs(a[r, c]))) return false;
            return true;
        }

        static InvalidParameterException Refuse(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
