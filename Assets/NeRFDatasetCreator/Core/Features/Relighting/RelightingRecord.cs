using System.Collections.Generic;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>relighting</c> record of dataset_config.json: <c>{ "lights_file": "lights/lights.json", "keys": ["sunset_000", …] }</c>
    /// — where the lights are described and every condition key a frame's <c>relit_paths</c> holds.
    /// </summary>
    public sealed class RelightingRecord
    {
        public const string Key = "relighting";

        /// <summary>The lights file as recorded (relative to the dataset root).</summary>
        public string LightsFile { get; private set; }

        /// <summary>The recorded keys, in order.</summary>
        public IReadOnlyList<string> Keys { get; private set; }

        /// <summary>The record when <paramref name="settings"/> relight the views; nothing otherwise.</summary>
        public static void Write(JsonWriter w, DatasetSettings settings)
        {
            var keys = LightingKeys.All(settings);
            if (keys.Count == 0) return;
            w.WritePropertyName(Key);
            w.WriteStartObject();
            w.WritePropertyName("lights_file"); w.WriteValue(RelightingKeys.LightsFile);
            w.WritePropertyName("keys");
            w.WriteStartArray();
            foreach (var key in keys) w.WriteValue(key);
            w.WriteEndArray();
            w.WriteEndObject();
        }

        /// <summary>The record of a config (null when it has none, or it is not an object with a "keys" list of strings).</summary>
        public static RelightingRecord Read(JObject config)
        {
            if (!(config?[Key] is JObject record) || !(record["keys"] is JArray list)) return null;
            var keys = new List<string>();
            foreach (var item in list)
                if (item.Type == JTokenType.String) keys.Add((string)item);
            return new RelightingRecord
            {
                LightsFile = record["lights_file"]?.Type == JTokenType.String ? (string)record["lights_file"] : null,
                Keys = keys,
            };
        }
    }
}
