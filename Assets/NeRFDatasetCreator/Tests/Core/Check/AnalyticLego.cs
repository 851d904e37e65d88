using System.IO;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A nerf_synthetic-style lego folder that a check can pass: the real lego cameras (transforms_train.json: poses and
    /// camera_angle_x only, no depth, normals or masks) with straight-alpha RGBA images of <see cref="AnalyticScene"/>
    /// rendered at its poses through NeRF's ray formula (coverage of 2×2 samples, the first surface's colour). Each
    /// split named gets the same poses, its file paths moved to <c>./&lt;split&gt;/</c>.
    /// </summary>
    static class AnalyticLego
    {
        public static void Write(string folder, int size = 64, params string[] splits)
        {
            if (splits.Length == 0) splits = new[] { "train" };
            var text = File.ReadAllText(Fixtures.LegoTrainPath);
            var json = JObject.Parse(text);
            var angle = (double)json["camera_angle_x"];
            var scene = AnalyticScene.Layout(SceneNormalisation.Identity, Vector3d.Zero);
            var images = new System.Collections.Generic.List<byte[]>();
            foreach (JObject frame in json["frames"])
                images.Add(PngWriter.Encode(Render(scene, frame["transform_matrix"].ToObject<double[][]>(), angle, size, size), size, size, PngPixelFormat.Rgba8));
            foreach (var split in splits)
            {
                Directory.CreateDirectory(Path.Combine(folder, split));
                File.WriteAllText(Path.Combine(folder, "transforms_" + split + ".json"), text.Replace("\"./train/", "\"./" + split + "/"));
                var i = 0;
                foreach (JObject frame in json["frames"])
                    File.WriteAllBytes(Path.Combine(folder, split, Path.GetFileName((string)frame["file_path"]) + ".png"), images[i++]);
            }
        }

        static byte[] Render(AnalyticScene scene, double[][] c2w, double angle, int w, int h)
        {
            var rgba = new byte[w * h * 4];
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    int covered = 0;
                    double[] colour = null;
                    for (var s = 0; s < 4; s++)
                    {
                        NerfRays.Ray(c2w, angle, w, h, x + 0.25 + 0.5 * (s & 1), y + 0.25 + 0.5 * (s >> 1), out var o, out var d);
                        if (!scene.Trace(new Vector3d(o[0], o[1], o[2]), new Vector3d(d[0], d[1], d[2]), 0, out _, out _, out var c, out _)) continue;
                        covered++;
                        colour = c;
                    }
                    if (covered == 0) continue;
                    var p = (y * w + x) * 4;
                    for (var c = 0; c < 3; c++) rgba[p + c] = (byte)(255 * colour[c]);
                    rgba[p + 3] = (byte)(covered * 255 / 4);
                }
            return rgba;
        }
    }
}
