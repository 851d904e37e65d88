using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset convert d --to nerfstudio|colmap|ngp|dynamic3dgs [--out o] [--depths]</c>: <see cref="DatasetConverter.Convert"/>, then
    /// where the files went, the warnings, and the command that trains on the result. Exit 1 when the dataset cannot
    /// be converted or a destination file exists (nothing is overwritten).
    /// </summary>
    public static class ConvertCommand
    {
        public static readonly ToolCommand Command = ToolCommand.Of("convert",
            "convert <dir> --to nerfstudio|colmap|ngp|dynamic3dgs|gaussian-grouping|nerfies|dycheck|llff|dynerf|neus|replica|tum|multiscale|hdr-nerf|tensoir|gs-ir|r3dg|kubric|nsff|shape-of-motion [--out <dir>] [--images copy|link|relative] [--depths] [--binary] [--points N] [--min-track N] [--object <name|id>] [--background white|black|random|protocol [--seed N]]",
            "write a dataset in another trainer's format (--depths: colmap + 3DGS depth maps; --binary/--points/--min-track: the colmap model, tracks from depth; dynamic3dgs: multi-view dynamic captures; gaussian-grouping: object masks from the labels; --object: nerfstudio masks of one labelled object; llff, dynerf (N3DV, multi-view dynamic), neus: LLFF, 4DGaussians and NeuS layouts; replica, tum: RGB-D sequences of a monocular dynamic capture for SLAM; multiscale: gsplat's images_2/4/8 and mip-NeRF's multiscale layout; hdr-nerf: HDR-NeRF's exposure brackets from a capture with hdr; tensoir (also NeRFactor), gs-ir, r3dg: inverse-rendering layouts with albedo, normals, roughness and relit views; kubric, nsff: Kubric/MOVi and NSFF scenes with the optical flow of flow/; shape-of-motion: Shape of Motion's iPhone layout with the exact tracks of flow/)",
            Parse, Run, "depths", "binary").WithOptions(
            "--to <format>        nerfstudio, colmap (= 3dgs), ngp (= instant-ngp), dynamic3dgs, gaussian-grouping, nerfies (Nerfies, HyperNeRF, 4DGaussians), dycheck (DyCheck iPhone, exact depth), llff, dynerf, neus, replica, tum (SLAM sequences), multiscale (gsplat images_2/4/8, mip-NeRF multiscale) hdr-nerf (exposure brackets from the linear HDR colour), tensoir (TensoIR, NeRFactor), gs-ir, r3dg (Relightable 3D Gaussians), kubric or nsff (scenes with the flow of nerf-dataset flow)",
            "--out <dir>          where the export goes (default: the format's place inside the dataset)",
            "--images copy|link|relative  nerfstudio, ngp: copy the files transforms.json names into the export (default with --out outside the dataset: a self-contained folder), hard-link them (the same without a second copy on disk; copies where the disk cannot link), or name the dataset's by relative path (default inside the dataset)",
            "--depths             colmap: also 3D Gaussian Splatting's inverse-depth maps and depth_params.json",
            "--binary             colmap: cameras.bin, images.bin, points3D.bin instead of the text model",
            "--points N           colmap: the first N points of points3d.ply (default: all)",
            "--min-track N        colmap: the fewest images a point must be seen in (0 keeps every point)",
            "--object <name|id>   nerfstudio: mask every frame to this labelled object (labels.json)",
            "--background white|black|random|protocol  colmap, nerfstudio: RGB images composited over the colour (random: one per image; protocol: the dataset's), the alpha in masks/ beside them, into <dir>/<format>_<background>",
            "--seed N             --background random: the seed of the per-image colours (default 0)");

        public sealed class Options
        {
            /// <summary>The Blender-format dataset to read.</summary>
            public string DatasetFolder { get; set; }

            /// <summary><c>--to nerfstudio|colmap|ngp|dynamic3dgs|gaussian-grouping</c>.</summary>
            public ExportTarget? Target { get; set; }

            /// <summary><c>--out &lt;dir&gt;</c>: where the export goes; null for the format's default place inside the dataset.</summary>
            public string OutputFolder { get; set; }

            /// <summary><c>--depths</c>: also write 3DGS's inverse-depth maps and depth_params.json (colmap).</summary>
            public bool Depths { get; set; }

            /// <summary><c>--binary</c>: cameras.bin, images.bin, points3D.bin instead of the text model.</summary>
            public bool Binary { get; set; }

            /// <summary><c>--points N</c>: the first N points of points3d.ply; null = all.</summary>
            public int? ColmapPoints { get; set; }

            /// <summary><c>--min-track N</c>: null = <see cref="ColmapOptions.DefaultMinTrackLength"/>.</summary>
            public int? MinTrackLength { get; set; }

            /// <summary>The COLMAP model options given, or null when none was.</summary>
            public ColmapOptions ColmapModelOptions => Binary || ColmapPoints.HasValue || MinTrackLength.HasValue
                ? new ColmapOptions(Binary, ColmapPoints, MinTrackLength ?? ColmapOptions.DefaultMinTrackLength)
                : null;

            /// <summary><c>--object &lt;name|id&gt;</c>: mask every frame to this labelled object (nerfstudio); null for none.</summary>
            public string ObjectName { get; set; }

            /// <summary><c>--images copy|link|relative</c>; null for the default (<see cref="ExportImagesModes.Resolve"/>).</summary>
            public ExportImages? Images { get; set; }

            /// <summary><c>--background white|black|random [--seed N]</c>; null for the dataset's own images.</summary>
            public ExportBackground Background { get; set; }
        }

        static Options Parse(ToolArguments arguments)
        {
            arguments.RefuseUnknownOptions("to", "out", "depths", "binary", "points", "min-track", "object", "images", "background", "seed");
            var options = new Options();
            ColmapModelOptions(arguments, options);
            options.Depths = arguments.Flag("depths");
            options.DatasetFolder = arguments.OnePositional("convert needs exactly one dataset folder.");
            if (!arguments.TryGet("to", out var to)) arguments.Error("convert needs --to " + string.Join("|", ExportTargets.Names) + " (or a loader name of the config: 3dgs, instant-ngp).");
            else
            {
                options.Target = ExportTargets.Parse(to, out var problem);
                if (problem != null) arguments.Error(problem.ToString()); // ValidationProblem formats its numbers with the invariant culture
                else if (options.Depths && options.Target != ExportTarget.Colmap)
                    arguments.Error("--depths writes 3D Gaussian Splatting's inverse-depth maps, which read a COLMAP source: use it with --to colmap (nerfstudio and ngp exports carry depth on their own).");
            }
            if (arguments.TryGet("object", out var objectName))
            {
                if (string.IsNullOrWhiteSpace(objectName)) arguments.Error("--object is empty: give a labelled object's name, hierarchy path or instance id (labels.json).");
                else if (options.Target.HasValue && options.Target != ExportTarget.Nerfstudio)
                    arguments.Error("--object writes nerfstudio's per-frame mask_path: use it with --to nerfstudio (--to gaussian-grouping writes masks of every object).");
                else options.ObjectName = objectName;
            }
            options.OutputFolder = arguments.OptionalPath("out", "--out is empty; leave it out to write into the dataset folder.");
            if (arguments.TryGet("images", out var images))
            {
                options.Images = ExportImagesModes.Parse(images, out var imagesProblem);
                if (imagesProblem != null) arguments.Error(imagesProblem.ToString());
                else if (options.Target.HasValue && !ExportImagesModes.NamesDatasetFiles(options.Target.Value) && options.Images != ExportImages.Copy)
                    arguments.Error(DatasetConverter.ImagesRefusal(options.Target.Value, options.Images.Value).ToString());
            }
            BackgroundOption(arguments, options);
            return options;
        }

        /// <summary><c>--background white|black|random [--seed N]</c> (<see cref="ExportBackground"/>): refused for the targets that do not take it.</summary>
        static void BackgroundOption(ToolArguments arguments, Options options)
        {
            var seed = arguments.WholeNumber("seed", 0, text => "--seed " + text + ": give a whole number ≥ 0 (the same seed gives the same colours).");
            if (!arguments.TryGet("background", out var value))
            {
                if (arguments.Has("seed")) arguments.Error("--seed picks the colours of --background random: add --background random, or leave --seed out.");
                return;
            }
            var background = ExportBackground.Parse(value, seed ?? 0, out var problem);
            if (problem != null) { arguments.Error(problem.ToString()); return; }
            if (arguments.Has("seed") && !background.IsRandom) { arguments.Error("--seed picks the colours of --background random; --background " + background.Name + " has one colour."); return; }
            var refusal = options.Target.HasValue ? ExportBackground.Refusal(options.Target.Value, background) : null;
            if (refusal != null) arguments.Error(refusal.ToString());
            else options.Background = background;
        }

        /// <summary><c>--binary</c>, <c>--points N</c>, <c>--min-track N</c>: the COLMAP model's shape (<see cref="ColmapOptions"/>).</summary>
        static void ColmapModelOptions(ToolArguments arguments, Options options)
        {
            var given = arguments.Has("binary") || arguments.Has("points") || arguments.Has("min-track");
            options.Binary = arguments.Flag("binary");
            options.ColmapPoints = arguments.WholeNumber("points", 1, points => "--points " + points + ": give how many points of points3d.ply the COLMAP model uses, a whole number of at least 1.");
            options.MinTrackLength = arguments.WholeNumber("min-track", 0, minTrack => "--min-track " + minTrack + ": give the fewest images a COLMAP point must be seen in, a whole number (0 keeps every point; default " +
                                                                               ColmapOptions.DefaultMinTrackLength + ").");
            if (given && arguments.TryGet("to", out var to) && ExportTargets.Parse(to, out var problem) != ExportTarget.Colmap && problem == null)
                arguments.Error("--binary, --points and --min-track shape the COLMAP model: use them with --to colmap.");
        }

        /// <summary>
        /// The command line of the Dataset Tools' export buttons: <c>convert &lt;dataset&gt; --to &lt;target&gt; [--out &lt;folder&gt;] [--depths] [--object &lt;name&gt;]</c>;
        /// an empty <paramref name="outputFolder"/> is the format's default place in the dataset.
        /// </summary>
        public static string[] Arguments(string datasetFolder, ExportTarget target, string outputFolder = null, bool depths = false, string objectName = null)
        {
            var args = new List<string> { Command.Name, ToolArguments.Required(datasetFolder), "--to", ExportTargets.Name(target) };
            if (!string.IsNullOrWhiteSpace(outputFolder)) args.AddRange(new[] { "--out", outputFolder });
            if (depths) args.Add("--depths");
            if (!string.IsNullOrWhiteSpace(objectName)) args.AddRange(new[] { "--object", objectName.Trim() });
            return args.ToArray();
        }

        /// <summary>A folder with more written files than this is summarised as a count (COLMAP's image copies).</summary>
        const int FilesListedPerFolder = 5;

        public static int Run(Options options, TextWriter stdout, TextWriter stderr) =>
            Run(options.DatasetFolder, options.Target.Value, options.OutputFolder, stdout, stderr, options.Depths, options.ColmapModelOptions, options.ObjectName, options.Images, options.Background);

        public static int Run(string datasetFolder, ExportTarget target, string outputFolder, TextWriter stdout, TextWriter stderr, bool depths = false, ColmapOptions colmap = null,
            string objectName = null, ExportImages? images = null, ExportBackground background = null)
        {
            ConversionResult result;
            try
            {
                // An earlier convert into the same output that was killed is finished or rolled back first.
                if (Directory.Exists(datasetFolder))
                {
                    var output = objectName != null
                        ? DatasetConverter.ObjectOutputFolder(Path.GetFullPath(datasetFolder), objectName, outputFolder)
                        : DatasetConverter.OutputFolder(Path.GetFullPath(datasetFolder), target, outputFolder, background);
                    var recovered = Recovery.Run(output);
                    foreach (var note in recovered) stderr.WriteLine("note: " + note);
                    if (recovered.Any(n => n.Operation == "convert" && n.Finished))
                    {
                        stdout.WriteLine("converted " + Path.GetFullPath(datasetFolder) + " to " + ExportTargets.Name(target) + " into " + output + " (the interrupted earlier convert, now finished)");
                        return ToolExitCodes.Success;
                    }
                }
                result = DatasetConverter.Convert(datasetFolder, target, outputFolder, depths, colmap, objectName, images, background);
            }
            catch (InvalidParameterException e)
            {
                if (Directory.Exists(datasetFolder) && DatasetConfig.Read(datasetFolder).IsPlanOnly)
                {
                    // One line instead of one "names no image" per planned frame.
                    stderr.WriteLine("error: " + new ValidationProblem(DatasetLayout.ConfigFileName + ": imagesRendered", "false",
                        "this dataset was planned by nerf-dataset plan and has no images, but convert needs them (their size sets the intrinsics; colmap copies them).",
                        "Render the dataset with the Unity plugin (window or batch mode) and convert that folder."));
                    stderr.WriteLine("convert refused: " + Count(e.Problems.Count, "problem") + ", the first: " + e.Problems[0] + " Nothing was written.");
                    return ToolExitCodes.Failure;
                }
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                stderr.WriteLine("convert refused: " + Count(e.Problems.Count, "problem") + "; nothing was written.");
                return ToolExitCodes.Failure;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                stderr.WriteLine("error: " + e.Message);
                stderr.WriteLine("convert failed; it writes into a working folder and moves the files into place only when all are complete, " +
                                 "so nothing was overwritten and running the same command again finishes or rolls back what was interrupted.");
                return ToolExitCodes.Failure;
            }

            foreach (var warning in result.Warnings) stderr.WriteLine("warning: " + warning);
            stdout.WriteLine("converted " + Path.GetFullPath(datasetFolder) + " to " + ExportTargets.Name(target) + ":");
            foreach (var folder in result.WrittenFiles.GroupBy(Path.GetDirectoryName))
            {
                var files = folder.ToList();
                if (files.Count > FilesListedPerFolder) stdout.WriteLine("  wrote " + files.Count + " files into " + folder.Key + Path.DirectorySeparatorChar);
                else foreach (var file in files) stdout.WriteLine("  wrote " + file);
            }
            if (result.FileReferences != null) stdout.WriteLine("files: " + result.FileReferences);
            if (result.TrainCommands.Count > 0) foreach (var command in result.TrainCommands) stdout.WriteLine("train with: " + command);
            else stdout.WriteLine("train with: " + NextStep(target, result.MainFile, depths));
            return ToolExitCodes.Success;
        }

        /// <summary>The training command of Documentation~/exports.md for the export just written.</summary>
        static string NextStep(ExportTarget target, string main, bool depths)
        {
            switch (target)
            {
                case ExportTarget.Ngp:
                    return "./instant-ngp " + Quote(main) + "   (from the instant-ngp folder)";
                default:
                    return "python train.py -s " + Quote(main) + (depths ? " -d " + GaussianSplattingDepths.FolderName : "") + " --eval   (3D Gaussian Splatting)";
            }
        }

        static string Quote(string path) => path.IndexOf(' ') >= 0 ? "\"" + path + "\"" : path;

        static string Count(int n, string noun) => n + " " + noun + (n == 1 ? "" : "s");
    }
}
