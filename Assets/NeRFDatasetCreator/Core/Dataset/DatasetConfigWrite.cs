using System.Globalization;
using Newtonsoft.Json;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writing <c>dataset_config.json</c> (reading it is <see cref="Read"/>): enough to regenerate the dataset — the full settings (the same object a config
    /// file holds, so it can be used as one), the seed, the resolved distance, the target and how output poses
    /// relate to the Unity world (<c>scene_normalisation</c>, as in the transforms files, and its inverse <c>unity_frame</c>), the plugin and Unity versions
    /// and the UTC date; with a point cloud, its <see cref="PointCloudRecord"/> (file, point count, SHA-256).
    /// </summary>
    public sealed partial class DatasetConfig
    {
        /// <param name="pointCloud">The record of the <c>points3d.ply</c> this run wrote, or null when it wrote none.</param>
        /// <param name="geometry">The geometry pack's record (<see cref="GeometryPackRecord"/>), or null when the run wrote none.</param>
        /// <param name="flow">The flow record (<see cref="FlowConfigRecord"/>), or null when the run computed no flow.</param>
        public static string Write(CapturePlan plan, Provenance provenance, PointCloudRecord pointCloud = null, Newtonsoft.Json.Linq.JObject geometry = null,
            Newtonsoft.Json.Linq.JObject flow = null)
        {
            using (var text = JsonNumbers.CreateText())
            {
                using (var w = JsonNumbers.CreateWriter(text))
                {
                    w.WriteStartObject();
                    w.WritePropertyName("generator"); w.WriteValue(PluginInfo.Name);
                    w.WritePropertyName("pluginVersion"); w.WriteValue(PluginInfo.Version);
                    w.WritePropertyName("unityVersion");
                    if (string.IsNullOrEmpty(provenance.UnityVersion)) w.WriteNull();
                    else w.WriteValue(provenance.UnityVersion);
                    w.WritePropertyName("tool");
                    if (string.IsNullOrEmpty(provenance.Tool)) w.WriteNull();
                    else w.WriteValue(provenance.Tool);
                    w.WritePropertyName("imagesRendered"); w.WriteValue(provenance.ImagesRendered);
                    w.WritePropertyName("createdUtc");
                    w.WriteValue(provenance.CreatedUtc.ToString("yyyy-MM-dd'T'HH:mm:ss'Z'", CultureInfo.InvariantCulture));
                    w.WritePropertyName("seed"); w.WriteValue(plan.Settings.Seed);
                    w.WritePropertyName("distance"); JsonNumbers.Write(w, plan.Distance);
                    w.WritePropertyName("target");
                    w.WriteStartObject();
                    w.WritePropertyName("unityCentre");
                    w.WriteStartArray();
                    JsonNumbers.Write(w, plan.Target.Centre.X); JsonNumbers.Write(w, plan.Target.Centre.Y); JsonNumbers.Write(w, plan.Target.Centre.Z);
                    w.WriteEndArray();
                    w.WritePropertyName("boundingRadius");
                    if (plan.Target.HasBounds) JsonNumbers.Write(w, plan.Target.BoundingRadius);
                    else w.WriteNull();
                    w.WriteEndObject();
                    w.WritePropertyName("outputFrame");
                    w.WriteValue("Blender world (right-handed, +Z up): output = scene_normalisation.scale * ((x, z, y) of the Unity position - scene_normalisation.centre); OpenGL camera axes; depth files in output units");
                    w.WritePropertyName(BlenderTransformsWriter.SceneNormalisationKey);
                    JsonNumbers.WriteToken(w, plan.Normalisation.ToJson());
                    // How to go back: the output-to-Unity matrix and the Editor's facts about the target (issue 34, place-splat).
                    w.WritePropertyName(UnityFrameRecord.Key);
                    JsonNumbers.WriteToken(w, UnityFrameRecord.ToJson(plan.Normalisation, provenance.UnityFrame));
                    w.WritePropertyName("views");
                    w.WriteStartObject();
                    foreach (var split in DatasetSplits.All)
                    {
                        w.WritePropertyName(DatasetSplits.Name(split));
                        w.WriteValue(TimePlanning.ViewCount(plan.Settings, plan.Time, split));
                    }
                    w.WriteEndObject();
                    if (plan.Time != null)
                    {
                        w.WritePropertyName(TimeRecord.Key);
                        TimeRecord.Write(w, plan.Time, plan.Settings.Time);
                    }
                    MaterialRecord.Write(w, plan.Settings, provenance.Materials);
                    if (pointCloud != null)
                    {
                        w.WritePropertyName(PointCloudRecord.Key);
                        JsonNumbers.WriteToken(w, pointCloud.ToJson());
                    }
                    if (geometry != null)
                    {
                        w.WritePropertyName(GeometryPackRecord.Key);
                        JsonNumbers.WriteToken(w, geometry);
                    }
                    RelightingRecord.Write(w, plan.Settings);
                    if (flow != null)
                    {
                        w.WritePropertyName(FlowConfigRecord.Key);
                        JsonNumbers.WriteToken(w, flow);
                    }
                    if (provenance.Statistics.Count > 0)
                    {
                        w.WritePropertyName("statistics");
                        w.WriteStartObject();
                        foreach (var pair in provenance.Statistics)
                        {
                            w.WritePropertyName(pair.Key);
                            JsonNumbers.Write(w, pair.Value);
                        }
                        w.WriteEndObject();
                    }
                    w.WritePropertyName("settings");
                    DatasetSettingsJson.WriteObject(w, plan.Settings);
                    w.WriteEndObject();
                }
                return text.ToString() + "\n"; // the writer's text, formatted by CreateText's invariant culture
            }
        }

        /// <summary>
        /// The config as text again, indented and ending in a newline: how merge writes the merged dataset's config (the
        /// first shard's, its strings verbatim, with the records that describe the whole dataset; see MergeStaging).
        /// </summary>
        public string ToText() => Json.ToString(Formatting.Indented) + "\n";
    }
}
