using System.IO;

namespace NerfDatasetCreator
{
    /// <summary><c>nerf-dataset validate d</c>: a summary line, then one line per problem and warning; exit 1 on any problem.</summary>
    public static class ValidateCommand
    {
        public static int Run(string datasetFolder, TextWriter stdout, TextWriter stderr)
        {
            var report = DatasetValidator.Validate(datasetFolder);
            stdout.WriteLine(report.Summary());
            foreach (var problem in report.Problems) stdout.WriteLine("problem: " + problem);
            foreach (var warning in report.Warnings) stdout.WriteLine("warning: " + warning);
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
