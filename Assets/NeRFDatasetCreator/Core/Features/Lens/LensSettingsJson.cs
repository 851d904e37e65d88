using System;
using System.Collections.Generic;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>"lens"</c> object of a settings file: <c>{ "model": "opencv", "k1": -0.1, "k2": 0.01, "p1": 0, "p2": 0,
    /// "k3": 0 }</c> or <c>{ "model": "opencv_fisheye", "k1": …, "k4": … }</c> (Documentation~/lens-distortion.md).
    /// Written only with a lens, and only the model's own coefficients (plus any other non-zero one, so validation
    /// still sees it after a round trip).
    /// </summary>
    public static class LensSettingsJson
    {
        /// <summary>The <c>"lens"</c> section with a lens; nothing for a pinhole capture, whose configs keep their keys.</summary>
        public static void Write(JsonWriter w, LensSettings lens)
        {
            if (lens != null && lens.Enabled) WriteObject(w, lens);
        }

        public static void WriteObject(JsonWriter w, LensSettings lens)
        {
            w.WritePropertyName(LensSettings.Key);
            w.WriteStartObject();
            w.WritePropertyName("model"); w.WriteValue(lens.Model ?? LensSettings.ModelNames.None);
            var fisheye = LensSettings.ModelNames.TryParse(lens.Model, out var model) && model == LensModel.OpenCvFisheye;
            Coefficient(w, "k1", lens.K1, true);
            Coefficient(w, "k2", lens.K2, true);
            Coefficient(w, "p1", lens.P1, !fisheye);
            Coefficient(w, "p2", lens.P2, !fisheye);
            Coefficient(w, "k3", lens.K3, true);
            Coefficient(w, "k4", lens.K4, fisheye);
            w.WriteEndObject();
        }

        // The model's own coefficients always; another only when non-zero, so validation still sees it after a round trip.
        static void Coefficient(JsonWriter w, string name, double value, bool always)
        {
            if (always || value != 0) JsonNumbers.SettingNumber(w, name, value);
        }

        internal static void Read(DatasetSettingsJson.Reader reader, JToken token, string path, LensSettings lens)
        {
            // "model" says none (off) or which lens; "enabled": false makes the capture pinhole whatever the model.
            var enabled = reader.Feature(token, path, new Dictionary<string, Action<JToken, string>>
            {
                ["model"] = (v, p) =>
                {
                    var name = reader.String(v, p);
                    if (!LensSettings.ModelNames.IsKnown(name))
                        throw reader.Error(v, p, "must be one of " + LensSettings.ModelNames.List + ", not \"" + name + "\"." +
                            SpellingSuggestion.Sentence(name, new[] { LensSettings.ModelNames.None, LensSettings.ModelNames.OpenCv, LensSettings.ModelNames.Fisheye }));
                    lens.Model = name.Trim().ToLowerInvariant();
                },
                ["k1"] = (v, p) => lens.K1 = reader.Double(v, p),
                ["k2"] = (v, p) => lens.K2 = reader.Double(v, p),
                ["k3"] = (v, p) => lens.K3 = reader.Double(v, p),
                ["k4"] = (v, p) => lens.K4 = reader.Double(v, p),
                ["p1"] = (v, p) => lens.P1 = reader.Double(v, p),
                ["p2"] = (v, p) => lens.P2 = reader.Double(v, p),
            });
            reader.Switch(token, path, enabled, lens.Enabled, () => lens.Model = LensSettings.ModelNames.None,
                "\"model\" is \"none\" (or missing); give \"model\": \"opencv\" or \"opencv_fisheye\"");
        }
    }
}
