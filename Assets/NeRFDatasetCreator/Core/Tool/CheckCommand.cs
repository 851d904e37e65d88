using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset check d [--split S] [--json FILE] [--max-views N]</c>: <see cref="DatasetCheck"/>'s summary (one
    /// line per check with its figure and threshold), then one line per problem naming file, frame and check; exit 1
    /// on any problem. <c>--json</c> writes the whole report to a new file and never replaces an existing one.
    /// </summary>
    public static class CheckCommand
    {
        public static int Run(ToolInvocation invocation, TextWriter stdout, TextWriter stderr)
        {
            var folder = invocation.DatasetFolder;
            if (!Directory.Exists(folder))
            {
                stderr.WriteLine("error: " + folder + " is not an existing folder. Pass the dataset folder that holds transforms_train.json.");
                return ToolExitCodes.Failure;
            }
            var json = invocation.JsonReport == null ? null : Path.GetFullPath(invocation.JsonReport);
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

            var report = DatasetCheck.Run(folder, new DatasetCheckOptions { Split = invocation.Split, MaxViews = invocation.MaxViews });
            stdout.WriteLine("check " + Path.GetFullPath(folder) + ": " + report.ViewsChecked + " views in " +
                             report.TotalSeconds.ToString("0.0", System.Globalization.CultureInfo.InvariantCulture) + " s (decoding " +
                             report.DecodeSeconds.ToString("0.0", System.Globalization.CultureInfo.InvariantCulture) + " s)");
            foreach (var line in report.SummaryLines) stdout.WriteLine("  " + line);
            foreach (var problem in report.Problems) stdout.WriteLine("problem: " + problem);

            if (json != null)
            {
                try
                {
                    // CreateNew: a file that appeared since the test above is not replaced either.
                    using (var stream = new FileStream(json, FileMode.CreateNew, FileAccess.Write))
                    using (var writer = new StreamWriter(stream, new System.Text.UTF8Encoding(false)))
                        writer.Write(report.ToJson());
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
                stdout.WriteLine("OK");
                return ToolExitCodes.Success;
            }
            stderr.WriteLine("failed: " + report.Problems.Count + (report.Problems.Count == 1 ? " problem" : " problems"));
            return ToolExitCodes.Failure;
        }
    }
}
