using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The config-file form of <see cref="ExposureSettings"/>, the <c>"exposure"</c> object of a settings file
    /// (Documentation~/exposure.md). Written only when exposure is on, so other configs keep their shape.
    /// </summary>
    public static class ExposureSettingsJson
    {
        public const string Key = "exposure";

        /// <summary>The <c>"exposure"</c> section when exposure is on; nothing when it is off.</summary>
        public static void Write(JsonWriter w, ExposureSettings e)
        {
            if (e == null || !e.Enabled) return;
            w.WritePropertyName(Key);
            WriteObject(w, e);
        }

        public static void WriteObject(JsonWriter w, ExposureSettings e)
        {
            w.WriteStartObject();
            w.WritePropertyName("mode"); w.WriteValue(ExposureModes.IsDefined(e.Mode) ? ExposureModes.Name(e.Mode) : ((int)e.Mode).ToString(System.Globalization.CultureInfo.InvariantCulture));
            w.WritePropertyName("splits");
            w.WriteStartArray();
            foreach (var split in DatasetSplits.All)
                if (SplitOn(e, split)) w.WriteValue(DatasetSplits.Name(split));
            w.WriteEndArray();
            if (e.Mode == ExposureMode.List)
            {
                w.WritePropertyName("values");
                w.WriteStartArray();
                foreach (var v in e.Values ?? new List<ViewExposure>())
                {
                    w.WriteStartObject();
                    JsonNumbers.SettingNumber(w, "ev", v.Ev);
                    w.WritePropertyName("whiteBalance");
                    w.WriteStartArray();
                    JsonNumbers.SettingValue(w, v.R); JsonNumbers.SettingValue(w, v.G); JsonNumbers.SettingValue(w, v.B);
                    w.WriteEndArray();
                    w.WriteEndObject();
                }
                w.WriteEndArray();
            }
            else
            {
                Pair(w, "evRange", e.EvMin, e.EvMax);
                Pair(w, "gainRange", e.GainMin, e.GainMax);
            }
            w.WritePropertyName("writeClean"); w.WriteValue(e.WriteClean);
            w.WriteEndObject();
        }

        static bool SplitOn(ExposureSettings e, DatasetSplit split) =>
            split == DatasetSplit.Train ? e.Train : split == DatasetSplit.Val ? e.Val : e.Test;

        static void Pair(JsonWriter w, string name, double a, double b)
        {
            w.WritePropertyName(name);
            w.WriteStartArray();
            JsonNumbers.SettingValue(w, a);
            JsonNumbers.SettingValue(w, b);
            w.WriteEndArray();
        }

        internal static void Read(DatasetSettingsJson.Reader reader, JToken token, string path, ExposureSettings e)
        {
            // Giving the section turns it on; "mode": "off" or "enabled": false turns it off again.
            if (e.Mode == ExposureMode.Off) e.Mode = ExposureMode.Random;
            var enabled = reader.Feature(token, path, new Dictionary<string, Action<JToken, string>>
            {
                ["mode"] = (v, p) => e.Mode = reader.Name<ExposureMode>(v, p, ExposureModes.TryParse, ExposureModes.NameList(), ExposureModes.All.Select(ExposureModes.Name)),
                ["splits"] = (v, p) =>
                {
                    if (v.Type != JTokenType.Array) throw reader.Error(v, p, "must be a list of split names such as [\"train\"].");
                    e.Train = e.Val = e.Test = false;
                    var index = 0;
                    foreach (var item in (JArray)v)
                    {
                        var itemPath = p + "[" + index++ + "]";
                        if (!DatasetSplits.TryParse(reader.String(item, itemPath), out var split))
                            throw reader.Error(item, itemPath, "is not a split; use \"train\", \"val\" or \"test\"." +
                                SpellingSuggestion.Sentence((string)item, DatasetSplits.Names));
                        if (split == DatasetSplit.Train) e.Train = true;
                        else if (split == DatasetSplit.Val) e.Val = true;
                        else e.Test = true;
                    }
                },
                ["evRange"] = (v, p) => ReadPair(reader, v, p, "stops", out e.EvMin, out e.EvMax),
                ["gainRange"] = (v, p) => ReadPair(reader, v, p, "gains", out e.GainMin, out e.GainMax),
                ["values"] = (v, p) =>
                {
                    if (v.Type != JTokenType.Array) throw reader.Error(v, p, "must be a list of { \"ev\": …, \"whiteBalance\": [r, g, b] } objects.");
                    var values = new List<ViewExposure>();
                    var index = 0;
                    foreach (var item in (JArray)v)
                    {
                        var itemPath = p + "[" + index++ + "]";
                        var value = ViewExposure.Identity;
                        reader.Object(item, itemPath, new Dictionary<string, Action<JToken, string>>
                        {
                            ["ev"] = (t, q) => value.Ev = reader.Double(t, q, "a number of stops"),
                            ["whiteBalance"] = (t, q) =>
                            {
                                if (t.Type != JTokenType.Array || ((JArray)t).Count != 3)
                                    throw reader.Error(t, q, "must be three gains [r, g, b], e.g. [1.1, 1, 0.9].");
                                value.R = reader.Double(t[0], q + "[0]");
                                value.G = reader.Double(t[1], q + "[1]");
                                value.B = reader.Double(t[2], q + "[2]");
                            },
                        });
                        values.Add(value);
                    }
                    e.Values = values;
                },
                ["writeClean"] = (v, p) => e.WriteClean = reader.Bool(v, p),
            });
            reader.Switch(token, path, enabled, e.Enabled, () => e.Mode = ExposureMode.Off, "\"mode\" is \"off\"; give \"mode\": \"random\" or \"list\"");
        }

        static void ReadPair(DatasetSettingsJson.Reader reader, JToken v, string p, string what, out double min, out double max)
        {
            if (v.Type != JTokenType.Array || ((JArray)v).Count != 2)
                throw reader.Error(v, p, "must be two " + what + " [lowest, highest].");
            min = reader.Double(v[0], p + "[0]");
            max = reader.Double(v[1], p + "[1]");
        }
    }
}
