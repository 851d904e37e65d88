using System;
using System.IO;
using System.Runtime.CompilerServices;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Documentation~/images/lens-distortion.png is what the lens code makes today: the same analytic view clean (the
    /// pinhole the output intrinsics describe) and through a barrel lens, the distorted one made the capture's way — a
    /// wide pinhole render resampled by <see cref="LensResampler"/>, then the k×k box average in linear light. The test
    /// renders the picture and compares it with the committed file; after a deliberate change to the lens code, rewrite
    /// the file with <c>NERF_DATASET_WRITE_DOC_IMAGES=1 dotnet test Tests/Core.Tests --filter "FullyQualifiedName~LensPicture"</c>.
    /// (It was an [Explicit] generator before, which printed a "Skipped" line in every test run.)
    /// </summary>
    [TestFixture]
    public class LensPictureTests
    {
        const int Width = 320, Height = 240, K = 2, Gap = 8;

        [Test]
        public void TheDocumentationPictureIsWhatTheLensCodeMakes()
        {
            var frame = CameraIntrinsics.FromVerticalFov(60, Width, Height);
            var lens = LensDistortion.OpenCv(-0.25, 0.06, 0, 0);
            var clean = Render(frame.Width * K, frame.Height * K, (i, j) => new Vector3d((i - frame.Cx) / frame.FlX, -(j - frame.Cy) / frame.FlY, -1));
            var wide = LensCapture.WideRender(lens, frame);
            var wideFrame = Render(wide.Width * K, wide.Height * K, (i, j) => new Vector3d((i - wide.Cx) / wide.Focal, -(j - wide.Cy) / wide.Focal, -1));
            var distorted = new LensResampler(lens, frame, wide).Resample(wideFrame);

            var canvas = new byte[(2 * Width + Gap) * Height * 3];
            for (var p = 0; p < canvas.Length; p++) canvas[p] = 255;
            Paste(clean, canvas, 0);
            Paste(distorted, canvas, Width + Gap);
            var path = Path.Combine(RepositoryRoot(), "Documentation~", "images", "lens-distortion.png");
            if (Environment.GetEnvironmentVariable("NERF_DATASET_WRITE_DOC_IMAGES") == "1")
            {
                File.WriteAllBytes(path, PngWriter.Encode(canvas, 2 * Width + Gap, Height, PngPixelFormat.Rgb8));
                TestContext.WriteLine("wrote " + path + " (wide render " + wide.Width + "×" + wide.Height + " for a " + Width + "×" + Height + " frame)");
            }

            var committed = PngReader.Decode(File.ReadAllBytes(path), path);
            Assert.That(new[] { committed.Width, committed.Height, committed.Channels }, Is.EqualTo(new[] { 2 * Width + Gap, Height, 3 }), path);
            // One level of tolerance: the file must show what the code makes, not carry its last bit across runtimes.
            var worst = 0;
            for (var p = 0; p < canvas.Length; p++) worst = Math.Max(worst, Math.Abs(canvas[p] - committed.Samples[p]));
            Assert.That(worst, Is.LessThanOrEqualTo(1),
                path + " no longer shows what the lens code makes; rewrite it with NERF_DATASET_WRITE_DOC_IMAGES=1 (see this test's summary).");
        }

        /// <summary>Linear colour, rows bottom first, of a wall of squares 3 units away with the analytic test spheres before it.</summary>
        static RawFrame Render(int w, int h, Func<double, double, Vector3d> ray)
        {
            var scene = new AnalyticScene();
            scene.Spheres.Add(new AnalyticScene.Sphere { Centre = new Vector3d(-0.5, 0.1, -2.2), Radius = 0.35, Colour = new[] { 0.8, 0.25, 0.1 } });
            scene.Spheres.Add(new AnalyticScene.Sphere { Centre = new Vector3d(0.55, -0.2, -2.5), Radius = 0.3, Colour = new[] { 0.2, 0.4, 0.9 } });
            var light = new Vector3d(0.3, 0.5, 0.8).Normalized();
            var frame = new RawFrame(w, h, K) { ColorLinear = new float[w * h * 4] };
            for (var ys = 0; ys < h; ys++)
                for (var xs = 0; xs < w; xs++)
                {
                    var d = ray((xs + 0.5) / K, (ys + 0.5) / K);
                    double[] colour;
                    if (scene.Trace(Vector3d.Zero, d, 0, out _, out var normal, out var c, out _))
                    {
                        var shade = 0.35 + 0.65 * Math.Max(0, Vector3d.Dot(normal, light));
                        colour = new[] { c[0] * shade, c[1] * shade, c[2] * shade };
                    }
                    else
                    {
                        // The wall z = −3: squares of 0.25 units, light and dark grey.
                        double x = d.X * 3 / -d.Z, y = d.Y * 3 / -d.Z;
                        var light2 = ((int)Math.Floor(x / 0.25) + (int)Math.Floor(y / 0.25)) % 2 == 0;
                        var g = light2 ? 0.8 : 0.12;
                        colour = new[] { g, g, g };
                    }
                    var p = ((h - 1 - ys) * w + xs) * 4;
                    for (var ch = 0; ch < 3; ch++) frame.ColorLinear[p + ch] = (float)colour[ch];
                    frame.ColorLinear[p + 3] = 1;
                }
            return frame;
        }

        /// <summary>The k×k box average in linear light, sRGB-encoded, top row first, at column <paramref name="left"/> of the canvas.</summary>
        static void Paste(RawFrame frame, byte[] canvas, int left)
        {
            var stride = 2 * Width + Gap;
            for (var y = 0; y < Height; y++)
                for (var x = 0; x < Width; x++)
                    for (var ch = 0; ch < 3; ch++)
                    {
                        double sum = 0;
                        for (var dy = 0; dy < K; dy++)
                            for (var dx = 0; dx < K; dx++)
                                sum += frame.ColorLinear[((frame.Height - 1 - (y * K + dy)) * frame.Width + x * K + dx) * 4 + ch];
                        canvas[(y * stride + left + x) * 3 + ch] = Srgb.EncodeByteExact(sum / (K * K));
                    }
        }

        static string RepositoryRoot([CallerFilePath] string path = "")
        {
            var folder = Path.GetDirectoryName(path);
            while (folder != null && !Directory.Exists(Path.Combine(folder, "Documentation~"))) folder = Path.GetDirectoryName(folder);
            return folder ?? throw new DirectoryNotFoundException("Documentation~ above " + path);
        }
    }
}
