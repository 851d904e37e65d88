using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>materials</c> record of dataset_config.json (contract of issue 38): the passes written, that the EXR is the
    /// truth, each PNG's encoding, what roughness and base colour mean, the render pipeline and the shaders read exactly
    /// and not. Written when the settings' materials are on.
    /// </summary>
    public static class MaterialRecord
    {
        public const string Key = "materials";

        /// <summary>The emission file's encoding (it has no PNG).</summary>
        public const string EmissionEncoding = "linear-float-exr";

        public const string Roughness = "perceptual (1 - smoothness)";
        public const string BaseColour = "base colour (not diffuse); diffuse = base * (1 - metallic)";

        public static void Write(JsonWriter w, DatasetSettings settings, MaterialCaptureFacts facts)
        {
            var m = settings?.Materials;
            if (m == null || !m.Enabled) return;
            w.WritePropertyName(Key);
            w.WriteStartObject();
            w.WritePropertyName("passes");
            w.WriteStartArray();
            foreach (var name in MaterialPassNames.On(m)) w.WriteValue(name);
            w.WriteEndArray();
            w.WritePropertyName("truth"); w.WriteValue("exr");
            w.WritePropertyName("encodings");
            w.WriteStartObject();
            foreach (var pass in MaterialPassFiles.All)
            {
                if (!MaterialPassNames.IsOn(m, pass.Name)) continue;
                if (pass.EncodingName != null)
                {
                    w.WritePropertyName(pass.Name + "_png");
                    w.WriteValue(pass.EncodingName);
                }
                else
                {
                    w.WritePropertyName(pass.Name);
                    w.WriteValue(EmissionEncoding);
                }
            }
            w.WriteEndObject();
            w.WritePropertyName("roughness"); w.WriteValue(Roughness);
            w.WritePropertyName("base_colour"); w.WriteValue(BaseColour);
            w.WritePropertyName("pipeline");
            if (facts?.Pipeline == null) w.WriteNull();
            else w.WriteValue(facts.Pipeline);
            w.WritePropertyName("supported_shaders");
            w.WriteStartArray();
            if (facts != null) foreach (var name in facts.SupportedShaders) w.WriteValue(name);
            w.WriteEndArray();
            w.WritePropertyName("unsupported_shaders");
            w.WriteStartArray();
            if (facts != null) foreach (var name in facts.UnsupportedShaders) w.WriteValue(name);
            w.WriteEndArray();
            w.WriteEndObject();
        }

        /// <summary>
        /// The PNG encoding a dataset records for <paramref name="pass"/> (<c>materials.encodings.&lt;pass&gt;_png</c>), or null
        /// when the config has no such record (then the reader assumes nothing).
        /// </summary>
        public static string PngEncoding(JObject config, string pass) =>
            (config?[Key]?["encodings"] as JObject)?[pass + "_png"] is JValue v && v.Type == JTokenType.String ? (string)v : null;
    }
}
