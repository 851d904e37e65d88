using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>The parsed command line of the <c>nerf-dataset</c> tool.</summary>
    public sealed class ToolInvocation
    {
        public const string PlanCommand = "plan";
        public const string ValidateCommand = "validate";
        public const string HelpCommand = "help";

        /// <summary>"plan", "validate" or "help".</summary>
        public string Command { get; internal set; }

        /// <summary><c>plan --config &lt;file&gt;</c>.</summary>
        public string ConfigPath { get; internal set; }

        /// <summary><c>plan --out &lt;dir&gt;</c>: the dataset folder itself.</summary>
        public string OutputFolder { get; internal set; }

        /// <summary><c>validate &lt;dir&gt;</c>.</summary>
        public string DatasetFolder { get; internal set; }

        /// <summary>Usage mistakes; the command runs only when this is empty.</summary>
        public List<string> Errors { get; } = new List<string>();

        public const string Usage =
            "usage:\n" +
            "  nerf-dataset plan --config <settings.json> --out <dataset-folder>\n" +
            "      writes transforms_{train,val,test}.json, dataset_config.json and rig_preview.ply (no images)\n" +
            "  nerf-dataset validate <dataset-folder>\n" +
            "      checks a Blender-format dataset; prints a summary and one line per problem; exit 1 on any problem\n" +
            "exit codes: 0 success, 1 problems found or the run failed, 2 usage or settings error";
    }
}
