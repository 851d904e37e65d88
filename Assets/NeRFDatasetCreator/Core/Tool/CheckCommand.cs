using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset check d [--split S] [--json FILE] [--max-views N]</c>: <see cref="DatasetCheck"/>'s summary (one
    /// line per check with its figure and threshold), then one line per problem naming file, frame and check; exit 1
    /// on any problem. <c>--json</c> writes the whole report to a new file outside the dataset, complete or not at all
    /// (<see cref="AtomicFile"/>), and never replaces an existing one.
    /// </summary>
    public static class CheckCommand
    {
        public static readonly ToolCommand Command = ToolCommand.Of("check", "check <dir> [--split S] [--json FILE] [--max-views N] [--model <dir>]",
            "decode the images and check that alpha, masks, depth, normals, poses and point cloud agree", Parse, Run).WithOptions(
            "--split S        only that split: train, val or test (default: all)",
            "--json FILE      also write the whole report to FILE, a new file (never replaced)",
            "--max-views N    check at most N views per split, spread evenly (default: all)",
            "--model <dir>    also compare eval_protocol.json with a trained output's cfg_args (3DGS) or config.yml (nerfstudio)");

        public sealed class Options
        {
            public string DatasetFolder { get; set; }

            /// <summary><c>--split train|val|test</c>: only that split; null for all.</summary>
            public string Split { get; set; }

            /// <summary><c>--json &lt;file&gt;</c>: where to write the whole report (a file that must not exist yet); null for none.</summary>
            public string JsonReport { get; set; }

            /// <summary><c>--max-views N</c>: at most N views per split, spread evenly; 0 for all.</summary>
            public int MaxViews { get; set; }

            /// <summary><c>--model &lt;dir&gt;</c>: a trained output whose written config is compared with the protocol (<see cref="TrainerConfigCheck"/>); null for none.</summary>
            public string Model { get; set; }
        }

        static Options Parse(ToolArguments arguments)
        {
            arguments.RefuseUnknownOptions("split", "json", "max-views", "model");
            return new Options
            {
                DatasetFolder = arguments.OnePositional("check needs exactly one dataset folder."),
                Split = arguments.Split(),
                JsonReport = arguments.OptionalPath("json", "--json is empty; name the report file to write, e.g. --json report.json."),
                MaxViews = arguments.WholeNumber("max-views", 1, max => "--max-views " + max + ": is not a whole number of at least 1.") ?? 0,
                Model = arguments.OptionalPath("model", "--model is empty; name the trained output folder (3DGS -m <model>, nerfstudio outputs/…/<timestamp>)."),
            };
        }

        /// <summary>The command line of the Dataset Tools' Check button: <c>check &lt;dataset&gt;</c>.</summary>
        public static string[] Arguments(string datasetFolder) => new[] { Command.Name, ToolArguments.Required(datasetFolder) };

        public static int Run(Options options, TextWriter stdout, TextWriter stderr)
        {
            var folder = options.DatasetFolder;
            // A file, a missing folder, a capture's working folder or an export: one line saying which (NotADatasetFolder).
            var notADataset = NotADatasetFolder.Describe(folder);
            if (notADataset != null || !Directory.Exists(folder))
            {
                stderr.WriteLine("error: " + folder + ": " + (notADataset ?? "is not an existing folder. Pass the dataset folder that holds transforms_train.json."));
                return ToolExitCodes.Failure;
            }
            if (DatasetConfig.Read(folder).IsPlanOnly)
            {
                // One line, as convert refuses a plan, instead of one "image is missing" per planned frame.
                stderr.WriteLine("error: " + new ValidationProblem(DatasetLayout.ConfigFileName + ": imagesRendered", "false",
                    "this dataset was planned by nerf-dataset plan and has no images, but check decodes them.",
                    "Render the dataset with the Unity plugin (window or batch mode) and check that folder; nerf-dataset validate checks a plan's JSON files."));
                return ToolExitCodes.Failure;
            }
            var json = options.JsonReport == null ? null : Path.GetFullPath(options.JsonReport);
            if (json != null && (File.Exists(json) || Directory.Exists(json)))
            {
                stderr.WriteLine("error: " + json + " already exists; check never replaces a file. Name a new file for --json, or move that one away.");
                return ToolExitCodes.Failure;
            }
            if (json != null && !Directory.Exists(Path.GetDirectoryName(json)))
            {
                stderr.WriteLine("error: the folder of " + json + " does not exist. Create it, or name a file in an existing folder for --json.");
                return ToolExitCodes.Failure;
            }
            // The real path, every link followed (SafeOutput's one rule): check never adds a file to the dataset it checks.
            var inside = json == null ? null : SafeOutput.WhyInsideDataset(json, folder);
            if (inside != null)
            {
                stderr.WriteLine("error: --json " + json + " " + inside + "; check never adds files to the dataset it checks. Name a file outside the dataset for --json.");
                return ToolExitCodes.Failure;
            }

            // The trainer's written config against the protocol, before the images are decoded: a wrong --model stops at once.
            TrainerConfigCheck.Result trainer = null;
            if (options.Model != null)
            {
                try { trainer = TrainerConfigCheck.Run(Path.GetFullPath(folder), options.Model); }
                catch (InvalidParameterException e)
                {
                    foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                    return ToolExitCodes.Failure;
                }
            }
            var report = DatasetCheck.Run(folder, new DatasetCheckOptions { Split = options.Split, MaxViews = options.MaxViews });
            stdout.WriteLine("check " + Path.GetFullPath(folder) + ": " + report.ViewsChecked + " views in " +
                             report.TotalSeconds.ToString("0.0", System.Globalization.CultureInfo.InvariantCulture) + " s (decoding " +
                             report.DecodeSeconds.ToString("0.0", System.Globalization.CultureInfo.InvariantCulture) + " s)");
            foreach (var line in report.SummaryLines) stdout.WriteLine("  " + line);
            if (trainer != null)
            {
                foreach (var line in trainer.Read) stdout.WriteLine("  trainer config: " + line);
                foreach (var warning in trainer.Warnings) stdout.WriteLine("warning: " + warning);
                if (trainer.Warnings.Count == 0) stdout.WriteLine("  trainer config agrees with the protocol");
            }
            foreach (var line in ProblemList.Lines(report.Problems, "problem: ", json != null ? "the report " + json + " lists every one" : "check --json FILE lists every one")) stdout.WriteLine(line);

            if (json != null)
            {
                try
                {
                    // Written beside it and renamed when complete: a kill leaves no half-written report under the name, and
                    // a file that appeared since the test above is not replaced either (AtomicFile).
                    AtomicFile.WriteNewText(json, report.ToJson());
                    stdout.WriteLine("report: " + json);
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    stderr.WriteLine("error: cannot write " + json + ": " + e.Message + " Name a new file in a folder you can write to.");
                    return ToolExitCodes.Failure;
                }
            }
            if (!report.Failed)
            {
                stdout.WriteLine(CheckVerdict.Passed(report));
                return ToolExitCodes.Success;
            }
            stderr.WriteLine("failed: " + report.Problems.Count + (report.Problems.Count == 1 ? " problem" : " problems") + " (" + CheckVerdict.Ran(report) + ")");
            return ToolExitCodes.Failure;
        }
    }
}
