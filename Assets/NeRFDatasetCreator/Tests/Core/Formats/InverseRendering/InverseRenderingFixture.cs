using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A dataset with the issue-38 files written exactly as contract38.md settles them, on top of a real analytic capture
    /// (<see cref="AnalyticDataset"/>: poses, images, normals, linear HDR colour, points3d.ply): per view
    /// <c>r_&lt;i&gt;_albedo.exr/.png</c>, <c>_metallic</c>, <c>_roughness</c> and <c>r_&lt;i&gt;_light_&lt;key&gt;.png</c>, the
    /// frame keys naming them, and <c>lights/lights.json</c> with <c>lights/sunset.exr</c>. The material values are
    /// known in closed form, so the tests' expectations never come from the exporters: base colour at pixel (x, y) =
    /// ((x + 0.5)/W, (y + 0.5)/H, 0.5) linear, metallic <see cref="Metallic"/>, roughness <see cref="Roughness"/>;
    /// the relit view under key j is the colour image's RGB codes + 37·(j + 1) mod 256 with its alpha.
    /// </summary>
    static class InverseRenderingFixture
    {
        public const double Metallic = 0.25, Roughness = 0.6;
        public const int MapWidth = 16, MapHeight = 8;

        /// <summary>The relit keys, in the order their code offsets are counted: sunset at 0° and 90°, one point light.</summary>
        public static readonly string[] Keys = { "sunset_000", "sunset_090", "olat-00" };

        public static double[] Base(int x, int y, int width, int height) => new[] { (x + 0.5) / width, (y + 0.5) / height, 0.5 };

        /// <summary>The environment map's linear RGB at column x, row y (top row first).</summary>
        public static float[] Map(int x, int y) => new[] { 0.25f * x, 0.5f * y, 1f + x + 100 * y };

        public static byte RelitCode(byte code, int keyIndex) => (byte)((code + 37 * (keyIndex + 1)) % 256);

        /// <summary>Writes the dataset into <paramref name="project"/>/NeRFDatasets/<paramref name="name"/> and returns its folder.</summary>
        public static string Write(string project, string name, int width = 32, int height = 32, bool materials = true, bool relighting = true, bool hdr = true, int test = 2)
        {
            var root = AnalyticDataset.Write(project, name, new AnalyticDataset.Options
            {
                Width = width, Height = height, Train = 2, Val = 1, Test = test, PointCloud = 200,
                Configure = s => { s.Hdr.On = hdr; },
            });
            foreach (var split in DatasetSplits.Names)
            {
                var path = Path.Combine(root, DatasetLayout.TransformsFileName(split));
                var json = JObject.Parse(File.ReadAllText(path));
                foreach (JObject frame in (JArray)json["frames"])
                {
                    var stem = ((string)frame["file_path"]).Replace("./", "");
                    var image = PngReader.Read(Path.Combine(root, stem + ".png"));
                    if (materials) WriteMaterials(root, stem, image, frame);
                    if (relighting) WriteRelit(root, stem, image, frame);
                }
                File.WriteAllText(path, json.ToString());
            }
            if (relighting) WriteLights(root);
            return root;
        }

        static void WriteMaterials(string root, string stem, PngImage image, JObject frame)
        {
            int w = image.Width, h = image.Height, n = w * h;
            var albedo = new float[n * 4];
            var metallic = new float[n * 4];
            var roughness = new float[n * 4];
            byte[] albedoPng = new byte[n * 4], metallicPng = new byte[n * 4], roughnessPng = new byte[n * 4];
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    var i = y * w + x;
                    var a = image.Samples[4 * i + 3];
                    if (a == 0) continue;
                    var b = Base(x, y, w, h);
                    for (var c = 0; c < 3; c++)
                    {
                        albedo[4 * i + c] = (float)b[c];
                        metallic[4 * i + c] = (float)Metallic;
                        roughness[4 * i + c] = (float)Roughness;
                        albedoPng[4 * i + c] = Srgb.EncodeByteExact(b[c]);
                        metallicPng[4 * i + c] = (byte)Math.Round(Metallic * 255, MidpointRounding.AwayFromZero);
                        roughnessPng[4 * i + c] = (byte)Math.Round(Roughness * 255, MidpointRounding.AwayFromZero);
                    }
                    albedo[4 * i + 3] = metallic[4 * i + 3] = roughness[4 * i + 3] = a / 255f;
                    albedoPng[4 * i + 3] = metallicPng[4 * i + 3] = roughnessPng[4 * i + 3] = a;
                }
            foreach (var (pass, key, exr, png) in new[] { ("albedo", MaterialKeys.AlbedoPath, albedo, albedoPng), ("metallic", MaterialKeys.MetallicPath, metallic, metallicPng), ("roughness", MaterialKeys.RoughnessPath, roughness, roughnessPng) })
            {
                File.WriteAllBytes(Path.Combine(root, stem + "_" + pass + ".exr"), InverseRenderingImages.EncodeExrTopDown(exr, w, h));
                File.WriteAllBytes(Path.Combine(root, stem + "_" + pass + ".png"), PngWriter.Encode(png, w, h, PngPixelFormat.Rgba8));
                frame[key] = "./" + stem + "_" + pass + ".png";
            }
        }

        static void WriteRelit(string root, string stem, PngImage image, JObject frame)
        {
            var paths = new JObject();
            for (var k = 0; k < Keys.Length; k++)
            {
                var rgba = (byte[])image.Samples.Clone();
                for (var i = 0; i < rgba.Length; i += 4)
                    if (rgba[i + 3] != 0)
                        for (var c = 0; c < 3; c++) rgba[i + c] = RelitCode(rgba[i + c], k);
                var file = stem + "_light_" + Keys[k] + ".png";
                File.WriteAllBytes(Path.Combine(root, file), PngWriter.Encode(rgba, image.Width, image.Height, PngPixelFormat.Rgba8));
                paths[Keys[k]] = "./" + file;
            }
            frame[RelightingKeys.RelitPaths] = paths;
        }

        static void WriteLights(string root)
        {
            Directory.CreateDirectory(Path.Combine(root, "lights"));
            var map = new float[MapWidth * MapHeight * 4];
            for (var y = 0; y < MapHeight; y++)
                for (var x = 0; x < MapWidth; x++)
                {
                    var v = Map(x, y);
                    for (var c = 0; c < 3; c++) map[(y * MapWidth + x) * 4 + c] = v[c];
                    map[(y * MapWidth + x) * 4 + 3] = 1;
                }
            File.WriteAllBytes(Path.Combine(root, "lights", "sunset.exr"), InverseRenderingImages.EncodeExrTopDown(map, MapWidth, MapHeight));
            var lights = new JObject
            {
                ["format"] = "nerf-dataset-lights",
                ["version"] = 1,
                ["conditions"] = new JArray
                {
                    new JObject { ["name"] = "sunset", ["kind"] = "environment", ["keys"] = new JArray("sunset_000", "sunset_090"), ["file"] = "lights/sunset.exr", ["rotations"] = new JArray(0, 90), ["intensity"] = 1 },
                    new JObject { ["name"] = "olat-00", ["kind"] = "point", ["keys"] = new JArray("olat-00"), ["position"] = new JArray(0.0, -3.0, 3.0), ["intensity"] = 20 },
                },
            };
            File.WriteAllText(Path.Combine(root, RelightingKeys.LightsFile), lights.ToString());
        }

        /// <summary>The test views' frames of a split as the dataset lists them: (stem without split folder, transform_matrix).</summary>
        public static List<(string stem, double[][] pose)> Frames(string root, string split)
        {
            var json = JObject.Parse(File.ReadAllText(Path.Combine(root, DatasetLayout.TransformsFileName(split))));
            return ((JArray)json["frames"]).Select(f => (Path.GetFileName((string)f["file_path"]), f["transform_matrix"].ToObject<double[][]>())).ToList();
        }
    }
}
