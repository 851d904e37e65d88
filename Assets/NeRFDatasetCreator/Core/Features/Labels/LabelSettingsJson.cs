using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The config-file form of <see cref="LabelSettings"/>, the <c>"labels"</c> object of a settings file
    /// (Documentation~/labels.md). Its presence turns labels on (<c>"enabled": false</c> off again); written only when they are on, so other configs keep
    /// their shape. <c>{"instances": "prefab", "classFrom": "tag", "classes": [{"match": "Car*", "class": "car"}], "otherClass": ""}</c>
    /// </summary>
    public static class LabelSettingsJson
    {
        public const string Key = "labels";

        /// <summary>What a message advises pasting into a settings file to turn labels on (a test pastes it into the sample config).</summary>
        public const string TurnOn = "\"labels\": { \"enabled\": true }";

        /// <summary>The <c>"labels"</c> section when labels are on; nothing when they are off.</summary>
        public static void Write(JsonWriter w, LabelSettings labels)
        {
            if (labels == null || !labels.Enabled) return;
            w.WritePropertyName(Key);
            WriteObject(w, labels);
        }

        public static void WriteObject(JsonWriter w, LabelSettings labels)
        {
            w.WriteStartObject();
            w.WritePropertyName("instances"); w.WriteValue(InstanceRules.Name(labels.Instances));
            w.WritePropertyName("classFrom"); w.WriteValue(ClassSources.Name(labels.ClassFrom));
            w.WritePropertyName("classes");
            w.WriteStartArray();
            foreach (var rule in labels.Classes ?? new List<ClassRule>())
            {
                w.WriteStartObject();
                w.WritePropertyName("match"); w.WriteValue(rule?.Match ?? "");
                w.WritePropertyName("class"); w.WriteValue(rule?.Class ?? "");
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WritePropertyName("otherClass"); w.WriteValue(labels.OtherClass ?? "");
            w.WriteEndObject();
        }

        internal static void Read(DatasetSettingsJson.Reader reader, JToken token, string path, LabelSettings labels)
        {
            // Giving the section turns labels on; "enabled": false turns them off again.
            var enabled = reader.Feature(token, path, new Dictionary<string, Action<JToken, string>>
            {
                ["instances"] = (v, p) => labels.Instances = reader.Name<InstanceRule>(v, p, InstanceRules.TryParse, InstanceRules.NameList(), InstanceRules.All.Select(InstanceRules.Name)),
                ["classFrom"] = (v, p) => labels.ClassFrom = reader.Name<ClassSource>(v, p, ClassSources.TryParse, ClassSources.NameList(), ClassSources.All.Select(ClassSources.Name)),
                ["classes"] = (v, p) =>
                {
                    if (v.Type != JTokenType.Array)
                        throw reader.Error(v, p, "must be a list such as [{\"match\": \"Car*\", \"class\": \"car\"}].");
                    var rules = new List<ClassRule>();
                    var index = 0;
                    foreach (var item in (JArray)v)
                    {
                        var itemPath = p + "[" + (index++).ToString(System.Globalization.CultureInfo.InvariantCulture) + "]";
                        var rule = new ClassRule();
                        reader.Object(item, itemPath, new Dictionary<string, Action<JToken, string>>
                        {
                            ["match"] = (m, mp) => rule.Match = reader.String(m, mp),
                            ["class"] = (c, cp) => rule.Class = reader.String(c, cp),
                        });
                        rules.Add(rule);
                    }
                    labels.Classes = rules;
                },
                ["otherClass"] = (v, p) => labels.OtherClass = reader.String(v, p),
            });
            labels.Enabled = enabled ?? true;
        }
    }
}
