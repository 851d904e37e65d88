using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The dataset's lighting conditions as the exports need them, read from <c>lights/lights.json</c>
    /// (<see cref="RelightingKeys.LightsFile"/>, contract38): each condition's name, kind, file keys, rotations, its
    /// environment map (<c>lights/&lt;name&gt;.exr</c>, equirect in the output world, Blender's convention
    /// u = 0.5 − atan2(y, x)/2π, top row +Z, unrotated) and a point light's position.
    /// </summary>
    public sealed class InverseRenderingLight
    {
        public string Name, Kind;
        public List<string> Keys = new List<string>();
        public List<int> Rotations = new List<int>();

        /// <summary>The environment's equirect EXR (full path), or null for a point / spot light.</summary>
        public string Map;

        public double[] Position;

        public bool IsEnvironment => Kind == "environment";

        /// <summary>A rotation's file key: <c>&lt;name&gt;_&lt;rot:000&gt;</c> (contract38).</summary>
        public string Key(int rotation) => Name + "_" + rotation.ToString("000", CultureInfo.InvariantCulture);

        /// <summary>The conditions of <c>lights/lights.json</c>, or an empty list when the dataset has none.</summary>
        public static List<InverseRenderingLight> Read(string root)
        {
            var path = Path.Combine(root, RelightingKeys.LightsFile);
            var lights = new List<InverseRenderingLight>();
            if (!File.Exists(path)) return lights;
            JObject json;
            try { json = JObject.Parse(File.ReadAllText(path)); }
            catch (Newtonsoft.Json.JsonException e)
            {
                throw new InvalidParameterException(new[] { new ValidationProblem(RelightingKeys.LightsFile, path, "is not JSON (" + e.Message + ").", "Re-capture the relighting set.") });
            }
            if (!(json["conditions"] is JArray conditions)) return lights;
            foreach (var token in conditions.OfType<JObject>())
            {
                var light = new InverseRenderingLight { Name = (string)token["name"] ?? "", Kind = ((string)token["kind"] ?? "").ToLowerInvariant() };
                if (token["keys"] is JArray keys) light.Keys.AddRange(keys.Select(k => (string)k));
                if (token["rotations"] is JArray rotations) light.Rotations.AddRange(rotations.Select(r => (int)Math.Round((double)r)));
                if (light.IsEnvironment && light.Rotations.Count == 0) light.Rotations.Add(0);
                if (light.Keys.Count == 0) light.Keys.AddRange(light.IsEnvironment ? light.Rotations.Select(light.Key) : new[] { light.Name });
                var file = (string)token["file"];
                if (light.IsEnvironment && !string.IsNullOrEmpty(file))
                {
                    var resolved = DatasetFile.Resolve(root, RelightingKeys.LightsFile + ": file", file, false);
                    light.Map = resolved.FullPath;
                }
                if (token["position"] is JArray position && position.Count == 3) light.Position = position.Select(p => (double)p).ToArray();
                lights.Add(light);
            }
            return lights;
        }

        /// <summary>
        /// An equirect map rotated by <paramref name="degrees"/> counter-clockwise about +Z seen from above: light that
        /// arrived from d arrives from Rz(θ)·d. With u = 0.5 − φ/2π, φ → φ + θ moves every column by −θ/360 of the width,
        /// so output column x samples the input at x + θ·W/360 (linear between the two nearest columns, wrapping in u).
        /// Returns RGB floats, top row first.
        /// </summary>
        public static float[] Rotate(ExrImage map, double degrees)
        {
            int w = map.Width, h = map.Height;
            float[][] channels = { map.Channel("R"), map.Channel("G"), map.Channel("B") };
            var rotated = new float[w * h * 3];
            var shift = degrees / 360.0 * w;
            for (var x = 0; x < w; x++)
            {
                var source = x + shift;
                var x0 = (int)Math.Floor(source);
                var t = source - x0;
                int a = ((x0 % w) + w) % w, b = (a + 1) % w;
                for (var y = 0; y < h; y++)
                    for (var c = 0; c < 3; c++)
                        rotated[(y * w + x) * 3 + c] = (float)((1 - t) * channels[c][y * w + a] + t * channels[c][y * w + b]);
            }
            return rotated;
        }

        /// <summary>An environment map's RGB floats, top row first (unrotated).</summary>
        public static float[] Rgb(ExrImage map)
        {
            float[] r = map.Channel("R"), g = map.Channel("G"), b = map.Channel("B");
            var rgb = new float[map.Width * map.Height * 3];
            for (var i = 0; i < map.Width * map.Height; i++)
            {
                rgb[3 * i] = r[i];
                rgb[3 * i + 1] = g[i];
                rgb[3 * i + 2] = b[i];
            }
            return rgb;
        }

        /// <summary>An environment's EXR, refused with the reason when missing or without RGB.</summary>
        public ExrImage ReadMap()
        {
            if (Map == null || !File.Exists(Map))
                throw new InvalidParameterException(new[] { new ValidationProblem(RelightingKeys.LightsFile + ": " + Name + ".file", Map ?? "(none)", "is missing: the exports write each environment as the .hdr / .exr their trainers read.", "Re-capture the relighting set (lights/<name>.exr is written with it).") });
            var exr = ExrReader.Read(Map);
            if (exr.Channel("R") == null || exr.Channel("G") == null || exr.Channel("B") == null)
                throw new InvalidParameterException(new[] { new ValidationProblem(RelightingKeys.LightsFile + ": " + Name + ".file", Map, "has no R, G, B channels.", "Re-capture the relighting set.") });
            return exr;
        }
    }
}
