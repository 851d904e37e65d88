using System;
using System.Collections.Generic;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The config-file form of <see cref="MaterialPassSettings"/>: <c>"materials": { "passes": ["albedo", "metallic",
    /// "roughness"] }</c>, written only when on. Giving the section turns it on (passes default to albedo, metallic,
    /// roughness); <c>"enabled": false</c> turns it off again. An unknown pass name is refused here, naming the key; an
    /// empty list by <see cref="MaterialPassSettingsValidator"/>.
    /// </summary>
    public static class MaterialPassSettingsJson
    {
        public const string Key = "materials";
        public const string PassesKey = "passes";

        public static void Write(JsonWriter w, MaterialPassSettings m)
        {
            if (m == null || !m.Enabled) return;
            w.WritePropertyName(Key);
            w.WriteStartObject();
            w.WritePropertyName(PassesKey);
            w.WriteStartArray();
            foreach (var name in MaterialPassNames.On(m)) w.WriteValue(name);
            w.WriteEndArray();
            w.WriteEndObject();
        }

        internal static void Read(DatasetSettingsJson.Reader reader, JToken token, string path, MaterialPassSettings m)
        {
            m.On = true;
            var enabled = reader.Feature(token, path, new Dictionary<string, Action<JToken, string>>
            {
                [PassesKey] = (v, p) =>
                {
                    if (v.Type != JTokenType.Array)
                        throw reader.Error(v, p, "must be a list of pass names such as [\"albedo\", \"metallic\", \"roughness\"].");
                    m.Albedo = m.Metallic = m.Roughness = m.Specular = m.Emission = false;
                    var index = 0;
                    foreach (var item in (JArray)v)
                    {
                        var itemPath = p + "[" + index++ + "]";
                        var name = reader.String(item, itemPath);
                        if (!MaterialPassNames.TurnOn(m, name))
                            throw reader.Error(item, itemPath, "is not a material pass; use " + string.Join(", ", MaterialPassNames.All) + "." +
                                SpellingSuggestion.Sentence(name, MaterialPassNames.All));
                    }
                },
            });
            if (enabled == false) m.On = false;
        }
    }
}
