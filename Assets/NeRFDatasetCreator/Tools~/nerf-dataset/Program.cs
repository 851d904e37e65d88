using System;

namespace NerfDatasetCreator.Tool
{
    /// <summary>
    /// Entry point of <c>nerf-dataset</c>; <see cref="Run"/> is what the tests call in-process. The commands live in
    /// Core (<see cref="ToolCommands"/>), where Unity's Dataset Tools run them too.
    /// </summary>
    public static class Program
    {
        public const int Success = ToolExitCodes.Success;
        public const int Failure = ToolExitCodes.Failure;
        public const int UsageError = ToolExitCodes.UsageError;

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
        public static int Run(string[] args, System.IO.TextWriter stdout, System.IO.TextWriter stderr)
        {
            // Core ships no JPEG code (IJpegCodec): the tool brings LibJpeg.NET from NuGet.
            if (JpegWriter.Codec == null) JpegWriter.Codec = new LibJpegCodec();
            return ToolCommands.Run(args, stdout, stderr);
        }
    }
}
