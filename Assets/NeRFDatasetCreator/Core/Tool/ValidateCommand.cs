using System.IO;

namespace NerfDatasetCreator
{
    /// <summary><c>nerf-dataset validate d</c>: a summary line, then one line per problem and warning; exit 1 on any problem.</summary>
    public static class ValidateCommand
    {
        public static readonly ToolCommand Command = ToolCommand.Of("validate", "validate <dir>", "check a Blender-format dataset", Parse, Run).WithOptions(
            "<dir>  the dataset folder: transforms_train/val/test.json, the images they name, dataset_config.json");

        public sealed class Options
        {
            /// <summary>The Blender-format dataset to read.</summary>
            public string DatasetFolder { get; set; }
        }

        static Options Parse(ToolArguments arguments)
        {
            arguments.RefuseUnknownOptions();
            return new Options { DatasetFolder = arguments.OnePositional("validate needs exactly one dataset folder.") };
        }

        /// <summary>The command line of the Dataset Tools' Validate button.</summary>
        public static string[] Arguments(string datasetFolder) => new[] { Command.Name, ToolArguments.Required(datasetFolder) };

        public static int Run(Options options, TextWriter stdout, TextWriter stderr) => Run(options.DatasetFolder, stdout, stderr);

        public static int Run(string datasetFolder, TextWriter stdout, TextWriter stderr)
        {
            var report = DatasetValidator.Validate(datasetFolder);
            stdout.WriteLine(report.Summary());
            foreach (var line in ProblemList.Lines(report.Problems, "problem: ", null)) stdout.WriteLine(line);
            foreach (var line in ProblemList.Lines(report.Warnings, "warning: ", null)) stdout.WriteLine(line);
            if (report.IsValid)
            {
                stdout.WriteLine("OK");
                return ToolExitCodes.Success;
            }
            stderr.WriteLine("invalid: " + report.Problems.Count + (report.Problems.Count == 1 ? " problem" : " problems"));
            return ToolExitCodes.Failure;
        }
    }
}
