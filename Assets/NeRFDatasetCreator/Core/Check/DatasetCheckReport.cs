using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>What <see cref="DatasetCheck.Run"/> found: one result per check, then every problem.</summary>
    public sealed class DatasetCheckReport
    {
        readonly List<DatasetCheckResult> results = new List<DatasetCheckResult>();
        readonly List<DatasetProblem> problems = new List<DatasetProblem>();

        public DatasetCheckReport(string datasetFolder) { DatasetFolder = datasetFolder; }

        public string DatasetFolder { get; }

        /// <summary>How many views were decoded and checked.</summary>
        public int ViewsChecked { get; internal set; }

        /// <summary>True when the check was cancelled before every view was seen; the results cover the views seen.</summary>
        public bool Cancelled { get; internal set; }

        /// <summary>Time spent reading and decoding PNGs, and in all, in seconds (for the log and the benchmark).</summary>
        public double DecodeSeconds { get; internal set; }
        public double TotalSeconds { get; internal set; }

        /// <summary>Time spent in each check, in seconds, by name (for the benchmark).</summary>
        public Dictionary<string, double> CheckSeconds { get; } = new Dictionary<string, double>();

        /// <summary>True when any check failed or any problem was found.</summary>
        public bool Failed => problems.Count > 0 || results.Any(r => r.Status == DatasetCheckStatus.Failed);

        public IReadOnlyList<DatasetCheckResult> Results => results;

        /// <summary>One line per check: name, figure, threshold, passed/failed/skipped (why).</summary>
        public IReadOnlyList<string> SummaryLines => results.Select(r => r.SummaryLine).ToList();

        /// <summary>Every problem, each naming its file, frame and check.</summary>
        public IReadOnlyList<DatasetProblem> Problems => problems;

        public void Add(DatasetCheckResult result) => results.Add(result);
        public void Add(DatasetProblem problem) => problems.Add(problem);

        /// <summary>The whole report as indented JSON.</summary>
        public string ToJson()
        {
            var json = new JObject
            {
                ["dataset"] = DatasetFolder,
                ["failed"] = Failed,
                ["cancelled"] = Cancelled,
                ["viewsChecked"] = ViewsChecked,
                ["checks"] = new JArray(results.Select(r => new JObject
                {
                    ["name"] = r.Name,
                    ["status"] = r.Status.ToString().ToLowerInvariant(),
                    ["figure"] = r.Figure,
                    ["threshold"] = r.Threshold,
                    ["reason"] = r.Reason,
                })),
                ["problems"] = new JArray(problems.Select(p => new JObject
                {
                    ["check"] = p.Check,
                    ["file"] = p.File,
                    ["frame"] = p.Frame,
                    ["message"] = p.Message,
                })),
            };
            return json.ToString(Formatting.Indented).Replace("\r\n", "\n") + "\n";
        }
    }
}
