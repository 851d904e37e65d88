using System;
using System.IO;

namespace NerfDatasetCreator.Tool
{
    /// <summary>Entry point of <c>nerf-dataset</c>; <see cref="Run"/> is what the tests call in-process.</summary>
    public static class Program
    {
        public const int Success = 0;
        public const int Failure = 1;
        public const int UsageError = 2;

        /// <summary>
        /// Test seam for the end-to-end kill test: with <c>NERF_DATASET_KILL_AT_FILE_OPERATION=n</c> the tool kills its
        /// own process (as <c>kill -9</c> would) just before its n-th file operation (<see cref="FileOps"/>).
        /// </summary>
        public const string KillVariable = "NERF_DATASET_KILL_AT_FILE_OPERATION";

        public static int Main(string[] args)
        {
            if (int.TryParse(Environment.GetEnvironmentVariable(KillVariable), System.Globalization.NumberStyles.None,
                    System.Globalization.CultureInfo.InvariantCulture, out var killAt) && killAt > 0)
                FileOps.Faults = FileFaultPlan.Killing(killAt, () => System.Diagnostics.Process.GetCurrentProcess().Kill());
            return Run(args, Console.Out, Console.Error);
        }

        /// <summary>Runs one command; whatever it cannot handle is one line on stderr and exit 1 (<see cref="UnexpectedError"/>).</summary>
        public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
        {
            string command = null;
            try
            {
                return Dispatch(args, stdout, stderr, out command);
            }
            catch (Exception e) when (!(e is SimulatedStopException))
            {
                stderr.WriteLine(UnexpectedError.Describe(command, e));
                return Failure;
            }
        }

        static int Dispatch(string[] args, TextWriter stdout, TextWriter stderr, out string command)
        {
            command = null;
            var invocation = ToolCommandLine.Parse(args);
            command = invocation.Command;
            if (invocation.Errors.Count > 0)
            {
                foreach (var error in invocation.Errors) stderr.WriteLine("error: " + error);
                stderr.WriteLine(ToolInvocation.Usage);
                return UsageError;
            }
            switch (invocation.Command)
            {
                case ToolInvocation.PlanCommand: return PlanCommand.Run(invocation.ConfigPath, invocation.OutputFolder, stdout, stderr);
                case ToolInvocation.ValidateCommand: return ValidateCommand.Run(invocation.DatasetFolder, stdout, stderr);
                case ToolInvocation.MergeCommand: return MergeCommand.Run(invocation.ShardFolders, invocation.OutputFolder, invocation.MoveFiles, stdout, stderr);
                case ToolInvocation.ConvertCommand: return ConvertCommand.Run(invocation.DatasetFolder, invocation.Target.Value, invocation.OutputFolder, stdout, stderr, invocation.Depths);
                case ToolInvocation.CleanCommand: return CleanCommand.Run(invocation.DatasetFolder, invocation.DryRun, stdout, stderr);
                case ToolInvocation.CheckCommand: return CheckCommand.Run(invocation, stdout, stderr);
                default:
                    stdout.WriteLine(ToolInvocation.Usage);
                    return Success;
            }
        }
    }
}
