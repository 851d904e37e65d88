using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The last line of <c>check</c> when nothing failed: "OK" and how many checks ran, naming the skipped ones (their
    /// summary lines above say why), so that a dataset that could be checked only in part does not read as fully checked
    /// (issue 33: "OK" when 10 of 12 checks were skipped).
    /// </summary>
    public static class CheckVerdict
    {
        public static string Passed(DatasetCheckReport report) => "OK (" + Ran(report) + ")";

        /// <summary>"12 of 12 checks ran", or "2 of 12 checks ran; 10 skipped: depth vs mask, …".</summary>
        public static string Ran(DatasetCheckReport report)
        {
            var all = report.Results.Count;
            var skipped = report.Results.Where(r => r.Status == DatasetCheckStatus.Skipped).Select(r => r.Name).ToList();
            var text = (all - skipped.Count) + " of " + all + " checks ran";
            return skipped.Count == 0 ? text : text + "; " + skipped.Count + " skipped: " + string.Join(", ", skipped);
        }
    }
}
