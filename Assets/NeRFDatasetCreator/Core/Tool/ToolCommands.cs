using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>nerf-dataset</c> commands behind one entry point: the headless tool's <c>Program</c> and Unity's
    /// Dataset Tools run the same command classes, so both print the same lines.
    /// </summary>
    public static class ToolCommands
    {
        /// <summary>Runs one command line; whatever a command cannot handle is one line on stderr and exit 1 (<see cref="UnexpectedError"/>).</summary>
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
                return ToolExitCodes.Failure;
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
                return ToolExitCodes.UsageError;
            }
            switch (invocation.Command)
            {
                case ToolInvocation.PlanCommand: return PlanCommand.Run(invocation.ConfigPath, invocation.OutputFolder, stdout, stderr);
                case ToolInvocation.ValidateCommand: return ValidateCommand.Run(invocation.DatasetFolder, stdout, stderr);
                case ToolInvocation.MergeCommand: return MergeCommand.Run(invocation.ShardFolders, invocation.OutputFolder, invocation.MoveFiles, stdout, stderr);
                case ToolInvocation.ConvertCommand: return ConvertCommand.Run(invocation.DatasetFolder, invocation.Target.Value, invocation.OutputFolder, stdout, stderr, invocation.Depths, invocation.ColmapModelOptions, invocation.ObjectName);
                case ToolInvocation.CleanCommand: return CleanCommand.Run(invocation.DatasetFolder, invocation.DryRun, stdout, stderr);
                case ToolInvocation.EvaluateCommand: return EvaluateCommand.Run(invocation.Evaluation, stdout, stderr);
                case ToolInvocation.CheckCommand: return CheckCommand.Run(invocation, stdout, stderr);
                default:
                    stdout.WriteLine(ToolInvocation.Usage);
                    return ToolExitCodes.Success;
            }
        }
    }
}
