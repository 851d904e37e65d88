using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The config-file form of <see cref="RelightingSettings"/>: <c>"relighting": { "conditions": [ { "name": "sunset",
    /// "kind": "environment", "file": "Assets/HDRI/sunset.exr", "rotations": [0, 90], "intensity": 1 }, … ] }</c>
    /// (Documentation~/relighting.md). Each condition holds only its kind's keys (<see cref="LightingKinds.KeysOf"/>); a key
    /// of another kind is refused by name. Written only when on, so a config without it keeps its bytes.
    /// </summary>
    public static class RelightingSettingsJson
    {
        public const string Key = "relighting";

        public static void Write(JsonWriter w, RelightingSettings r)
        {
            if (r == null || !r.Enabled) return;
            w.WritePropertyName(Key);
            w.WriteStartObject();
            w.WritePropertyName("conditions");
            w.WriteStartArray();
            foreach (var c in r.Conditions)
            {
                if (c == null) continue;
                w.WriteStartObject();
                w.WritePropertyName("name"); w.WriteValue(c.Name ?? "");
                w.WritePropertyName("kind"); w.WriteValue(LightingKinds.Name(c.Kind));
                if (c.Kind == LightingKind.Environment)
                {
                    w.WritePropertyName("file"); w.WriteValue(c.File ?? "");
                    Numbers(w, "rotations", c.Rotations);
                    JsonNumbers.SettingNumber(w, "intensity", c.Intensity);
                }
                else
                {
                    Numbers(w, "position", c.Position);
                    if (c.Kind == LightingKind.Spot)
                    {
                        if (c.Direction != null) Numbers(w, "direction", c.Direction);
                        JsonNumbers.SettingNumber(w, "spotAngle", c.SpotAngle);
                    }
                    JsonNumbers.SettingNumber(w, "intensity", c.Intensity);
                    Numbers(w, "colour", c.Colour);
                    w.WritePropertyName("shadows"); w.WriteValue(c.Shadows);
                }
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteEndObject();
        }

        static void Numbers(JsonWriter w, string name, double[] values)
        {
            w.WritePropertyName(name);
            w.WriteStartArray();
            foreach (var v in values ?? new double[0]) JsonNumbers.SettingValue(w, v);
            w.WriteEndArray();
        }

        internal static void Read(DatasetSettingsJson.Reader reader, JToken token, string path, RelightingSettings r)
        {
            // Giving the section turns it on; "enabled": false turns it off again.
            r.On = true;
            var enabled = reader.Feature(token, path, new Dictionary<string, Action<JToken, string>>
            {
                ["conditions"] = (v, p) =>
                {
                    if (v.Type != JTokenType.Array)
                        throw reader.Error(v, p, "must be a list of lighting conditions such as [{ \"name\": \"sunset\", \"kind\": \"environment\", \"file\": \"Assets/HDRI/sunset.exr\" }].");
                    r.Conditions = new List<LightingCondition>();
                    var index = 0;
                    foreach (var item in (JArray)v) r.Conditions.Add(ReadCondition(reader, item, p + "[" + index++ + "]"));
                },
            });
            if (enabled == false) r.On = false;
        }

        static LightingCondition ReadCondition(DatasetSettingsJson.Reader reader, JToken token, string path)
        {
            var c = new LightingCondition();
            if (token.Type != JTokenType.Object) throw reader.Error(token, path, "must be an object { \"name\": …, \"kind\": … }, not " + DatasetSettingsJson.Describe(token) + ".");
            var kindToken = token["kind"];
            if (kindToken == null) throw reader.Error(token, path + ".kind", "is missing; use " + LightingKinds.NameList() + ".");
            c.Kind = reader.Name<LightingKind>(kindToken, path + ".kind", LightingKinds.TryParse, LightingKinds.NameList(), LightingKinds.Names);
            var all = new Dictionary<string, Action<JToken, string>>
            {
                ["file"] = (v, p) => c.File = reader.String(v, p),
                ["rotations"] = (v, p) => c.Rotations = Numbers(reader, v, p, -1, "a list of whole degrees such as [0, 90, 180, 270]"),
                ["intensity"] = (v, p) => c.Intensity = reader.Double(v, p),
                ["position"] = (v, p) => c.Position = Numbers(reader, v, p, 3, "[x, y, z] in the output world (+Z up)"),
                ["direction"] = (v, p) => c.Direction = Numbers(reader, v, p, 3, "[x, y, z] in the output world (+Z up)"),
                ["spotAngle"] = (v, p) => c.SpotAngle = reader.Double(v, p),
                ["colour"] = (v, p) => c.Colour = Numbers(reader, v, p, 3, "[r, g, b] linear"),
                ["shadows"] = (v, p) => c.Shadows = reader.Bool(v, p),
            };
            var own = LightingKinds.KeysOf(c.Kind);
            var handlers = new Dictionary<string, Action<JToken, string>>
            {
                ["name"] = (v, p) => c.Name = reader.String(v, p),
                ["kind"] = (v, p) => { },
            };
            foreach (var pair in all)
            {
                var name = pair.Key;
                if (own.Contains(name)) handlers[name] = pair.Value;
                else handlers[name] = (v, p) => throw reader.Error(v, p, "is not a key of a " + LightingKinds.Name(c.Kind) + " light (it takes " + string.Join(", ", own) +
                    "); remove it, or change \"kind\".");
            }
            reader.Object(token, path, handlers);
            return c;
        }

        static double[] Numbers(DatasetSettingsJson.Reader reader, JToken v, string path, int count, string expected)
        {
            if (v.Type != JTokenType.Array || (count >= 0 && ((JArray)v).Count != count))
                throw reader.Error(v, path, "must be " + expected + ", not " + DatasetSettingsJson.Describe(v) + ".");
            var values = new double[((JArray)v).Count];
            for (var i = 0; i < values.Length; i++) values[i] = reader.Double(v[i], path + "[" + i + "]");
            return values;
        }
    }
}
