using System.Globalization;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What dataset_config.json records of a capture's flow: <c>"flow": { "record": "flow/flow.json", "pairs": n,
    /// "videos": n, "tracks": n }</c> (the counts of flow.json's lists), and the capture summary's sentence about it.
    /// </summary>
    public static class FlowConfigRecord
    {
        public const string Key = "flow";

        /// <param name="flow">flow.json's content (<see cref="FlowWriter.Write"/>).</param>
        public static JObject Of(JObject flow) => new JObject
        {
            ["record"] = FlowLayout.RecordFile,
            ["pairs"] = Count(flow, "pairs"),
            ["videos"] = Count(flow, "videos"),
            ["tracks"] = Count(flow, "tracks"),
        };

        /// <summary>"flow/ holds 8 frame pairs of 1 video and 1 tracks file (flow/flow.json)."</summary>
        public static string Summary(JObject flow) => string.Format(CultureInfo.InvariantCulture,
            "flow/ holds {0} frame pairs of {1} video{2} and {3} tracks file{4} ({5}).",
            Count(flow, "pairs"), Count(flow, "videos"), Count(flow, "videos") == 1 ? "" : "s", Count(flow, "tracks"), Count(flow, "tracks") == 1 ? "" : "s", FlowLayout.RecordFile);

        static int Count(JObject flow, string key) => flow?[key] is JArray a ? a.Count : 0;
    }
}
