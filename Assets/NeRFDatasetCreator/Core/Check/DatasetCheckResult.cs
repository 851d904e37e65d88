using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>One check's summary: its figure against its threshold, or why it was skipped.</summary>
    public sealed class DatasetCheckResult
    {
        public DatasetCheckResult(string name, DatasetCheckStatus status, string figure, string threshold, string reason)
        {
            Name = name;
            Status = status;
            Figure = figure;
            Threshold = threshold;
            Reason = reason;
        }

        public static DatasetCheckResult Skip(string name, string reason) => new DatasetCheckResult(name, DatasetCheckStatus.Skipped, null, null, reason);

        public string Name { get; }
        public DatasetCheckStatus Status { get; }

        /// <summary>What was measured, in words and numbers (e.g. "median IoU 0.998 over 40 views").</summary>
        public string Figure { get; }

        /// <summary>What the figure is held to (e.g. "IoU ≥ 0.98 per view").</summary>
        public string Threshold { get; }

        /// <summary>Why it was skipped, or a note on a pass or failure; may be null.</summary>
        public string Reason { get; }

        public string SummaryLine
        {
            get
            {
                var status = Status.ToString().ToLowerInvariant();
                if (Status == DatasetCheckStatus.Skipped) return Name + ": skipped (" + Reason + ")";
                return Name + ": " + Figure + "; threshold " + Threshold + "; " + status + (string.IsNullOrEmpty(Reason) ? "" : " (" + Reason + ")");
            }
        }

        internal static string Number(double value, string format = "0.###") => value.ToString(format, CultureInfo.InvariantCulture);
    }
}
