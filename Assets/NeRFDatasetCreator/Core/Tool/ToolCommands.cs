using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>nerf-dataset</c> commands behind one entry point: the headless tool's <c>Program</c> and Unity's
    /// Dataset Tools run the same command classes, so both print the same lines. <see cref="All"/> is the one list
    /// of commands: the parser looks a command up in it, <c>--help</c> prints its lines, and <see cref="Run"/> runs
    /// what it parsed. A new command is its own file (options, parsing, run) and one line here.
    /// </summary>
    public static class ToolCommands
    {
        /// <summary>Every command, in the order <c>--help</c> lists them.</summary>
        public static readonly IReadOnlyList<ToolCommand> All = new[]
        {
            PlanCommand.Command,
            ValidateCommand.Command,
            MergeCommand.Command,
            ConvertCommand.Command,
            CleanCommand.Command,
            CheckCommand.Command,
            EvaluateCommand.Command,
            SplitsCommand.Command,
            DemoCommand.Command,
            PlaceSplatCommand.Command,
            FlowCommand.Command,
        };

        /// <summary>The last line of every usage text.</summary>
        public const string ExitCodes = "exit codes: 0 success; 1 problems found, refused or failed; 2 usage, config or settings error";

        /// <summary>What <c>--help</c> prints: one line per command, then the exit codes and where the rest is.</summary>
        public static readonly string Usage =
            "usage: nerf-dataset <command> [arguments]\n" +
            string.Concat(All.Select(c => c.HelpLine + "\n")) +
            ExitCodes + "\n" +
            "nerf-dataset <command> --help prints that command's options; nerf-dataset --version its version.";

        /// <summary>What <c>--version</c> prints: the tool is the package's, so its version is package.json's (<see cref="PluginInfo.Version"/>).</summary>
        public static string VersionLine => "nerf-dataset " + PluginInfo.Version;

        /// <summary>The command named <paramref name="name"/> (case-sensitive), or null.</summary>
        public static ToolCommand Find(string name) => All.FirstOrDefault(c => c.Name == name);

        /// <summary>
        /// Whether <c>--name</c> takes no value in any command: the parser must know before it knows whether the
        /// command takes it, so that <c>validate d --depths</c> reports the unknown option, not a missing value.
        /// </summary>
        public static bool IsFlag(string name) => All.Any(c => c.Flags.Contains(name));

        /// <summary>Runs one command line; whatever a command cannot handle is one line on stderr and exit 1 (<see cref="UnexpectedError"/>).</summary>
        public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
        {
            string command = null;
            try
            {
                var invocation = ToolCommandLine.Parse(args);
                command = invocation.Command;
                if (invocation.Errors.Count > 0)
                {
                    foreach (var error in invocation.Errors) stderr.WriteLine("error: " + error);
                    // A known command's mistake prints only that command's usage; no or an unknown command, the table.
                    stderr.WriteLine(Find(invocation.Command)?.Usage ?? Usage);
                    return ToolExitCodes.UsageError;
                }
                return invocation.Run(stdout, stderr);
            }
            catch (Exception e) when (!(e is SimulatedStopException))
            {
                stderr.WriteLine(UnexpectedError.Describe(command, e));
                return ToolExitCodes.Failure;
            }
        }
    }
}
