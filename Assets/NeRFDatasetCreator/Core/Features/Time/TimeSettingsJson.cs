using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The config-file form of <see cref="TimeSettings"/>, the <c>"time"</c> object of a settings file
    /// (Documentation~/dynamic-capture.md). Written only for a dynamic capture, so static configs keep their shape.
    /// </summary>
    public static class TimeSettingsJson
    {
        public const string Key = "time";

        /// <summary>The <c>"time"</c> section of a dynamic capture; nothing for a static one.</summary>
        public static void Write(JsonWriter w, TimeSettings t)
        {
            if (t == null || !t.Enabled) return;
            w.WritePropertyName(Key);
            WriteObject(w, t);
        }

        public static void WriteObject(JsonWriter w, TimeSettings t)
        {
            w.WriteStartObject();
            w.WritePropertyName("mode"); w.WriteValue(TimeModes.IsDefined(t.Mode) ? TimeModes.Name(t.Mode) : ((int)t.Mode).ToString(System.Globalization.CultureInfo.InvariantCulture));
            w.WritePropertyName("sources");
            w.WriteStartArray();
            foreach (var name in TimeSourceNames.NamesOf(t.Sources)) w.WriteValue(name);
            w.WriteEndArray();
            JsonNumbers.SettingNumber(w, "start", t.StartSeconds);
            if (t.EndAtClipLength)
            {
                w.WritePropertyName("end");
                w.WriteValue("clip");
            }
            else JsonNumbers.SettingNumber(w, "end", t.EndSeconds);
            w.WritePropertyName("steps"); w.WriteValue(t.Steps);
            JsonNumbers.SettingNumber(w, "fps", t.Fps);
            w.WriteEndObject();
        }

        internal static void Read(DatasetSettingsJson.Reader reader, JToken token, string path, TimeSettings t)
        {
            // "mode" says static (off) or dynamic; "enabled": false makes the capture static whatever the mode.
            var enabled = reader.Feature(token, path, new Dictionary<string, Action<JToken, string>>
            {
                ["mode"] = (v, p) => t.Mode = reader.Name<TimeMode>(v, p, TimeModes.TryParse, TimeModes.NameList(), TimeModes.All.Select(TimeModes.Name)),
                ["sources"] = (v, p) =>
                {
                    if (v.Type != JTokenType.Array) throw reader.Error(v, p, "must be a list such as [\"timeline\", \"animator\"].");
                    var sources = TimeSources.None;
                    var index = 0;
                    foreach (var item in (JArray)v)
                    {
                        var itemPath = p + "[" + index++ + "]";
                        if (!TimeSourceNames.TryParse(reader.String(item, itemPath), out var source))
                            throw reader.Error(item, itemPath, "is not a time source; use one of " + TimeSourceNames.NameList() + "." +
                                SpellingSuggestion.Sentence((string)item, new[] { "timeline", "animator", "animation", "particles" }));
                        sources |= source;
                    }
                    t.Sources = sources;
                },
                ["start"] = (v, p) => t.StartSeconds = reader.Double(v, p, "a number of seconds"),
                ["end"] = (v, p) =>
                {
                    if (v.Type == JTokenType.String && string.Equals((string)v, "clip", StringComparison.OrdinalIgnoreCase))
                        t.EndAtClipLength = true;
                    else
                    {
                        t.EndAtClipLength = false;
                        t.EndSeconds = reader.Double(v, p, "a number of seconds or \"clip\"");
                    }
                },
                ["steps"] = (v, p) => t.Steps = reader.Int(v, p),
                ["fps"] = (v, p) => t.Fps = reader.Double(v, p),
            });
            reader.Switch(token, path, enabled, t.Enabled, () => t.Mode = TimeMode.Static, "\"mode\" is \"static\" (or missing); give \"mode\": \"monocular\" or \"multi-view\"");
        }
    }
}
