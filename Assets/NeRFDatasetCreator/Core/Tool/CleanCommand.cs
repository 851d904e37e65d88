using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset clean &lt;folder&gt; [--dry-run]</c>: finishes or rolls back the interrupted operations on the
    /// outputs in the folder, then removes the leftover working folders (<see cref="LeftoverCleaner"/>), printing each
    /// with its size. Folders it cannot prove the tool wrote are listed as "not ours, left alone". Exit 0 (also when
    /// there was nothing to clean, or only folders that are not ours), 1 when a leftover had to be kept or a journal was refused.
    /// </summary>
    public static class CleanCommand
    {
        public static readonly ToolCommand Command = ToolCommand.Of("clean", "clean <dir> [--dry-run]",
            "finish or roll back interrupted runs, remove their leftover folders", Parse, Run, DryRunFlag).WithOptions(
            "<dir>       the folder holding the datasets (e.g. NeRFDatasets), or one dataset",
            "--dry-run   list what would be finished, rolled back or removed, and change nothing");

        const string DryRunFlag = "dry-run";

        public sealed class Options
        {
            /// <summary>The folder holding the datasets (e.g. NeRFDatasets), or a dataset.</summary>
            public string Folder { get; set; }

            /// <summary><c>--dry-run</c>: list the leftovers without changing anything.</summary>
            public bool DryRun { get; set; }
        }

        static Options Parse(ToolArguments arguments)
        {
            arguments.RefuseUnknownOptions(DryRunFlag);
            return new Options
            {
                Folder = arguments.OnePositional("clean needs exactly one folder: the one holding the datasets (e.g. NeRFDatasets) or a dataset."),
                // Given at all: --dry-run=anything is a dry run too, as it always was (the safe reading).
                DryRun = arguments.Has(DryRunFlag),
            };
        }

        /// <summary>The command line of the Dataset Tools' Clean and dry-run buttons.</summary>
        public static string[] Arguments(string folder, bool dryRun = false) =>
            dryRun ? new[] { Command.Name, ToolArguments.Required(folder), "--" + DryRunFlag } : new[] { Command.Name, ToolArguments.Required(folder) };

        public static int Run(Options options, TextWriter stdout, TextWriter stderr) => Run(options.Folder, options.DryRun, stdout, stderr);

        public static int Run(string folder, bool dryRun, TextWriter stdout, TextWriter stderr)
        {
            LeftoverCleaner.Result result;
            try
            {
                result = LeftoverCleaner.Clean(folder, dryRun);
            }
            catch (InvalidParameterException e)
            {
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                return ToolExitCodes.UsageError;
            }
            foreach (var note in result.Recovered) stdout.WriteLine(note);
            foreach (var removed in result.Removed) stdout.WriteLine((dryRun ? "would remove " : "removed ") + removed);
            foreach (var refused in result.Refused) stderr.WriteLine("error: " + refused);
            foreach (var kept in result.Kept) stderr.WriteLine("kept " + kept);
            foreach (var alone in result.LeftAlone) stdout.WriteLine("not ours, left alone: " + alone);
            if (result.Recovered.Count + result.Removed.Count + result.Kept.Count + result.Refused.Count + result.LeftAlone.Count == 0)
                stdout.WriteLine("nothing to clean in " + Path.GetFullPath(folder) + ": no working folder is left over.");
            return result.Kept.Count + result.Refused.Count > 0 ? ToolExitCodes.Failure : ToolExitCodes.Success;
        }
    }
}
