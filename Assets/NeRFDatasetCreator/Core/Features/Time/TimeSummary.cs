using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>One line about a dynamic capture's time, for the headless tool and the window.</summary>
    public static class TimeSummary
    {
        public static string Describe(TimeRange range)
        {
            var rate = range.Fps > 0 ? " at " + ValidationProblem.Format(range.Fps) + " fps" : "";
            var how = range.Mode == TimeMode.Monocular
                ? "one train view per step, val/test views between them"
                : "every camera at every step";
            return string.Format(CultureInfo.InvariantCulture, "time: {0}, {1} steps from {2} s to {3} s{4} ({5})",
                TimeModes.Name(range.Mode), range.Steps, ValidationProblem.Format(range.StartSeconds), ValidationProblem.Format(range.EndSeconds), rate, how);
        }
    }
}
