using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>conversions</c> of a lights.json condition: for TensoIR, NeRFactor, R3DG and Stanford-ORB, the file names,
    /// the lines to paste into the trainer's config and how its map convention relates to ours — each cited to the
    /// loader's code (<c>source</c>; details and lines in Documentation~/maintainers/relighting.md,
    /// <see cref="LightConventions"/> holds the conventions as code).
    /// </summary>
    public static class LightConversions
    {
        public const string TensoIrSource = "Haian-Jin/TensoIR@8f7b8dd models/relight_utils.py:193-205, models/tensorBase_rotated_lights.py:479-488,586, dataLoader/tensoIR_rotation_setting.py:82,120, opt.py:162-166";
        public const string NerfactorSource = "google/nerfactor@a668dca brdf/renderer.py:184-219, nerfactor/models/nerfactor.py:85-91, data_gen/nerf_synth/render.py:187-210";
        public const string R3dgSource = "NJU-3DV/Relightable3DGaussian@a102f14 scene/envmap.py:22-53, eval_relighting_syn4.py:61-70,129";
        public const string StanfordOrbSource = "StanfordORB/Stanford-ORB@8a3bdae orb/utils/env_map.py:12-26";

        public static void Write(JsonWriter w, LightingCondition c, EnvironmentMap map)
        {
            var keys = LightingKeys.Of(c);
            w.WriteStartObject();
            if (c.Kind == LightingKind.Environment)
            {
                var rotations = c.Rotations.Select(LightsFile.Degrees).ToList();
                w.WritePropertyName("tensoir");
                w.WriteStartObject();
                w.WritePropertyName("convention"); w.WriteValue("same as equirect (get_light: arccos(z), atan2(y, x)); light_rotation is our rotation");
                w.WritePropertyName("hdr_file"); w.WriteValue(c.Name + ".hdr");
                w.WritePropertyName("images"); w.WriteValue("rgba_" + c.Name + "_<rotation>.png");
                Strings(w, "config_lines", new[] { "light_name = " + c.Name, "light_rotation = [" + string.Join(", ", rotations) + "]" });
                JsonNumbers.Number(w, "scale", c.Intensity);
                w.WritePropertyName("source"); w.WriteValue(TensoIrSource);
                w.WriteEndObject();

                w.WritePropertyName("nerfactor");
                w.WriteStartObject();
                w.WritePropertyName("convention"); w.WriteValue("same as equirect (gen_light_xyz: lat = pi/2 at the top row, lng = pi at the left column); no rotation: one map per rotated light");
                Strings(w, "hdr_files", keys.Select(k => k + ".hdr"));
                Strings(w, "images", keys.Select(k => "rgba_" + k + ".png"));
                JsonNumbers.Number(w, "scale", c.Intensity);
                w.WritePropertyName("source"); w.WriteValue(NerfactorSource);
                w.WriteEndObject();

                w.WritePropertyName("r3dg");
                w.WriteStartObject();
                w.WritePropertyName("convention"); w.WriteValue("same as equirect (EnvLight.direct_light: arccos(z), atan2(y, x)); no rotation: one map per rotated light");
                Strings(w, "envmap_paths", keys.Select(k => "env_map/" + k + ".exr"));
                Strings(w, "images", keys.Select(k => "test_rli/" + k + "_r_<i>.png"));
                JsonNumbers.Number(w, "scale", c.Intensity);
                w.WritePropertyName("source"); w.WriteValue(R3dgSource);
                w.WriteEndObject();

                w.WritePropertyName("stanford_orb");
                w.WriteStartObject();
                w.WritePropertyName("convention");
                w.WriteValue("Y-up (x, y, z) = (x, z, -y) of ours; u = (atan2(x, -z) + pi) / (2 pi), v = acos(y) / pi: ORB column c is our column (c - roll_columns) mod W");
                w.WritePropertyName("roll_columns"); w.WriteValue(LightConventions.StanfordOrbRollColumns(map.Width));
                JsonNumbers.Number(w, "scale", c.Intensity);
                w.WritePropertyName("source"); w.WriteValue(StanfordOrbSource);
                w.WriteEndObject();
            }
            else
            {
                w.WritePropertyName("tensoir"); w.WriteNull();
                w.WritePropertyName("nerfactor");
                w.WriteStartObject();
                w.WritePropertyName("olat_file"); w.WriteValue(c.Name + ".json");
                w.WritePropertyName("olat_json");
                w.WriteStartObject();
                LightsFile.Triple(w, "point_location", c.Position);
                w.WriteEndObject();
                w.WritePropertyName("images"); w.WriteValue("rgba_" + c.Name + ".png");
                w.WritePropertyName("source"); w.WriteValue(NerfactorSource);
                w.WriteEndObject();
                w.WritePropertyName("r3dg"); w.WriteNull();
                w.WritePropertyName("stanford_orb"); w.WriteNull();
                w.WritePropertyName("why_null"); w.WriteValue("TensoIR, R3DG and Stanford-ORB relight with environment maps only; NeRFactor's OLAT .json takes point_location");
            }
            w.WriteEndObject();
        }

        static void Strings(JsonWriter w, string name, IEnumerable<string> values)
        {
            w.WritePropertyName(name);
            w.WriteStartArray();
            foreach (var v in values) w.WriteValue(v);
            w.WriteEndArray();
        }
    }
}
