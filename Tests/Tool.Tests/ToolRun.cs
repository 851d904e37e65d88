using System.IO;
using NerfDatasetCreator.Tool;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>One in-process run of the tool: its exit code and what it printed.</summary>
    sealed class ToolRun
    {
        public int ExitCode;
        public string Out;
        public string Err;

        public static ToolRun Of(params string[] args)
        {
            var stdout = new StringWriter { NewLine = "\n" };
            var stderr = new StringWriter { NewLine = "\n" };
            var code = Program.Run(args, stdout, stderr);
            return new ToolRun { ExitCode = code, Out = stdout.ToString(), Err = stderr.ToString() };
        }

        public override string ToString() => "exit " + ExitCode + "\n--- stdout\n" + Out + "--- stderr\n" + Err;
    }
}
