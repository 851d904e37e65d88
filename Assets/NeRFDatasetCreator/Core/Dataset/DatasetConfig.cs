using System.Collections.Generic;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A dataset's <c>dataset_config.json</c> as typed sections — who wrote it, whether its images were rendered, the
    /// background and camera sources of its settings, the time record, the point cloud and geometry pack records, the
    /// target's reach. Read once per command (<see cref="Read"/>) and handed to every reader, so no other file opens or
    /// parses it; written by <see cref="Write"/>. Each feature's section is read by the feature's own record type
    /// (<see cref="RecordedTime"/>, <see cref="PointCloudRecord"/>, <see cref="GeometryPackStepRecord"/>,
    /// <see cref="InsideOutRecord"/>, <see cref="DatasetTargetReach"/>) from the object parsed here. Every section is
    /// lenient: a key that is missing or of the wrong type reads as "not recorded", as every caller treated it before.
    /// </summary>
    public sealed partial class DatasetConfig
    {
        public const string FileName = DatasetLayout.ConfigFileName;

        public DatasetConfig(JObject json)
        {
            Json = json ?? new JObject();
        }

        /// <summary>The whole parsed object, strings verbatim (merge compares and copies it key by key).</summary>
        public JObject Json { get; }

        /// <summary><c>generator</c>: the software that wrote the dataset, or null when the key is not a string.</summary>
        public string Generator => Json["generator"]?.Type == JTokenType.String ? (string)Json["generator"] : null;

        /// <summary>Whether this plugin wrote the dataset (<see cref="PluginInfo.Name"/> as <c>generator</c>).</summary>
        public bool IsThisPlugin => Generator == PluginInfo.Name;

        /// <summary><c>imagesRendered</c>, a boolean (<see cref="Provenance.ImagesRendered"/>); null when it is not one.</summary>
        public bool? ImagesRendered => Json["imagesRendered"]?.Type == JTokenType.Boolean ? (bool?)(bool)Json["imagesRendered"] : null;

        /// <summary>True when the config marks the folder as a plan without images (<c>"imagesRendered": false</c>).</summary>
        public bool IsPlanOnly => ImagesRendered == false;

        /// <summary>The <c>settings</c> object (the same object a settings file holds, <see cref="DatasetSettingsJson"/>), or null.</summary>
        public JObject Settings => Json["settings"] as JObject;

        /// <summary><c>settings.background</c> as written ("transparent", "sky", "#rrggbb"), or null when it is not a string.</summary>
        public string BackgroundText => Settings?["background"]?.Type == JTokenType.String ? (string)Settings["background"] : null;

        /// <summary><c>settings.background</c> parsed as the settings reader parses it; null when absent or not one of its forms.</summary>
        public BackgroundSettings Background => BackgroundSettings.Parse(BackgroundText);

        /// <summary>The capture was over a solid colour or the sky: alpha is 255 everywhere by design.</summary>
        public bool OpaqueBackground => Background is BackgroundSettings b && !b.Transparent;

        /// <summary>Whether a split's camera source was a volume: an inside-out environment capture (<see cref="InsideOutRecord"/>).</summary>
        public bool InsideOut => InsideOutRecord.FromConfig(Json);

        /// <summary>The <c>time</c> record of a dynamic capture, or null for a still one (<see cref="TimeRecord"/> writes it).</summary>
        public RecordedTime Time => RecordedTime.FromJson(Json[TimeRecord.Key]);

        /// <summary>The <c>pointCloud</c> record, or null when there is none or it is malformed.</summary>
        public PointCloudRecord PointCloud => PointCloudRecord.FromConfig(Json);

        /// <summary>The <c>relighting</c> record (<see cref="RelightingRecord"/>), or null.</summary>
        public RelightingRecord Relighting => RelightingRecord.Read(Json);

        /// <summary>The <c>geometry</c> record as written (<see cref="GeometryPackRecord"/>), or null.</summary>
        public JObject GeometryRecord => Json[GeometryPackRecord.Key] as JObject;

        /// <summary>Every mesh of the geometry pack, in step order (<see cref="GeometryPackStepRecord.Entries"/>); empty without a pack.</summary>
        public IReadOnlyList<GeometryPackEntry> GeometryEntries => GeometryPackStepRecord.Entries(Json);

        /// <summary>Whether the geometry pack holds one mesh per time step.</summary>
        public bool GeometryIsPerStep => GeometryPackStepRecord.IsPerStep(Json);

        /// <summary>
        /// The output-to-Unity frame (<see cref="UnityFrameRecord"/>): <c>unity_frame</c>, else derived from
        /// <c>scene_normalisation</c>; null when neither is recorded. A malformed <c>unity_frame</c> throws, naming it.
        /// </summary>
        public UnityFrameRecord UnityFrame => UnityFrameRecord.Read(Json);

        /// <summary>How far the target reaches from the output origin (<see cref="DatasetTargetReach"/>), or null; a malformed record is a warning.</summary>
        public double? TargetReach(ICollection<ValidationProblem> warnings = null) => DatasetTargetReach.FromConfig(Json, warnings);
    }
}
