using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Turns the PNGs (and nerfstudio arrays) of a view into the float images the metrics take: colour as 3 samples per
    /// pixel in [0, 1] (8- or 16-bit, grey or RGB, with or without alpha; alpha composited on the background), depth as
    /// output units per pixel, normals as 3 floats per pixel, the mask as one byte per pixel.
    /// </summary>
    public static class EvaluationImages
    {
        public static float[] Colour(PngImage png, EvaluationBackground background, string path)
        {
            var channels = png.Channels;
            if (channels == 0) throw Bad(path, "has a PNG colour type this tool does not read.", "Save the render as 8- or 16-bit grey, RGB or RGBA PNG.");
            var pixels = png.Width * png.Height;
            var result = new float[pixels * 3];
            var wide = png.BitDepth == 16;
            var max = wide ? 65535f : 255f;
            var hasAlpha = channels == 2 || channels == 4;
            var colourChannels = hasAlpha ? channels - 1 : channels;
            var s = png.Samples;
            for (var p = 0; p < pixels; p++)
            {
                var at = p * channels;
                float r, g, b;
                if (colourChannels == 1) r = g = b = Sample(s, at, wide) / max;
                else
                {
                    r = Sample(s, at, wide) / max;
                    g = Sample(s, at + 1, wide) / max;
                    b = Sample(s, at + 2, wide) / max;
                }
                if (hasAlpha)
                {
                    var a = Sample(s, at + channels - 1, wide) / max;
                    if (a < 1)
                    {
                        if (!background.Known)
                            throw new InvalidParameterException(new[] { new ValidationProblem("--background", background.Name, path + " has transparent pixels, and the dataset records no solid background colour to put behind them.", "Use --background white (nerf_synthetic's evaluation) or black, matching how the model was trained.") });
                        r = (float)(r * a + background.R * (1 - a));
                        g = (float)(g * a + background.G * (1 - a));
                        b = (float)(b * a + background.B * (1 - a));
                    }
                }
                result[3 * p] = r;
                result[3 * p + 1] = g;
                result[3 * p + 2] = b;
            }
            return result;
        }

        static float Sample(byte[] s, int index, bool wide) => wide ? (s[2 * index] << 8) | s[2 * index + 1] : s[index];

        /// <summary>The dataset's depth PNG in output units: value × <paramref name="scale"/>, 0 = no surface.</summary>
        public static float[] DepthPng(PngImage png, double scale, string path)
        {
            if (png.Channels != 1 || png.BitDepth != 16) throw Bad(path, "is not a 16-bit grey depth PNG.", "Use this plugin's depth encoding: round(z·1000) in 16-bit grey.");
            var result = new float[png.Width * png.Height];
            for (var i = 0; i < result.Length; i++) result[i] = (float)(((png.Samples[2 * i] << 8) | png.Samples[2 * i + 1]) * scale);
            return result;
        }

        /// <summary>
        /// A nerfstudio raw depth array (H × W × 1) in output units; with <paramref name="alongRay"/> the distance along
        /// each pixel's ray (nerfacto's median depth) is turned into z-depth: z = d / √(1 + x'² + y'²), x' = (u + 0.5 − cx)/f.
        /// </summary>
        public static float[] DepthNpy(NpyReader.NpyArray array, int width, int height, bool alongRay, double focal, double cx, double cy, string path)
        {
            var shape = array.Shape;
            if (!(shape.Length >= 2 && shape[0] == height && shape[1] == width && (shape.Length == 2 || (shape.Length == 3 && shape[2] == 1))))
                throw Bad(path, "has shape (" + string.Join(", ", shape) + "), not (" + height + ", " + width + ", 1) like the dataset's images.", "Render at the dataset's resolution (no --downscale-factor).");
            var result = (float[])array.Values.Clone();
            if (alongRay)
                for (var v = 0; v < height; v++)
                {
                    var y = (v + 0.5 - cy) / focal;
                    for (var u = 0; u < width; u++)
                    {
                        var x = (u + 0.5 - cx) / focal;
                        result[v * width + u] = (float)(result[v * width + u] / Math.Sqrt(1 + x * x + y * y));
                    }
                }
            return result;
        }

        public static float[] NormalsPng(PngImage png, string path)
        {
            if (png.Channels != 3 || png.BitDepth != 8) throw Bad(path, "is not an 8-bit RGB normal PNG.", "Use this plugin's normal encoding: round((n·0.5 + 0.5)·255), output world frame.");
            return NormalErrors.Decode8Bit(png.Samples);
        }

        public static float[] NormalsNpy(NpyReader.NpyArray array, int width, int height, string path)
        {
            var shape = array.Shape;
            if (!(shape.Length == 3 && shape[0] == height && shape[1] == width && shape[2] == 3))
                throw Bad(path, "has shape (" + string.Join(", ", shape) + "), not (" + height + ", " + width + ", 3).", "Render raw-normals at the dataset's resolution.");
            return array.Values;
        }

        public static byte[] Mask(PngImage png, string path)
        {
            if (png.Channels != 1 || png.BitDepth != 8) throw Bad(path, "is not an 8-bit grey mask PNG.", "Use this plugin's mask encoding (255 = target).");
            return png.Samples;
        }

        static InvalidParameterException Bad(string path, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(Path.GetFileName(path), path, reason, fix) });
    }
}
