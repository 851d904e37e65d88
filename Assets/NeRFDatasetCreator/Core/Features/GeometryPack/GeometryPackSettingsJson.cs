using System;
using System.Collections.Generic;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The config-file form of the geometry pack's settings (<see cref="DatasetSettings.GeometryPack"/>, on by default,
    /// and <see cref="DatasetSettings.GeometryPackEveryStep"/>): <c>"geometryPack": true | false | "everyStep"</c>, or the
    /// section form every optional output accepts, <c>{ "enabled": true, "everyStep": true }</c>
    /// (Documentation~/settings.md). Written only when not the default (on, the start time's mesh), in the short form.
    /// </summary>
    public static class GeometryPackSettingsJson
    {
        public const string Key = "geometryPack";

        /// <summary>The key that asks for a mesh at every time step in the section form.</summary>
        public const string EveryStepKey = "everyStep";

        /// <summary>Nothing for the default; false when off; "everyStep" for a mesh at every time step.</summary>
        public static void Write(JsonWriter w, DatasetSettings s)
        {
            if (!s.GeometryPack)
            {
                w.WritePropertyName(Key);
                w.WriteValue(false);
            }
            else if (s.GeometryPackEveryStep)
            {
                w.WritePropertyName(Key);
                w.WriteValue(GeometryPackSteps.EveryStepValue);
            }
        }

        internal static void Read(DatasetSettingsJson.Reader reader, JToken t, string p, DatasetSettings s)
        {
            if (t.Type == JTokenType.Object)
            {
                // The section form: giving it turns the pack on (as for every feature), "enabled": false off.
                var everyStep = false;
                var enabled = reader.Feature(t, p, new Dictionary<string, Action<JToken, string>>
                {
                    [EveryStepKey] = (v, q) => everyStep = reader.Bool(v, q),
                });
                s.GeometryPack = enabled ?? true;
                s.GeometryPackEveryStep = everyStep;
                return;
            }
            // true (the start time's mesh), false (none) or "everyStep" (a dynamic capture's mesh at every step).
            if (t.Type == JTokenType.String && (string)t == GeometryPackSteps.EveryStepValue)
            {
                s.GeometryPack = true;
                s.GeometryPackEveryStep = true;
                return;
            }
            if (t.Type != JTokenType.Boolean)
                throw reader.Error(t, p, "must be true, false or \"" + GeometryPackSteps.EveryStepValue + "\" (a dynamic capture's mesh at every time step), not " + DatasetSettingsJson.Describe(t) + "." +
                    (t.Type == JTokenType.String ? SpellingSuggestion.Sentence((string)t, new[] { GeometryPackSteps.EveryStepValue }) : ""));
            s.GeometryPack = reader.Bool(t, p);
            s.GeometryPackEveryStep = false;
        }
    }
}
