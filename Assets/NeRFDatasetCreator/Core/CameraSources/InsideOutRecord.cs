using System.IO;
using Newtonsoft.Json;
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
        public static bool Read(string datasetDirectory)
        {
            var path = Path.Combine(datasetDirectory, DatasetLayout.ConfigFileName);
            if (!File.Exists(path)) return false;
            try { return FromConfig(JObject.Parse(FileOps.ReadText(path))); }
            catch (JsonException) { return false; } // DatasetTargetReach already warns about a broken config
            catch (System.Exception e) when (e is IOException || e is System.UnauthorizedAccessException) { return false; } // … and an unreadable one
        }

        public static bool FromConfig(JObject config)
        {
            if (!(config?["settings"]?["splits"] is JObject splits)) return false;
            foreach (var split in splits.Properties())
                if (split.Value["source"]?["kind"] is JValue kind && kind.Type == JTokenType.String &&
                    (string)kind == CameraSourceSettings.KindName(CameraSourceKind.Volume))
                    return true;
            return false;
        }
    }
}
