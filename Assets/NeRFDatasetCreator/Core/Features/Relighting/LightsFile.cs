using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using Newtonsoft.Json;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes <c>lights/lights.json</c> and <c>lights/&lt;name&gt;.exr</c> per environment (contract of issue 38;
    /// Documentation~/relighting.md): the conventions (<see cref="Equirect"/>), each condition with its keys, and the
    /// ready values per trainer (<see cref="LightConversions"/>). The environment EXRs are float32 RGB equirects of the
    /// output frame, unrotated and unscaled (intensity is recorded beside them).
    /// </summary>
    public static class LightsFile
    {
        public const string Format = "nerf-dataset-lights";
        public const int Version = 1;

        /// <summary><c>lights/sunset.exr</c>.</summary>
        public static string EnvironmentFile(string name) => RelightingKeys.LightsFolder + "/" + name + ".exr";

        /// <summary>
        /// Writes the folder when <paramref name="settings"/> relight the views; <paramref name="environments"/> holds
        /// each environment condition's map by name (<see cref="UnitySkybox.FromPanoramic"/>, <see cref="UnitySkybox.FromCubemap"/>, or an analytic one).
        /// </summary>
        public static void Write(DatasetWriteSession session, DatasetSettings settings, IReadOnlyDictionary<string, EnvironmentMap> environments)
        {
            var relighting = settings?.Relighting;
            if (relighting == null || !relighting.Enabled) return;
            foreach (var c in relighting.Conditions)
                if (c.Kind == LightingKind.Environment && (environments == null || !environments.ContainsKey(c.Name)))
                    throw new InvalidOperationException("Relighting condition \"" + c.Name + "\" is an environment, but no map was given for it: pass its equirect (EnvironmentMap) to write lights/.");
            Directory.CreateDirectory(session.PathOf(RelightingKeys.LightsFolder));
            foreach (var c in relighting.Conditions)
            {
                if (c.Kind != LightingKind.Environment) continue;
                var map = environments[c.Name];
                File.WriteAllBytes(session.PathOf(EnvironmentFile(c.Name)), ExrWriter.Encode(map.ToRgbBottomUp(), map.Width, map.Height, 3));
            }
            session.WriteText(RelightingKeys.LightsFile, Text(settings, environments));
        }

        /// <summary>The lights.json text (indented, ending in a newline).</summary>
        public static string Text(DatasetSettings settings, IReadOnlyDictionary<string, EnvironmentMap> environments)
        {
            using (var text = JsonNumbers.CreateText())
            {
                using (var w = JsonNumbers.CreateWriter(text))
                {
                    w.WriteStartObject();
                    w.WritePropertyName("format"); w.WriteValue(Format);
                    w.WritePropertyName("version"); w.WriteValue(Version);
                    w.WritePropertyName("frame"); w.WriteValue("output world (Blender, right-handed, +Z up), as transform_matrix");
                    w.WritePropertyName("equirect");
                    w.WriteStartObject();
                    w.WritePropertyName("u"); w.WriteValue("0.5 - atan2(y, x) / (2 pi)");
                    w.WritePropertyName("v"); w.WriteValue("acos(z) / pi");
                    w.WritePropertyName("top_row"); w.WriteValue("+Z");
                    w.WritePropertyName("u_wraps"); w.WriteValue(true);
                    w.WritePropertyName("meaning");
                    w.WriteValue("d = (x, y, z) is a unit direction FROM the surface TOWARDS the light, output world; (u, v) in [0, 1); column = u * W from the left, row = v * H from the top");
                    w.WriteEndObject();
                    w.WritePropertyName("rotation");
                    w.WriteValue("counter-clockwise about +Z seen from above, degrees; a rotation by theta maps the light arriving from d to arriving from Rz(theta) * d");
                    w.WritePropertyName("conditions");
                    w.WriteStartArray();
                    foreach (var c in settings.Relighting.Conditions) Condition(w, c, environments);
                    w.WriteEndArray();
                    w.WriteEndObject();
                }
                return text.ToString() + "\n";
            }
        }

        static void Condition(JsonWriter w, LightingCondition c, IReadOnlyDictionary<string, EnvironmentMap> environments)
        {
            w.WriteStartObject();
            w.WritePropertyName("name"); w.WriteValue(c.Name);
            w.WritePropertyName("kind"); w.WriteValue(LightingKinds.Name(c.Kind));
            w.WritePropertyName("keys");
            w.WriteStartArray();
            foreach (var key in LightingKeys.Of(c)) w.WriteValue(key);
            w.WriteEndArray();
            JsonNumbers.Number(w, "intensity", c.Intensity);
            if (c.Kind == LightingKind.Environment)
            {
                var map = environments[c.Name];
                w.WritePropertyName("file"); w.WriteValue(EnvironmentFile(c.Name));
                w.WritePropertyName("source"); w.WriteValue(c.File ?? "");
                w.WritePropertyName("width"); w.WriteValue(map.Width);
                w.WritePropertyName("height"); w.WriteValue(map.Height);
                w.WritePropertyName("rotations");
                w.WriteStartArray();
                foreach (var r in c.Rotations) w.WriteValue((int)r);
                w.WriteEndArray();
            }
            else
            {
                Triple(w, "position", c.Position);
                if (c.Kind == LightingKind.Spot)
                {
                    Triple(w, "direction", LightGeometry.SpotDirection(c));
                    JsonNumbers.Number(w, "spot_angle", c.SpotAngle);
                }
                Triple(w, "colour", c.Colour);
                w.WritePropertyName("shadows"); w.WriteValue(c.Shadows);
            }
            w.WritePropertyName("conversions");
            LightConversions.Write(w, c, c.Kind == LightingKind.Environment ? environments[c.Name] : null);
            w.WriteEndObject();
        }

        internal static void Triple(JsonWriter w, string name, double[] v)
        {
            w.WritePropertyName(name);
            w.WriteStartArray();
            foreach (var x in v) JsonNumbers.Write(w, x);
            w.WriteEndArray();
        }

        internal static string Degrees(double rotation) => ((int)rotation).ToString("000", CultureInfo.InvariantCulture);
    }
}
