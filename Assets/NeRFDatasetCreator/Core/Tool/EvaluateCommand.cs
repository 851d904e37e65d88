using System;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset evaluate d --renders r …</c>: <see cref="RenderEvaluator.Run"/>, then the means and where the
    /// report is. Exit 1 when the inputs are refused (nothing written) or a file fails.
    /// </summary>
    public static class EvaluateCommand
    {
        public static readonly ToolCommand Command = ToolCommand.Of("evaluate",
            "evaluate <dir> --renders <dir> [--inverse <dir>] [--split test|sparse_<n>] [--out <dir>] [--layout 3dgs|nerfstudio|ngp|nerf-pytorch|plain] [--background white|black|dataset [--override-protocol]] [--trainer-metrics <json>] [--render-depth z|ray] [--geometry <recon.ply|.obj|folder> [--gt-mesh <mesh>] [--threshold <units>] [--step <k>]]",
            "score a trainer's renders (PSNR, SSIM, depth, normals, Chamfer/F-score): metrics.json, error maps, report.html", Parse, Run, "override-protocol").WithOptions(
            "--renders <dir>               the trainer's renders of the split (3DGS model folder, ns-render --output-path, instant-ngp --screenshot_dir, or r_<i>.png)",
            "--inverse <dir>               a relightable model's albedo/, normal/, roughness/, relit/<key>/ (r_<i>.png|.exr): TensoIR's albedo PSNR, normal MAE, relit PSNR/SSIM, R3DG's roughness MSE (--renders may then be left out)",
            "--flow <dir>                  instead: a model's flow (<video>/flow_<a>_<b>.flo) and tracks (<video>/tracks_<q>.npz) against the dataset's flow/: EPE, PCK-T",
            "--split test|val|train        the split the renders show (default: eval_protocol.json's, else test)",
            "--split sparse_<n>            score only the test views splits/sparse_<n>.json lists (nerf-dataset splits)",
            "--out <dir>                   where metrics.json, report.html and the error maps go (default <renders>/evaluation-<split>)",
            "--layout 3dgs|nerfstudio|ngp|nerf-pytorch|plain  how the renders are named (default: detected)",
            "--background white|black|dataset    what the dataset's transparent pixels are composited on (default: eval_protocol.json's, else white)",
            "--override-protocol           score over a --background that contradicts eval_protocol.json, or renders of another background, with a warning",
            "--trainer-metrics <json>      3DGS metrics.py's results.json or ns-eval's JSON, shown beside (default: <model>/results.json for 3DGS renders)",
            "--render-depth z|ray          the renders' depth: z-depth (splatfacto) or distance along the ray (nerfacto)",
            "--geometry <recon.ply|.obj|folder>  also score a reconstructed surface (Chamfer, F-score)",
            "--gt-mesh <mesh>              the ground-truth mesh for --geometry, in the output frame (.ply or .obj)",
            "--threshold <units>           the F-score distance, in output units",
            "--step <k>                    the time step of --geometry (dynamic captures)");

        /// <summary><c>evaluate &lt;dataset&gt; --renders &lt;dir&gt; [options]</c> → <see cref="EvaluationOptions"/>.</summary>
        static EvaluationOptions Parse(ToolArguments arguments)
        {
            arguments.RefuseUnknownOptions("renders", "inverse", "flow", "split", "out", "layout", "background", "override-protocol", "trainer-metrics", "render-depth", "geometry", "gt-mesh", "threshold", "step");
            var e = new EvaluationOptions();
            e.DatasetFolder = arguments.OnePositional("evaluate needs exactly one dataset folder, e.g. evaluate NeRFDatasets/lego --renders output/lego.");
            if (arguments.Has("flow")) return ParseFlow(arguments, e);
            e.InverseFolder = arguments.OptionalPath("inverse", "--inverse is empty; name the folder with albedo/, normal/, roughness/ or relit/<key>/, or leave it out.");
            if ((!arguments.TryGet("renders", out var renders) || string.IsNullOrWhiteSpace(renders)) && e.InverseFolder == null)
                arguments.Error("evaluate needs --renders <folder>: the trainer's renders of the split (3DGS model folder, ns-render dataset's --output-path, instant-ngp --screenshot_dir, or r_<i>.png files).");
            e.RendersFolder = renders;
            // sparse_<n>: a split file (splits/sparse_<n>.json), checked against the dataset when it is read; anything else
            // is read (and refused) as every command reads --split.
            if (arguments.TryGet("split", out var splitName) && SparseSplit.IsFileName(splitName + ".json")) e.SplitFile = splitName;
            else e.Split = arguments.Split();
            e.OutFolder = arguments.OptionalPath("out", "--out is empty; leave it out to write into <renders>/evaluation-<split>.");
            if (arguments.TryGet("layout", out var layout))
            {
                if (RenderLayouts.TryParse(layout, out var parsed)) e.Layout = parsed;
                else arguments.Error("--layout = " + layout + ": is not " + string.Join(", ", RenderLayouts.Names) + ".");
            }
            if (arguments.TryGet("background", out var background))
            {
                if (Array.IndexOf(EvaluationBackground.Names, background) < 0) arguments.Error("--background = " + background + ": is not white, black or dataset.");
                else e.Background = background;
            }
            e.OverrideProtocol = arguments.Flag("override-protocol");
            e.TrainerMetricsPath = arguments.OptionalPath("trainer-metrics", "--trainer-metrics is empty; name 3DGS's results.json or ns-eval's JSON, or leave it out.");
            if (arguments.TryGet("render-depth", out var depth))
            {
                if (depth == "ray") e.DepthAlongRay = true;
                else if (depth != "z") arguments.Error("--render-depth = " + depth + ": is not z (z-depth, splatfacto) or ray (distance along the ray, nerfacto).");
            }
            arguments.TryGet("geometry", out var geometry);
            e.GeometryPath = geometry;
            if (arguments.TryGet("gt-mesh", out var mesh))
            {
                e.TruthMeshPath = mesh;
                if (geometry == null) arguments.Error("--gt-mesh is the ground truth for --geometry; give --geometry <reconstruction> too.");
            }
            if (arguments.Has("threshold"))
            {
                e.Threshold = arguments.PositiveNumber("threshold", t => "--threshold = " + t + ": must be a distance > 0 in output units, e.g. 0.01.");
                if (geometry == null) arguments.Error("--threshold is the F-score threshold of --geometry; give --geometry <reconstruction> too.");
            }
            if (arguments.Has("step"))
            {
                e.Step = arguments.WholeNumber("step", 0, k => "--step = " + k + ": must be a time step number ≥ 0 (the train views' time_step), e.g. --step 0.");
                if (geometry == null) arguments.Error("--step picks the time step of --geometry; give --geometry <reconstruction> too.");
            }
            return e;
        }

        /// <summary><c>evaluate &lt;dataset&gt; --flow &lt;folder&gt; [--out &lt;dir&gt;]</c>: motion is scored on its own, without the image options.</summary>
        static EvaluationOptions ParseFlow(ToolArguments arguments, EvaluationOptions e)
        {
            e.FlowFolder = arguments.OptionalPath("flow", "--flow is empty; name the folder of the model's <video>/flow_<a>_<b>.flo and <video>/tracks_<q>.npz.");
            e.OutFolder = arguments.OptionalPath("out", "--out is empty; leave it out to write into <flow folder>/evaluation-flow.");
            foreach (var other in new[] { "renders", "inverse", "split", "layout", "background", "override-protocol", "trainer-metrics", "render-depth", "geometry", "gt-mesh", "threshold", "step" })
                if (arguments.Has(other)) arguments.Error("--" + other + " is for rendered images; --flow scores motion on its own: evaluate <dataset> --flow <folder> [--out <dir>].");
            return e;
        }

        /// <summary>The command line of the Dataset Tools' Evaluate button: <c>evaluate &lt;dataset&gt; --renders &lt;folder&gt;</c> with the tool's defaults (the protocol's split and background, layout detected).</summary>
        public static string[] Arguments(string datasetFolder, string rendersFolder) =>
            new[] { Command.Name, ToolArguments.Required(datasetFolder), "--renders", ToolArguments.Required(rendersFolder) };

        public static int Run(EvaluationOptions options, TextWriter stdout, TextWriter stderr)
        {
            if (options.FlowFolder != null) return RunFlow(options, stdout, stderr);
            if (options.InverseFolder != null)
            {
                var code = RunInverse(options, stdout, stderr);
                if (code != ToolExitCodes.Success || options.RendersFolder == null) return code;
            }
            if (!Attempt(() => RenderEvaluator.Run(options, line => stderr.WriteLine("… " + line)), stderr, out EvaluationResult result)) return ToolExitCodes.Failure;
            foreach (var note in result.Notes.Concat(result.Renders.Notes).Concat(result.Trainer?.Notes ?? Enumerable.Empty<string>())) stdout.WriteLine("note: " + note);
            foreach (var warning in result.Warnings) stderr.WriteLine("warning: " + warning);
            var json = MetricsJson.Build(result);
            var mean = json["mean"];
            stdout.WriteLine("protocol: " + (result.Protocol != null ? result.Protocol.Describe() + " (" + EvalProtocolFile.FileName + ")" : "none (the dataset has no " + EvalProtocolFile.FileName + "): defaults used"));
            stdout.WriteLine("evaluated " + result.Views.Count + " " + result.Split + " views (" + RenderLayouts.Name(result.Renders.Layout) + " layout, background " + result.Background.Name + "):");
            var identical = (int)mean["identical_views"];
            stdout.WriteLine("  PSNR " + Show(mean["psnr"], "0.00") + " dB" + (identical > 0 ? " (" + identical + " identical views, PSNR ∞, left out)" : "") + ", SSIM " + Show(mean["ssim"], "0.0000") +
                             (mean["psnr_masked"] != null ? ", PSNR in mask " + Show(mean["psnr_masked"], "0.00") + " dB" : ""));
            stdout.WriteLine("  (SSIM in double precision; 3DGS metrics.py runs it in float32 and prints values up to ~2e-4 different)");
            if (result.Trainer != null && (result.Trainer.Psnr.HasValue || result.Trainer.Lpips.HasValue))
            {
                var t = json["trainer_metrics"];
                stdout.WriteLine("  " + result.Trainer.Source + " (" + result.Trainer.Method + "): PSNR " + Show(t["psnr"], "0.00") + " dB, SSIM " + Show(t["ssim"], "0.0000") + ", LPIPS " + Show(t["lpips"], "0.0000") +
                                 " (" + result.Trainer.LpipsVariant + ")" + (result.TrainerFlaggedViews.Count > 0 ? "; " + result.TrainerFlaggedViews.Count + " views' PSNR differ beyond the tolerance" : ""));
            }
            if (mean["depth"] != null) stdout.WriteLine("  depth abs-rel " + Show(mean["depth"]["abs_rel"], "0.0000") + ", RMSE " + Show(mean["depth"]["rmse"], "0.0000") + ", δ<1.25 " + Show(mean["depth"]["delta_1_25"], "0.0000"));
            if (mean["normals"] != null) stdout.WriteLine("  normals " + Show(mean["normals"]["mean_degrees"], "0.00") + "° mean angular error");
            if (result.Geometry != null)
            {
                var g = json["geometry"];
                stdout.WriteLine("  geometry: Chamfer " + Show(g["chamfer"], "0.00000") + " (accuracy " + Show(g["accuracy"], "0.00000") + ", completeness " + Show(g["completeness"], "0.00000") +
                                 "), F-score " + Show(g["fscore"], "0.0000") + " at " + Show(g["threshold"], "0.#####") + " output units");
            }
            if (result.GeometrySteps.Count > 0)
            {
                var g = json["geometry_mean_over_steps"];
                stdout.WriteLine("  geometry over " + result.GeometrySteps.Count + " time steps: mean Chamfer " + Show(g["chamfer"], "0.00000") + " (accuracy " + Show(g["accuracy"], "0.00000") +
                                 ", completeness " + Show(g["completeness"], "0.00000") + "), mean F-score " + Show(g["fscore"], "0.0000"));
                foreach (var step in json["geometry_steps"])
                    stdout.WriteLine("    step " + step["step"] + ": Chamfer " + Show(step["chamfer"], "0.00000") + ", F-score " + Show(step["fscore"], "0.0000"));
            }
            else if (result.Geometry?.Step != null) stdout.WriteLine("  geometry at time step " + result.Geometry.Step.Value);
            if (result.Trainer?.Lpips == null) stdout.WriteLine("  LPIPS is not computed (it needs network weights): 3DGS python metrics.py -m <model>, nerfstudio ns-eval; evaluate shows their figures (--trainer-metrics).");
            stdout.WriteLine("wrote " + Path.Combine(result.OutFolder, MetricsJson.FileName) + ", " + Path.Combine(result.OutFolder, ReportHtml.FileName) + " and " + result.Views.Count + " error maps in " +
                             Path.Combine(result.OutFolder, EvaluationOutput.ErrorFolder));
            return ToolExitCodes.Success;
        }

        static int RunFlow(EvaluationOptions options, TextWriter stdout, TextWriter stderr)
        {
            if (!Attempt(() => FlowEvaluation.Run(options.DatasetFolder, options.FlowFolder, options.OutFolder), stderr, out FlowEvaluationResult result)) return ToolExitCodes.Failure;
            var c = System.Globalization.CultureInfo.InvariantCulture;
            if (result.Pairs.Count > 0)
                stdout.WriteLine("flow of " + result.Pairs.Count + " frame pairs: EPE " + result.EpeVisible.ToString("0.000", c) + " px on pixels visible in both frames, " + result.EpeAll.ToString("0.000", c) + " px on all pixels with a surface");
            else stdout.WriteLine("flow: not scored (the folder has no .flo files)");
            if (result.Tracks.Count > 0)
                stdout.WriteLine("tracks of " + result.Tracks.Count + " query frames: PCK-T " + result.PckT.ToString("0.0000", c) + " (within " + result.Tracks[0].Threshold.ToString("0.##", c) + " px = 0.05 × the larger image side, DyCheck's)");
            else stdout.WriteLine("tracks: not scored (the folder has no tracks_<q>.npz)");
            stdout.WriteLine("wrote " + Path.Combine(result.OutFolder, FlowEvaluation.FileName));
            return ToolExitCodes.Success;
        }

        /// <summary>
        /// Runs one evaluation: a refusal (<see cref="InvalidParameterException"/>, nothing written) or a file it cannot
        /// read (<see cref="InvalidDataException"/>) is printed as the tool's error lines and gives false.
        /// </summary>
        static bool Attempt<T>(Func<T> run, TextWriter stderr, out T result)
        {
            result = default;
            try
            {
                result = run();
                return true;
            }
            catch (InvalidParameterException e)
            {
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                stderr.WriteLine("evaluate refused: nothing was written.");
            }
            catch (InvalidDataException e)
            {
                stderr.WriteLine("error: " + e.Message);
                stderr.WriteLine("evaluate stopped on a file it cannot read.");
            }
            return false;
        }

        /// <summary><c>--inverse</c>: <see cref="InverseRenderingEvaluator"/>, then its figures.</summary>
        static int RunInverse(EvaluationOptions options, TextWriter stdout, TextWriter stderr)
        {
            var split = options.Split ?? "test";
            var outFolder = options.ResolvedOutFolder(options.InverseFolder, split);
            if (!Attempt(() => InverseRenderingEvaluator.Run(options.DatasetFolder, options.InverseFolder, split, outFolder), stderr, out Newtonsoft.Json.Linq.JObject json)) return ToolExitCodes.Failure;
            stdout.WriteLine("inverse rendering, " + json["views"] + " " + split + " views:");
            if (json["albedo"] is Newtonsoft.Json.Linq.JObject albedo)
                stdout.WriteLine("  albedo PSNR " + Show(albedo["psnr_tensoir_three_channel_global"], "0.00") + " dB (TensoIR's three-channel global median scaling; single-channel " + Show(albedo["psnr_single_channel_global"], "0.00") +
                                 ", per view " + Show(albedo["psnr_three_channel_per_view"], "0.00") + " / " + Show(albedo["psnr_single_channel_per_view"], "0.00") + " dB)");
            if (json["normals"] is Newtonsoft.Json.Linq.JObject normals)
                stdout.WriteLine("  normals " + Show(normals["mae_degrees_all_pixels"], "0.00") + "° mean angular error over all pixels (TensoIR's), " + Show(normals["mae_degrees_target"], "0.00") + "° over the target");
            if (json["roughness"] is Newtonsoft.Json.Linq.JObject roughness)
                stdout.WriteLine("  roughness MSE " + Show(roughness["mse"], "0.00000") + " (R3DG's, alpha-masked)");
            if (json["relit"] is Newtonsoft.Json.Linq.JObject relit)
                foreach (var pair in relit)
                    stdout.WriteLine("  relit " + pair.Key + ": PSNR " + Show(pair.Value["psnr"], "0.00") + " dB, SSIM " + Show(pair.Value["ssim"], "0.0000"));
            stdout.WriteLine("wrote " + Path.Combine(outFolder, InverseRenderingEvaluator.FileName));
            return ToolExitCodes.Success;
        }

        static string Show(Newtonsoft.Json.Linq.JToken token, string format) =>
            token == null || token.Type == Newtonsoft.Json.Linq.JTokenType.Null ? "—" : ((double)token).ToString(format, System.Globalization.CultureInfo.InvariantCulture);
    }
}
