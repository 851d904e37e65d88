using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The reading code of the inverse-rendering loaders, re-implemented line for line (the commits and lines are in
    /// Documentation~/maintainers/layouts-inverse-rendering.md): what each loader would hold in memory after reading an
    /// export. Images are float arrays, top row first, as torchvision's ToTensor / numpy give them.
    /// </summary>
    static class InverseRenderingLoaders
    {
        /// <summary>TensoIR tensoIR_rotation_setting.py:42–44: the entries of the root whose stem starts with the split, sorted as text.</summary>
        public static List<string> TensoIRSplitList(string root, string split) =>
            Directory.EnumerateFileSystemEntries(root).Where(p => Path.GetFileNameWithoutExtension(p).StartsWith(split, StringComparison.Ordinal))
                .OrderBy(p => p, StringComparer.Ordinal).ToList();

        public sealed class TensoIRItem
        {
            public int Width, Height;
            public double Focal;
            public double[,] CamTrans = new double[4, 4];
            public List<double[]> Rgbs = new List<double[]>(); // per rotation, [H*W*3] blended over white
            public bool[] Mask;
            public double[] Albedo; // [H*W*3] blended over white
            public double[] Normals; // [H*W*3] unit
        }

        /// <summary>TensoIR tensoIR_rotation_setting.py:162–248 (__getitem__ of a test item, downsample 1).</summary>
        public static TensoIRItem TensoIRGetItem(string itemPath, string lightName, IEnumerable<string> rotations)
        {
            var meta = JObject.Parse(File.ReadAllText(Path.Combine(itemPath, "metadata.json")));              // :165–167
            var item = new TensoIRItem { Width = (int)meta["imw"], Height = (int)meta["imh"] };               // :168
            item.Focal = 0.5 * (int)meta["imw"] / Math.Tan(0.5 * (double)meta["cam_angle_x"]);                 // :171
            var values = ((string)meta["cam_transform_mat"]).Split(',').Select(s => double.Parse(s, CultureInfo.InvariantCulture)).ToArray(); // :176
            Assert.That(values.Length, Is.EqualTo(16));
            for (var i = 0; i < 16; i++) item.CamTrans[i / 4, i % 4] = values[i];
            float[] last = null;
            foreach (var rotation in rotations)                                                                  // :184–198
            {
                last = ToTensor(Path.Combine(itemPath, "rgba_" + lightName + "_" + rotation + ".png"), 4);
                item.Rgbs.Add(OverWhite(last));                                                                  // :194
            }
            item.Mask = Enumerable.Range(0, last.Length / 4).Select(i => last[4 * i + 3] != 0).ToArray();       // :203
            item.Albedo = OverWhite(ToTensor(Path.Combine(itemPath, "albedo.png"), 4));                         // :206–213
            item.Normals = NormalFromPng(Path.Combine(itemPath, "normal.png"));                                 // :220–234
            return item;
        }

        /// <summary>TensoIR :220–234 and GS-IR normal_eval.py:39–45: (c/255 − 0.5)·2, blended with (0, 0, 1) by alpha, normalised.</summary>
        public static double[] NormalFromPng(string path)
        {
            var png = PngReader.Read(path);
            Assert.That(png.Channels, Is.EqualTo(4), path + " has alpha");
            var n = png.Width * png.Height;
            var normals = new double[n * 3];
            for (var i = 0; i < n; i++)
            {
                var a = png.Samples[4 * i + 3] / 255.0;
                var v = new double[3];
                for (var c = 0; c < 3; c++) v[c] = (png.Samples[4 * i + c] / 255.0 - 0.5) * 2.0 * a + (c == 2 ? 1.0 : 0.0) * (1.0 - a);
                var norm = Math.Sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                for (var c = 0; c < 3; c++) normals[3 * i + c] = v[c] / norm;
            }
            return normals;
        }

        /// <summary>torchvision ToTensor of a PIL image: codes / 255, channel-last here; asserts the channel count the caller views it as (.view(4, -1)).</summary>
        public static float[] ToTensor(string path, int channels)
        {
            Assert.That(File.Exists(path), Is.True, path);
            var png = PngReader.Read(path);
            Assert.That(png.Channels, Is.EqualTo(channels), path);
            return png.Samples.Select(s => s / 255f).ToArray();
        }

        /// <summary>rgb·a + (1 − a) per pixel of an RGBA tensor (TensoIR :194, :213).</summary>
        public static double[] OverWhite(float[] rgba)
        {
            var n = rgba.Length / 4;
            var rgb = new double[n * 3];
            for (var i = 0; i < n; i++)
                for (var c = 0; c < 3; c++) rgb[3 * i + c] = rgba[4 * i + c] * rgba[4 * i + 3] + (1 - rgba[4 * i + 3]);
            return rgb;
        }

        /// <summary>NeRFactor nerf.py:63–89 (_glob): the metadata.json of every '&lt;mode&gt;_???' folder with its rgba.png, sorted.</summary>
        public static List<string> NerfactorGlob(string root, string mode)
        {
            var modeStr = mode == "train" || mode == "test" ? mode : "val";                                     // :65–68
            return Directory.EnumerateDirectories(root)
                .Where(d => { var n = Path.GetFileName(d); return n.Length == modeStr.Length + 4 && n.StartsWith(modeStr + "_", StringComparison.Ordinal); }) // '%s_???' :69
                .Select(d => Path.Combine(d, "metadata.json")).Where(File.Exists)
                .Where(m => File.Exists(Path.Combine(Path.GetDirectoryName(m), "rgba.png")))                   // :80–83
                .OrderBy(p => p, StringComparer.Ordinal).ToList();
        }

        /// <summary>PIL's convert("L") of RGB (ITU-R 601-2 luma, fixed point: (R·19595 + G·38470 + B·7471 + 0x8000) >> 16), as imageio's mode='L' reads it.</summary>
        public static int Luma(byte r, byte g, byte b) => (r * 19595 + g * 38470 + b * 7471 + 0x8000) >> 16;

        /// <summary>A Radiance .hdr as cv2 / Radiance's freadcolrs read it (flat or "new" run-length scan lines), linear RGB top row first.</summary>
        public static float[] ReadHdr(string path, out int width, out int height)
        {
            var bytes = File.ReadAllBytes(path);
            var at = 0;
            string Line()
            {
                var start = at;
                while (bytes[at] != (byte)'\n') at++;
                return Encoding.ASCII.GetString(bytes, start, at++ - start);
            }
            Assert.That(Line(), Is.EqualTo("#?RADIANCE"));
            var format = false;
            for (var line = Line(); line.Length > 0; line = Line()) format |= line == "FORMAT=32-bit_rle_rgbe";
            Assert.That(format, Is.True, "FORMAT line");
            var size = Line().Split(' ');
            Assert.That(size[0] == "-Y" && size[2] == "+X", Is.True, "top-down, left-right");
            height = int.Parse(size[1], CultureInfo.InvariantCulture);
            width = int.Parse(size[3], CultureInfo.InvariantCulture);
            var rgb = new float[width * height * 3];
            var row = new byte[width * 4];
            for (var y = 0; y < height; y++)
            {
                if (width >= 8 && width <= 32767 && bytes[at] == 2 && bytes[at + 1] == 2 && (bytes[at + 2] & 0x80) == 0)
                {
                    Assert.That((bytes[at + 2] << 8) | bytes[at + 3], Is.EqualTo(width));
                    at += 4;
                    for (var c = 0; c < 4; c++)
                        for (var x = 0; x < width;)
                        {
                            int count = bytes[at++];
                            if (count > 128) { count -= 128; var value = bytes[at++]; for (var k = 0; k < count; k++) row[4 * (x++) + c] = value; }
                            else for (var k = 0; k < count; k++) row[4 * (x++) + c] = bytes[at++];
                        }
                }
                else
                {
                    Array.Copy(bytes, at, row, 0, row.Length);
                    at += row.Length;
                }
                for (var x = 0; x < width; x++)
                {
                    // Radiance color.c colr_color: 0 when e = 0, else (m + 0.5)·2^(e − 136).
                    var e = row[4 * x + 3];
                    for (var c = 0; c < 3; c++) rgb[(y * width + x) * 3 + c] = e == 0 ? 0f : (float)((row[4 * x + c] + 0.5) * Math.Pow(2, e - 136));
                }
            }
            Assert.That(at, Is.EqualTo(bytes.Length), "nothing after the last scan line");
            return rgb;
        }
    }
}
