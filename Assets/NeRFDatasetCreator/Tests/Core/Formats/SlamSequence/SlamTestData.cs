using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// What the SLAM layout tests share: a monocular dynamic analytic capture (one moving camera, one train view per
    /// time step, depth on), and the expectations derived by hand from its transforms — the OpenCV camera-to-world is
    /// our OpenGL c2w with its y and z columns negated (x right, y down, looking along +z).
    /// </summary>
    static class SlamTestData
    {
        public static string Monocular(string root, string name, int steps = 5, int width = 40, int height = 30, Action<DatasetSettings> configure = null) =>
            AnalyticDataset.Write(root, name, new AnalyticDataset.Options
            {
                Width = width, Height = height, Supersampling = 1, Train = steps, Val = 1, Test = 1, TimeSteps = steps, Monocular = true, PointCloud = 0,
                Configure = configure,
            });

        /// <summary>The train frames in time order, as the dataset's transforms hold them.</summary>
        public static List<ExportFrame> TrainInTime(ExportScene scene) =>
            scene.Split("train").OrderBy(f => f.Timing.Seconds.Value).ToList();

        public static double[,] OpenCv(Matrix4x4d c2w)
        {
            var m = new double[4, 4];
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++)
                    m[r, c] = c == 1 || c == 2 ? -c2w[r, c] : c2w[r, c];
            return m;
        }

        public static void AssertPose(double[,] expected, double[,] actual, double tolerance, string what)
        {
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++)
                    Assert.That(actual[r, c], Is.EqualTo(expected[r, c]).Within(tolerance), what + " [" + r + ", " + c + "]");
        }

        /// <summary>The dataset's own depth in output units (its 16-bit PNG × the depth unit).</summary>
        public static double[] SourceDepth(ExportScene scene, ExportFrame frame) =>
            PngGray16Reader.Read(Path.Combine(scene.RootDirectory, frame.DepthPath), out _, out _).Select(d => d * scene.DepthUnitScale).ToArray();

        /// <summary>The straight-alpha image over (r, g, b), by the over formula on 8-bit values, rounded to nearest, written out here.</summary>
        public static byte[] ExpectedRgb(ExportScene scene, ExportFrame frame, byte r, byte g, byte b)
        {
            var image = PngReader.Read(Path.Combine(scene.RootDirectory, frame.ImagePath));
            if (image.ColorType == PngInfo.ColorTypeRgb) return image.Samples;
            var n = image.Width * image.Height;
            var rgb = new byte[n * 3];
            var bg = new[] { r, g, b };
            for (var i = 0; i < n; i++)
            {
                var a = image.Samples[4 * i + 3];
                for (var c = 0; c < 3; c++)
                    rgb[3 * i + c] = (byte)Math.Floor((image.Samples[4 * i + c] * a + bg[c] * (255 - a)) / 255.0 + 0.5);
            }
            return rgb;
        }

        /// <summary>A key of a flat or two-level YAML file as the methods' yaml.safe_load reads a plain number.</summary>
        public static double YamlNumber(string file, string key)
        {
            var line = File.ReadAllLines(file).Single(l => l.Trim().StartsWith(key + ":", StringComparison.Ordinal));
            return double.Parse(line.Substring(line.IndexOf(':') + 1).Trim(), System.Globalization.CultureInfo.InvariantCulture);
        }

        /// <summary>PSNR in dB of two 8-bit images.</summary>
        public static double Psnr(byte[] a, byte[] b)
        {
            double sum = 0;
            for (var i = 0; i < a.Length; i++) sum += (a[i] - b[i]) * (double)(a[i] - b[i]);
            var mse = sum / a.Length;
            return mse == 0 ? double.PositiveInfinity : 10 * Math.Log10(255.0 * 255.0 / mse);
        }
    }
}
