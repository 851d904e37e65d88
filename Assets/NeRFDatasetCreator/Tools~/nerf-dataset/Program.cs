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

        public static int Main(string[] args) => Run(args, Console.Out, Console.Error);

        public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
        {
            var invocation = ToolCommandLine.Parse(args);
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
                default:
                    stdout.WriteLine(ToolInvocation.Usage);
                    return Success;
            }
        }
    }
}
