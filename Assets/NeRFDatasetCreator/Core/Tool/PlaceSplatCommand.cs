using System;
using System.Globalization;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset place-splat &lt;dataset&gt; --model &lt;trained output&gt; [--trainer 3dgs|nerfstudio|gsplat] [--ply &lt;file&gt;] [--json &lt;file&gt;]</c>:
    /// where the trained splat goes in the Unity scene it was captured from (<see cref="SplatPlacer"/>). Prints the
    /// Transform and the object-to-world matrix, writes the viewer's cameras.json beside the PLY (never over one) and,
    /// with <c>--json</c>, the same placement as JSON. Exit 0 placed, 1 refused.
    /// </summary>
    public static class PlaceSplatCommand
    {
        public static readonly ToolCommand Command = ToolCommand.Of("place-splat", "place-splat <dir> --model <trained output> [--trainer 3dgs|nerfstudio|gsplat] [--ply <file>] [--json <file>]",
            "where a trained Gaussian splat goes in the Unity scene: Transform, object-to-world, cameras.json", Parse, Run).WithOptions(
            "<dir>              the dataset folder (dataset_config.json, transforms files; a planned dataset works too)",
            "--model <folder>   3DGS model folder (-m), nerfstudio run folder (config.yml), gsplat --result_dir",
            "--trainer <name>   3dgs, nerfstudio or gsplat; detected from the folder when left out",
            "--ply <file>       the PLY to place when it is not in the folder (ns-export gaussian-splat --output-dir)",
            "--json <file>      also write the placement as JSON (a new file; an existing one is never replaced)");

        public sealed class Options
        {
            public string Dataset { get; set; }
            public string Model { get; set; }
            public string Trainer { get; set; }
            public string Ply { get; set; }
            public string Json { get; set; }
        }

        static Options Parse(ToolArguments arguments)
        {
            arguments.RefuseUnknownOptions("model", "trainer", "ply", "json");
            var o = new Options { Dataset = arguments.OnePositional("place-splat needs exactly one dataset folder, e.g. place-splat NeRFDatasets/lego --model output/lego.") };
            o.Model = arguments.RequiredPath("model", "place-splat needs --model <folder>: the trained output (3DGS model folder, nerfstudio run folder or gsplat result folder).");
            if (arguments.TryGet("trainer", out var trainer))
            {
                if (TrainedModel.Trainers.Contains(trainer)) o.Trainer = trainer;
                else arguments.Error("--trainer = " + trainer + ": is not " + string.Join(", ", TrainedModel.Trainers) + ".");
            }
            o.Ply = arguments.OptionalPath("ply", "--ply is empty; leave it out to use the PLY in the model folder.");
            o.Json = arguments.OptionalPath("json", "--json is empty; leave it out to print the placement only.");
            return o;
        }

        /// <summary>The command line of the Dataset Tools' button (the Editor helper's window may run it).</summary>
        public static string[] Arguments(string dataset, string model) =>
            new[] { Command.Name, ToolArguments.Required(dataset), "--model", ToolArguments.Required(model) };

        public static int Run(Options options, TextWriter stdout, TextWriter stderr)
        {
            if (options.Json != null && (File.Exists(options.Json) || Directory.Exists(options.Json)))
            {
                stderr.WriteLine("error: " + new ValidationProblem("--json", Path.GetFullPath(options.Json), "already exists; place-splat never replaces a file.", "Name a new file, or move the old one away."));
                return ToolExitCodes.Failure;
            }
            SplatPlacement placement;
            try
            {
                placement = SplatPlacer.Place(options.Dataset, options.Model, options.Trainer, options.Ply);
            }
            catch (InvalidParameterException e)
            {
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                stderr.WriteLine("place-splat refused: nothing was written.");
                return ToolExitCodes.Failure;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is InvalidDataException)
            {
                stderr.WriteLine("error: " + e.Message);
                stderr.WriteLine("place-splat stopped on a file it cannot read.");
                return ToolExitCodes.Failure;
            }
            foreach (var line in Lines(placement)) stdout.WriteLine(line);
            if (options.Json != null)
            {
                try
                {
                    AtomicFile.WriteNewText(options.Json, ExportJson.Serialise(ToJson(placement)) + "\n");
                    stdout.WriteLine("wrote " + Path.GetFullPath(options.Json));
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    stderr.WriteLine("error: --json " + Path.GetFullPath(options.Json) + " could not be written: " + e.Message);
                    return ToolExitCodes.Failure;
                }
            }
            return ToolExitCodes.Success;
        }

        /// <summary>What the command prints: the Transform as the Inspector shows it, the matrix, cameras.json, the notes.</summary>
        public static string[] Lines(SplatPlacement p)
        {
            var m = p.ObjectToWorld;
            var lines = new System.Collections.Generic.List<string>
            {
                "placed " + p.PlyPath,
                "  trainer " + p.Trainer + ": " + p.TrainerFrame,
                "  position " + Vector(p.Position),
                "  rotation " + Vector(p.EulerDegrees) + " (Euler degrees, as the Inspector shows it); quaternion (x, y, z, w) " + Vector(p.Rotation),
                "  scale    " + Vector(p.Scale) + (p.Scale.Any(s => s < 0) ? " (the negative component carries the reflection)" : ""),
                "  object_to_world (x_unity = M · [x_ply, 1]):",
            };
            for (var r = 0; r < 4; r++) lines.Add("    " + Vector(new[] { m[4 * r], m[4 * r + 1], m[4 * r + 2], m[4 * r + 3] }));
            if (p.CamerasJsonPath != null)
                lines.Add("wrote " + p.CamerasJsonPath + " (" + p.CameraCount + " train cameras in the PLY's frame)" +
                          (p.ViewerCamerasJsonPath == p.CamerasJsonPath ? "; aras-p's importer will read it (the first cameras.json up from the PLY's folder)." : "; aras-p's importer will read " + (p.ViewerCamerasJsonPath ?? "none") + " instead."));
            else
                lines.Add(p.ViewerCamerasJsonPath != null
                    ? "aras-p's importer will read " + p.ViewerCamerasJsonPath + " for its camera slider (the first cameras.json up from the PLY's folder)."
                    : "no cameras.json: aras-p's importer will show no training cameras.");
            foreach (var note in p.Notes) lines.Add("note: " + note);
            return lines.ToArray();
        }

        /// <summary>The <c>--json</c> record (contract keys from issue 34: trainer, ply, object_to_world, position, rotation, scale).</summary>
        public static JObject ToJson(SplatPlacement p) => new JObject
        {
            ["trainer"] = p.Trainer,
            ["ply"] = p.PlyPath,
            ["object_to_world"] = Rows(p.ObjectToWorld),
            ["position"] = new JArray(p.Position),
            ["rotation"] = new JArray(p.Rotation),
            ["rotation_order"] = "quaternion x, y, z, w (Unity's Quaternion)",
            ["euler_degrees"] = new JArray(p.EulerDegrees),
            ["scale"] = new JArray(p.Scale),
            ["trainer_frame"] = p.TrainerFrame,
            ["trainer_to_output"] = Rows(p.TrainerToOutput),
            ["output_to_unity"] = Rows(p.OutputToUnity),
            ["unity_frame_derived_from"] = p.UnityFrameDerivedFrom,
            ["cameras_json"] = p.CamerasJsonPath,
            ["viewer_cameras_json"] = p.ViewerCamerasJsonPath,
            ["notes"] = new JArray(p.Notes),
        };

        static JArray Rows(double[] m) => new JArray(Enumerable.Range(0, 4).Select(r => new JArray(m[4 * r], m[4 * r + 1], m[4 * r + 2], m[4 * r + 3])));

        static string Vector(double[] v) => "(" + string.Join(", ", v.Select(x => (Math.Abs(x) < 5e-13 ? 0 : x).ToString("0.#########", CultureInfo.InvariantCulture))) + ")";
    }
}
