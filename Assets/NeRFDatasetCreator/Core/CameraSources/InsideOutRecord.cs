using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Whether a dataset is an inside-out environment capture, as its own <c>dataset_config.json</c> records it: a split
    /// of <c>settings.splits</c> whose <c>source.kind</c> is <c>"volume"</c> (<see cref="CameraSourceJson"/>). False
    /// when the dataset does not say (nerf_synthetic, other tools, an unreadable config).
    /// </summary>
    public static class InsideOutRecord
    {
        /// <summary>The record in a parsed dataset_config.json (<see cref="DatasetConfig.InsideOut"/>); null reads as false.</summary>
        public static bool FromConfig(JObject config)
        {
            // Objects all the way down: a list or a number where an object belongs reads as "not recorded", never a crash.
            if (!((config?["settings"] as JObject)?["splits"] is JObject splits)) return false;
            foreach (var split in splits.Properties())
                if (((split.Value as JObject)?["source"] as JObject)?["kind"] is JValue kind && kind.Type == JTokenType.String &&
                    (string)kind == CameraSourceSettings.KindName(CameraSourceKind.Volume))
                    return true;
            return false;
        }
    }
}
