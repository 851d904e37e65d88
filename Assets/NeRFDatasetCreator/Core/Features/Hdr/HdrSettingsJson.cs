using System;
using System.Collections.Generic;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>The config-file form of <see cref="HdrSettings"/>: <c>"hdr": { "splits": ["train", "val", "test"] }</c>, written only when on.</summary>
    public static class HdrSettingsJson
    {
        public const string Key = "hdr";

        public static void Write(JsonWriter w, HdrSettings h)
        {
            if (h == null || !h.Enabled) return;
            w.WritePropertyName(Key);
            w.WriteStartObject();
            w.WritePropertyName("splits");
            w.WriteStartArray();
            foreach (var split in DatasetSplits.All)
                if (h.Applies(split)) w.WriteValue(DatasetSplits.Name(split));
            w.WriteEndArray();
            w.WriteEndObject();
        }

        internal static void Read(DatasetSettingsJson.Reader reader, JToken token, string path, HdrSettings h)
        {
            // Giving the section turns it on; "enabled": false turns it off again.
            h.On = true;
            var enabled = reader.Feature(token, path, new Dictionary<string, Action<JToken, string>>
            {
                ["splits"] = (v, p) =>
                {
                    if (v.Type != JTokenType.Array) throw reader.Error(v, p, "must be a list of split names such as [\"train\", \"test\"].");
                    h.Train = h.Val = h.Test = false;
                    var index = 0;
                    foreach (var item in (JArray)v)
                    {
                        var itemPath = p + "[" + index++ + "]";
                        if (!DatasetSplits.TryParse(reader.String(item, itemPath), out var split))
                            throw reader.Error(item, itemPath, "is not a split; use \"train\", \"val\" or \"test\"." +
                                SpellingSuggestion.Sentence((string)item, DatasetSplits.Names));
                        if (split == DatasetSplit.Train) h.Train = true;
                        else if (split == DatasetSplit.Val) h.Val = true;
                        else h.Test = true;
                    }
                },
            });
            if (enabled == false) h.On = false;
        }
    }
}
