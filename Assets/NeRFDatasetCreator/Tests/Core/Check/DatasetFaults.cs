using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Plants one capture bug in a copy of a rendered dataset, file by file, as a broken capture would have written it.</summary>
    static class DatasetFaults
    {
        public static string Copy(string source, string target)
        {
            foreach (var dir in Directory.GetDirectories(source, "*", SearchOption.AllDirectories))
                Directory.CreateDirectory(target + dir.Substring(source.Length));
            Directory.CreateDirectory(target);
            foreach (var file in Directory.GetFiles(source, "*", SearchOption.AllDirectories))
                File.Copy(file, target + file.Substring(source.Length));
            return target;
        }

        /// <summary>Rewrites every PNG whose name ends with <paramref name="suffix"/> (e.g. "_mask_0000.png", or ".png" for colour) through <paramref name="edit"/>.</summary>
        public static void EditImages(string folder, Func<string, bool> which, Action<PngImage, byte[], string> edit)
        {
            foreach (var file in Directory.GetFiles(folder, "*.png", SearchOption.AllDirectories).Where(which))
            {
                var png = PngReader.Read(file);
                var samples = (byte[])png.Samples.Clone();
                edit(png, samples, file);
                var format = png.BitDepth == 16 ? PngPixelFormat.Gray16 : png.Channels == 4 ? PngPixelFormat.Rgba8 : png.Channels == 3 ? PngPixelFormat.Rgb8 : PngPixelFormat.Gray8;
                File.WriteAllBytes(file, PngWriter.Encode(samples, png.Width, png.Height, format));
            }
        }

        public static bool IsColour(string file) => System.Text.RegularExpressions.Regex.IsMatch(Path.GetFileName(file), "^r_[0-9]+\\.png$");
        public static bool IsMask(string file) => file.EndsWith("_mask_0000.png", StringComparison.Ordinal);
        public static bool IsDepth(string file) => file.EndsWith("_depth_0000.png", StringComparison.Ordinal);
        public static bool IsNormal(string file) => file.EndsWith("_normal_0000.png", StringComparison.Ordinal);

        public static void FlipRows(PngImage png, byte[] samples)
        {
            var stride = samples.Length / png.Height;
            var row = new byte[stride];
            for (var y = 0; y < png.Height / 2; y++)
            {
                Buffer.BlockCopy(samples, y * stride, row, 0, stride);
                Buffer.BlockCopy(samples, (png.Height - 1 - y) * stride, samples, y * stride, stride);
                Buffer.BlockCopy(row, 0, samples, (png.Height - 1 - y) * stride, stride);
            }
        }

        /// <summary>Moves every pixel <paramref name="dx"/> to the right (the left column becomes transparent).</summary>
        public static void ShiftRight(PngImage png, byte[] samples, int dx)
        {
            var bpp = samples.Length / (png.Width * png.Height);
            var original = (byte[])samples.Clone();
            for (var y = 0; y < png.Height; y++)
                for (var x = 0; x < png.Width; x++)
                    for (var c = 0; c < bpp; c++)
                    {
                        var from = x - dx;
                        samples[(y * png.Width + x) * bpp + c] = from >= 0 && from < png.Width ? original[(y * png.Width + from) * bpp + c] : (byte)0;
                    }
        }

        /// <summary>Multiplies every 16-bit depth sample by <paramref name="factor"/> (e.g. centimetres where thousandths were meant).</summary>
        public static void ScaleDepth(byte[] samples, double factor)
        {
            for (var i = 0; i < samples.Length; i += 2)
            {
                var v = (samples[i] << 8) | samples[i + 1];
                var scaled = (int)Math.Min(65535, Math.Round(v * factor));
                if (v != 0 && scaled == 0) scaled = 1;
                samples[i] = (byte)(scaled >> 8);
                samples[i + 1] = (byte)scaled;
            }
        }

        /// <summary>Edits every transforms file's JSON.</summary>
        public static void EditTransforms(string folder, Action<JObject> edit)
        {
            foreach (var split in new[] { "train", "val", "test" })
            {
                var path = Path.Combine(folder, "transforms_" + split + ".json");
                var json = JObject.Parse(File.ReadAllText(path));
                edit(json);
                File.WriteAllText(path, json.ToString());
            }
        }

        /// <summary>Replaces every frame's transform_matrix M by <paramref name="change"/>(M).</summary>
        public static void EditPoses(string folder, Func<Matrix4x4d, Matrix4x4d> change) => EditTransforms(folder, json =>
        {
            foreach (JObject frame in json["frames"])
            {
                var m = Matrix4x4d.FromRows(frame["transform_matrix"].ToObject<double[][]>());
                frame["transform_matrix"] = JArray.FromObject(change(m).ToRows());
            }
        });

        /// <summary>The camera-to-world matrix of the frame whose normal file is <paramref name="normalFile"/>.</summary>
        public static Matrix4x4d PoseOf(string folder, string normalFile)
        {
            var split = Path.GetFileName(Path.GetDirectoryName(normalFile));
            var stem = "./" + split + "/" + Path.GetFileName(normalFile).Replace("_normal_0000.png", "");
            var json = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_" + split + ".json")));
            var frame = json["frames"].Single(f => (string)f["file_path"] == stem);
            return Matrix4x4d.FromRows(frame["transform_matrix"].ToObject<double[][]>());
        }
    }
}
