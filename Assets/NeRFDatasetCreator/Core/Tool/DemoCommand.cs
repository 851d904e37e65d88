using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset demo &lt;dir&gt; [--preset P] [--views N] [--size PX]</c>: a small, trainable, checked dataset of the
    /// built-in analytic scene, written through the capture's own writers (<see cref="DemoDataset"/>), then the next
    /// commands (check, convert, train, evaluate). <c>demo &lt;dir&gt; --renders-for &lt;demo&gt;</c>: stand-in renders of a
    /// demo's test split for <c>evaluate</c> (<see cref="DemoRenders"/>). Exit 1 when the folder is refused (nothing is
    /// written) or the dataset fails its check.
    /// </summary>
    public static class DemoCommand
    {
        public static readonly ToolCommand Command = ToolCommand.Of("demo",
            "demo <dir> [--preset static|dynamic|labels|lens|exposure|blur|monocular|hdr|materials|relight|flow] [--views N] [--size PX] [--renders-for <dataset>]",
            "write a small trainable dataset of a built-in scene, no Unity needed (--renders-for: stand-in renders of a demo's test split, to try evaluate)",
            Parse, Run);

        public sealed class Options
        {
            /// <summary>Where the dataset (or, with <see cref="RendersFor"/>, the renders) goes: a new or empty folder, or an earlier demo.</summary>
            public string Folder { get; set; }

            public DemoPreset Preset { get; set; } = DemoPreset.Static;

            /// <summary><c>--views N</c>: train views (val a tenth, test a fifth; a dynamic capture spreads them over its time steps); null for the preset's default.</summary>
            public int? Views { get; set; }

            /// <summary><c>--size PX</c>: the images' width and height.</summary>
            public int Size { get; set; } = DemoDataset.DefaultSize;

            /// <summary><c>--renders-for &lt;dataset&gt;</c>: write stand-in renders of this demo dataset's test split instead of a dataset.</summary>
            public string RendersFor { get; set; }
        }

        static Options Parse(ToolArguments arguments)
        {
            arguments.RefuseUnknownOptions("preset", "views", "size", "renders-for");
            var options = new Options { Folder = arguments.OnePositional("demo needs exactly one folder to write into, e.g. demo demo/lego.") };
            if (arguments.TryGet("preset", out var preset))
            {
                var parsed = DemoPresets.Parse(preset, out var problem);
                if (problem != null) arguments.Error(problem.ToString());
                else options.Preset = parsed.Value;
            }
            var views = arguments.WholeNumber("views", DemoDataset.MinViews, v => "--views " + v + ": give the train views, a whole number from " + DemoDataset.MinViews + " to " + DemoDataset.MaxViews + ".");
            if (views > DemoDataset.MaxViews) arguments.Error("--views " + views + ": give the train views, a whole number from " + DemoDataset.MinViews + " to " + DemoDataset.MaxViews + ".");
            else options.Views = views;
            var size = arguments.WholeNumber("size", DemoDataset.MinSize, s => "--size " + s + ": give the image side in pixels, a whole number from " + DemoDataset.MinSize + " to " + DemoDataset.MaxSize + ".");
            if (size > DemoDataset.MaxSize) arguments.Error("--size " + size + ": give the image side in pixels, a whole number from " + DemoDataset.MinSize + " to " + DemoDataset.MaxSize + ".");
            else if (size != null) options.Size = size.Value;
            if (options.Preset == DemoPreset.Lens && options.Size < DemoDataset.MinLensSize)
                arguments.Error("--size " + options.Size + ": the lens preset needs " + DemoDataset.MinLensSize + " px or more (its depth and mask are resampled from a wide render, and smaller their edges disagree by more than check allows).");
            options.RendersFor = arguments.OptionalPath("renders-for", "--renders-for is empty; name the demo dataset whose test split to render, e.g. --renders-for demo/lego.");
            if (options.RendersFor != null && (arguments.Has("preset") || arguments.Has("views") || arguments.Has("size")))
                arguments.Error("--renders-for renders the views the demo dataset already has: leave out --preset, --views and --size.");
            return options;
        }

        /// <summary>The command line of the Dataset Tools' Demo button: <c>demo &lt;folder&gt; --preset &lt;preset&gt;</c>.</summary>
        public static string[] Arguments(string folder, DemoPreset preset) =>
            new[] { Command.Name, ToolArguments.Required(folder), "--preset", DemoPresets.Name(preset) };

        public static int Run(Options options, TextWriter stdout, TextWriter stderr) =>
            options.RendersFor != null ? RunRenders(options, stdout, stderr) : RunDataset(options, stdout, stderr);

        static int RunDataset(Options options, TextWriter stdout, TextWriter stderr)
        {
            DemoResult result;
            try
            {
                result = DemoDataset.Write(options.Folder, options.Preset, options.Views ?? DemoDataset.DefaultViewsFor(options.Preset), options.Size, line => stderr.WriteLine("… " + line));
            }
            catch (InvalidParameterException e)
            {
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                stderr.WriteLine("demo refused: nothing was written.");
                return ToolExitCodes.Failure;
            }
            var check = result.Check;
            stdout.WriteLine("demo " + DemoPresets.Name(result.Preset) + ": wrote " + result.Views + " views of " + options.Size + " × " + options.Size + " px into " + result.Folder +
                             " in " + result.RenderSeconds.ToString("0.0", CultureInfo.InvariantCulture) + " s (" + Contents(result.Preset) + ")");
            stdout.WriteLine("check: " + (check.Failed ? "FAILED, " + check.Problems.Count + (check.Problems.Count == 1 ? " problem" : " problems") : "passed") + ", " + check.ViewsChecked + " views in " +
                             check.TotalSeconds.ToString("0.0", CultureInfo.InvariantCulture) + " s; the report is " + Path.Combine(result.Folder, DatasetCheck.ReportFileName));
            foreach (var problem in check.Problems.Take(10)) stdout.WriteLine("problem: " + problem);
            if (check.Failed)
            {
                stderr.WriteLine("failed: the demo dataset did not pass its own check; please report this with " + DatasetCheck.ReportFileName + ".");
                return ToolExitCodes.Failure;
            }
            stdout.WriteLine("next:");
            foreach (var line in NextSteps(options.Folder, result.Preset, DatasetConfig.Read(result.Folder).Config?.TargetReach())) stdout.WriteLine("  " + line);
            return ToolExitCodes.Success;
        }

        static int RunRenders(Options options, TextWriter stdout, TextWriter stderr)
        {
            int written;
            try
            {
                written = DemoRenders.Write(options.RendersFor, options.Folder);
            }
            catch (InvalidParameterException e)
            {
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                stderr.WriteLine("demo refused: nothing was written.");
                return ToolExitCodes.Failure;
            }
            stdout.WriteLine("demo: wrote " + written + (written == 1 ? " STAND-IN render of " : " STAND-IN renders of ") + Path.GetFullPath(options.RendersFor) + "'s " + DemoRenders.Split + " split into " + Path.GetFullPath(options.Folder) +
                             " (traced from the demo's scene, deliberately imperfect; not a trained model: " + DemoRenders.NoteFileName + ")");
            stdout.WriteLine("next:");
            stdout.WriteLine("  " + Line("evaluate", options.RendersFor, "--renders", options.Folder));
            return ToolExitCodes.Success;
        }

        /// <summary>What the preset's dataset holds besides RGBA, depth, normals and masks.</summary>
        static string Contents(DemoPreset preset)
        {
            var extra = preset == DemoPreset.Dynamic ? ", " + DemoDataset.TimeSteps + " time steps with a moving sphere"
                : preset == DemoPreset.Labels ? ", instance and semantic maps with labels.json"
                : preset == DemoPreset.Lens ? ", an OpenCV lens (k1 −0.12, k2 0.02) at a 55° field of view"
                : preset == DemoPreset.Exposure ? ", random exposure with the clean images beside"
                : preset == DemoPreset.Blur ? ", camera-shake motion blur with the sharp images beside"
                : preset == DemoPreset.Monocular ? ", one camera moving around the target over time, " + ValidationProblem.Format(DemoDataset.MonocularFrameRate) + " views a second"
                : preset == DemoPreset.Hdr ? ", linear HDR colour (r_<i>_hdr.exr) beside each PNG"
                : preset == DemoPreset.Materials ? ", material passes (albedo, metallic, roughness, specular, emission: EXR + PNG) and material coverage"
                : preset == DemoPreset.Relight ? ", each view under an analytic sky at 3 rotations and a point light (r_<i>_light_<key>.png, HDR beside), lights/"
                : preset == DemoPreset.Flow ? ", one camera moving over time, the target's mesh at every step and its exact flow, occlusion and tracks (flow/)"
                : "";
            return "RGBA, depth, normals, masks" + extra + ", points3d.ply, the geometry pack";
        }

        /// <summary>
        /// The exports that fit the preset's dataset: the static ones (LLFF and NeuS for the plain static preset: they
        /// hold no lens), Gaussian Grouping with labels, the dynamic layouts (Dynamic 3D Gaussians, Nerfies, DyCheck,
        /// N3DV) for the dynamic one.
        /// </summary>
        public static IReadOnlyList<ExportTarget> Targets(DemoPreset preset)
        {
            if (preset == DemoPreset.Dynamic) return new[] { ExportTarget.Dynamic3dgs, ExportTarget.Nerfies, ExportTarget.Dycheck, ExportTarget.Dynerf };
            if (preset == DemoPreset.Monocular) return new[] { ExportTarget.Replica, ExportTarget.Tum };
            if (preset == DemoPreset.Flow) return new[] { ExportTarget.Replica, ExportTarget.Tum, ExportTarget.Kubric, ExportTarget.Nsff, ExportTarget.ShapeOfMotion };
            if (preset == DemoPreset.Hdr) return new[] { ExportTarget.HdrNerf };
            // The inverse-rendering layouts read the material passes and relit views; R3DG also the linear HDR colour the preset writes.
            if (preset == DemoPreset.Relight) return new[] { ExportTarget.Tensoir, ExportTarget.GsIr, ExportTarget.R3dg };
            var targets = new List<ExportTarget> { ExportTarget.Nerfstudio, ExportTarget.Colmap, ExportTarget.Ngp };
            if (preset == DemoPreset.Labels) targets.Add(ExportTarget.GaussianGrouping);
            // LLFF, NeuS and multiscale hold no lens (mip-NeRF's metadata is a pinhole): the plain static preset only.
            if (preset == DemoPreset.Static) targets.AddRange(new[] { ExportTarget.Llff, ExportTarget.Neus, ExportTarget.Multiscale });
            return targets;
        }

        /// <summary>
        /// The commands that follow a demo written into <paramref name="folder"/> (as the user typed it): check, one
        /// convert per export that fits, the trainers (comments: they run on a GPU machine, and each convert prints its
        /// exact line), stand-in renders and evaluate.
        /// </summary>
        /// <param name="targetReach">How far the target reaches (dataset_config.json), for nerfstudio's scale flags.</param>
        public static IReadOnlyList<string> NextSteps(string folder, DemoPreset preset, double? targetReach)
        {
            var lines = new List<string> { Line("check", folder) };
            var trains = new List<string>();
            foreach (var target in Targets(preset))
            {
                var name = ExportTargets.Name(target);
                var output = folder.TrimEnd('/', '\\') + "-" + name;
                lines.Add(Line("convert", folder, "--to", name, "--out", output));
                trains.Add("# " + TrainLine(target, output, targetReach));
            }
            lines.AddRange(trains);
            if (preset != DemoPreset.Dynamic && preset != DemoPreset.Monocular && preset != DemoPreset.Flow)
            {
                var renders = folder.TrimEnd('/', '\\') + "-renders";
                lines.Add(Line("demo", renders, "--renders-for", folder) + "   # stand-in renders: evaluate without a model");
                lines.Add(Line("evaluate", folder, "--renders", renders) + "   # writes " + renders + "/evaluation-test/" + ReportHtml.FileName);
            }
            return lines;
        }

        /// <summary>One trainer's command for an export at <paramref name="output"/> (Documentation~/exports.md); convert prints the exact one.</summary>
        static string TrainLine(ExportTarget target, string output, double? targetReach)
        {
            switch (target)
            {
                case ExportTarget.Nerfstudio: return NerfstudioTraining.Commands(output + "/" + NerfstudioWriter.FileName, targetReach)[0] + "   (nerfstudio)";
                case ExportTarget.Colmap: return "python train.py -s " + Quote(output) + " --eval   (3D Gaussian Splatting)";
                case ExportTarget.Ngp: return "./instant-ngp " + Quote(output + "/" + NgpWriter.FileName) + "   (instant-ngp, from its folder)";
                case ExportTarget.GaussianGrouping: return "python train.py -s " + Quote(output) + " -r 1 --config_file " + Quote(output + "/" + GaussianGrouping.ConfigFileName) + "   (Gaussian Grouping)";
                case ExportTarget.Nerfies: return "python train.py -s " + Quote(output) + " --configs arguments/hypernerf/default.py   (4DGaussians)";
                case ExportTarget.Dycheck: return "python tools/launch.py --gin_configs configs/iphone/tnerf/randbkgd_depth_dist.gin …   (DyCheck: copy " + Quote(output) + " to its datasets/iphone/ first, as convert says)";
                case ExportTarget.Llff: return "python run_nerf.py --dataset_type llff --datadir " + Quote(output) + " --factor 1 --no_ndc --spherify   (nerf-pytorch)";
                case ExportTarget.Neus: return "python exp_runner.py --mode train --conf ./confs/wmask.conf --case <case>   (NeuS: copy " + Quote(output) + " to public_data/<case>/ first)";
                case ExportTarget.Dynerf: return "python train.py -s " + Quote(output) + " --configs arguments/dynerf/default.py   (4DGaussians)";
                case ExportTarget.Replica:
                case ExportTarget.Tum: return "python slam.py --config " + Quote(output + "/" + Replica.MonoGsConfigFileName) + "   (MonoGS, from its folder; convert prints SplaTAM's and Gaussian-SLAM's)";
                case ExportTarget.Multiscale: return "python simple_trainer.py default --data_dir " + Quote(output + "/" + MultiscaleExport.ColmapFolder) + " --data_factor 4   (gsplat; mip-NeRF layout in " + Quote(output + "/" + MipNerfMultiscale.FolderName) + ")";
                case ExportTarget.Tensoir: return "export PYTHONPATH=. && python train_tensoIR_rotated_multi_lights.py --config configs/multi_light_rotated/lego.txt --datadir " + Quote(output) + "   (TensoIR; NeRFactor reads it too)";
                case ExportTarget.GsIr: return "python train.py -m outputs/scene/ -s " + Quote(output) + " --iterations 30000 --eval   (GS-IR stage 1)";
                case ExportTarget.R3dg: return "python train.py --eval -s " + Quote(output) + " -m output/scene/3dgs   (R3DG stage 1)";
                case ExportTarget.ShapeOfMotion: return "python run_training.py --work-dir " + Quote(output + "-run") + " data:iphone --data.data-dir " + Quote(output) + " --data.depth-type lidar --data.camera-type original   (Shape of Motion)";
                case ExportTarget.HdrNerf: return "python3 run_nerf.py --config configs/demo.txt --dataset_type syn_llff --datadir " + Quote(output) + " --white_bkgd   (HDR-NeRF)";
                case ExportTarget.Kubric: return "load_scene_directory(\"" + output + "/" + Kubric.ScenesFolder + "/train\", (H, W), layers=(\"rgba\", \"forward_flow\", \"backward_flow\"))   (Kubric / MOVi, challenges/movi/movi_e.py)";
                case ExportTarget.Nsff: return "python run_nerf.py --config configs/config_kid-running.txt --datadir " + Quote(output + "/train") + " --final_height <H> --end_frame <N> --target_idx <N-1>   (NSFF: convert prints the exact line)";
                default: return "python train.py   (Dynamic 3D Gaussians: copy " + Quote(output) + " to its data/ folder first, as convert says)";
            }
        }

        static string Line(string command, params string[] arguments) => "nerf-dataset " + command + " " + string.Join(" ", arguments.Select(Quote));

        static string Quote(string path) => path.IndexOf(' ') >= 0 ? "\"" + path + "\"" : path;
    }
}
