namespace NerfDatasetCreator
{
    /// <summary>
    /// The captured target's hierarchy path as the dataset recorded it (<c>dataset_config.json</c> <c>settings.target</c>,
    /// written by DatasetSettingsJson), so <i>Place trained splat</i> can find the source object when none is picked.
    /// </summary>
    public static class SplatSourceTarget
    {
        /// <summary>"Props/Lego", or null when the dataset has no readable config or no target (a plan, a whole-scene capture).</summary>
        public static string HierarchyPathIn(string datasetFolder)
        {
            if (string.IsNullOrWhiteSpace(datasetFolder)) return null;
            var settings = DatasetConfig.Read(datasetFolder).Config?.Settings;
            var target = settings?["target"];
            if (target == null || target.Type != Newtonsoft.Json.Linq.JTokenType.String) return null;
            var path = (string)target;
            return string.IsNullOrWhiteSpace(path) ? null : path;
        }
    }
}
