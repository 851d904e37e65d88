using System;
using System.Collections.Generic;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The config-file form of <see cref="FlowSettings"/> (Documentation~/flow.md): <c>"flow": { "forward": true,
    /// "backward": true, "spans": [1], "sceneFlow": true, "tracks": { "queryFrames": [0], "stride": 8 } }</c>. Giving the
    /// section turns flow on, <c>"enabled": false</c> off (the one convention, Documentation~/settings.md); written only
    /// when on, so other configs keep their bytes.
    /// </summary>
    public static class FlowSettingsJson
    {
        public const string Key = "flow";

        public static void Write(JsonWriter w, FlowSettings f)
        {
            if (f == null || !f.Enabled) return;
            w.WritePropertyName(Key);
            w.WriteStartObject();
            w.WritePropertyName("forward"); w.WriteValue(f.Forward);
            w.WritePropertyName("backward"); w.WriteValue(f.Backward);
            w.WritePropertyName("spans"); Ints(w, f.Spans);
            w.WritePropertyName("sceneFlow"); w.WriteValue(f.SceneFlow);
            w.WritePropertyName("tracks");
            w.WriteStartObject();
            w.WritePropertyName("queryFrames"); Ints(w, f.TrackQueryFrames);
            w.WritePropertyName("stride"); w.WriteValue(f.TrackStride);
            w.WriteEndObject();
            w.WriteEndObject();
        }

        static void Ints(JsonWriter w, int[] values)
        {
            w.WriteStartArray();
            foreach (var v in values ?? new int[0]) w.WriteValue(v);
            w.WriteEndArray();
        }

        internal static void Read(DatasetSettingsJson.Reader reader, JToken token, string path, FlowSettings f)
        {
            // Giving the section turns it on; "enabled": false turns it off again.
            f.On = true;
            var enabled = reader.Feature(token, path, new Dictionary<string, Action<JToken, string>>
            {
                ["forward"] = (v, p) => f.Forward = reader.Bool(v, p),
                ["backward"] = (v, p) => f.Backward = reader.Bool(v, p),
                ["spans"] = (v, p) => f.Spans = IntList(reader, v, p, "step spans such as [1, 2]"),
                ["sceneFlow"] = (v, p) => f.SceneFlow = reader.Bool(v, p),
                ["tracks"] = (v, p) => reader.Object(v, p, new Dictionary<string, Action<JToken, string>>
                {
                    ["queryFrames"] = (t, q) => f.TrackQueryFrames = IntList(reader, t, q, "frame indices such as [0, 10]"),
                    ["stride"] = (t, q) => f.TrackStride = reader.Int(t, q),
                }),
            });
            if (enabled == false) f.On = false;
        }

        static int[] IntList(DatasetSettingsJson.Reader reader, JToken v, string p, string what)
        {
            if (v.Type != JTokenType.Array) throw reader.Error(v, p, "must be a list of " + what + ", not " + DatasetSettingsJson.Describe(v) + ".");
            var list = new List<int>();
            var index = 0;
            foreach (var item in (JArray)v) list.Add(reader.Int(item, p + "[" + index++ + "]"));
            return list.ToArray();
        }
    }
}
