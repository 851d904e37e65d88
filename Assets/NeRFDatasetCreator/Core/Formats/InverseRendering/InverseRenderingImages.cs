using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-view images of the inverse-rendering exports, made from the dataset's truth: the material passes' float
    /// EXRs (contract38: the EXR is the truth; re-encoding the 8-bit sRGB PNG to linear can be 2 codes off) and the
    /// colour image's alpha. Every image is straight RGBA with the colour image's alpha and RGB 0 where alpha is 0.
    /// </summary>
    public static class InverseRenderingImages
    {
        /// <summary>Linear value → nearest 8-bit code, clipped to [0, 1]; "linear clipped to 8 bits without the sRGB curve".</summary>
        public static byte LinearCode(double v)
        {
            if (!(v > 0)) return 0;
            if (v >= 1) return 255;
            return (byte)Math.Floor(v * 255 + 0.5);
        }

        /// <summary>An 8-bit RGBA PNG (the colour image, relit images): refused with the reason otherwise.</summary>
        public static PngImage ReadRgba(string path, string why)
        {
            var png = PngReader.Read(path);
            if (png.BitDepth != 8 || png.Channels != 4)
                throw new InvalidParameterException(new[] { new ValidationProblem("file_path", path, "is not 8-bit RGBA: " + why, "Capture with a transparent background (the plugin's PNGs are straight RGBA).") });
            return png;
        }

        /// <summary>The alpha codes of an RGBA image.</summary>
        public static byte[] Alpha(PngImage rgba)
        {
            var n = rgba.Width * rgba.Height;
            var a = new byte[n];
            for (var i = 0; i < n; i++) a[i] = rgba.Samples[4 * i + 3];
            return a;
        }

        /// <summary>Reads a pass's EXR, refusing a missing one or one of another size than the colour image, naming it.</summary>
        public static ExrImage ReadPass(string path, string key, int width, int height)
        {
            if (path == null || !File.Exists(path))
                throw new InvalidParameterException(new[] { new ValidationProblem(key, path ?? "(none)", "is missing: the exports read the material passes' float EXR truth beside the PNG the key names.", "Re-capture with the material passes on.") });
            var exr = ExrReader.Read(path);
            if (exr.Width != width || exr.Height != height || exr.Channel("R") == null)
                throw new InvalidParameterException(new[] { new ValidationProblem(key, path, "is " + exr.Width + "×" + exr.Height + " without an R channel or of another size than the colour image (" + width + "×" + height + ").", "Re-capture the dataset.") });
            return exr;
        }

        /// <summary>
        /// albedo.png of TensoIR / NeRFactor / GS-IR: the DIFFUSE colour base × (1 − metallic), linear in 8 bits (no sRGB
        /// curve), alpha = the colour image's; <paramref name="metallic"/> null reads as 0 (the base colour).
        /// </summary>
        public static byte[] DiffuseLinear(ExrImage baseColour, ExrImage metallic, byte[] alpha)
        {
            float[] r = baseColour.Channel("R"), g = baseColour.Channel("G"), b = baseColour.Channel("B"), m = metallic?.Channel("R");
            var rgba = new byte[alpha.Length * 4];
            for (var i = 0; i < alpha.Length; i++)
            {
                if (alpha[i] == 0) continue;
                var keep = m == null ? 1.0 : 1.0 - m[i];
                rgba[4 * i] = LinearCode(r[i] * keep);
                rgba[4 * i + 1] = LinearCode(g[i] * keep);
                rgba[4 * i + 2] = LinearCode(b[i] * keep);
                rgba[4 * i + 3] = alpha[i];
            }
            return rgba;
        }

        /// <summary>R3DG's _albedo.png: the BASE colour sRGB-encoded to the nearest code, alpha = the colour image's.</summary>
        public static byte[] BaseSrgb(ExrImage baseColour, byte[] alpha)
        {
            float[] r = baseColour.Channel("R"), g = baseColour.Channel("G"), b = baseColour.Channel("B");
            var rgba = new byte[alpha.Length * 4];
            for (var i = 0; i < alpha.Length; i++)
            {
                if (alpha[i] == 0) continue;
                rgba[4 * i] = Srgb.EncodeByteExact(r[i]);
                rgba[4 * i + 1] = Srgb.EncodeByteExact(g[i]);
                rgba[4 * i + 2] = Srgb.EncodeByteExact(b[i]);
                rgba[4 * i + 3] = alpha[i];
            }
            return rgba;
        }

        /// <summary>A one-value pass (roughness) as R = G = B = round(v·255), linear, alpha = the colour image's.</summary>
        public static byte[] GreyLinear(ExrImage pass, byte[] alpha)
        {
            var v = pass.Channel("R");
            var rgba = new byte[alpha.Length * 4];
            for (var i = 0; i < alpha.Length; i++)
            {
                if (alpha[i] == 0) continue;
                rgba[4 * i] = rgba[4 * i + 1] = rgba[4 * i + 2] = LinearCode(v[i]);
                rgba[4 * i + 3] = alpha[i];
            }
            return rgba;
        }

        /// <summary>
        /// normal.png: the dataset's world-space normal codes (round((n·0.5 + 0.5)·255), output-format.md) with the colour
        /// image's alpha, RGB 0 where alpha is 0 (TensoIR blends the background to +Z by that alpha).
        /// </summary>
        public static byte[] NormalWithAlpha(PngImage normal, byte[] alpha)
        {
            var channels = normal.Channels;
            var rgba = new byte[alpha.Length * 4];
            for (var i = 0; i < alpha.Length; i++)
            {
                if (alpha[i] == 0) continue;
                for (var c = 0; c < 3; c++) rgba[4 * i + c] = normal.Samples[channels * i + c];
                rgba[4 * i + 3] = alpha[i];
            }
            return rgba;
        }

        /// <summary>An RGBA copy with RGB 0 wherever alpha is 0 (R3DG masks its test images by non-black RGB).</summary>
        public static byte[] BlackWhereTransparent(PngImage rgba)
        {
            var copy = (byte[])rgba.Samples.Clone();
            for (var i = 0; i < copy.Length; i += 4)
                if (copy[i + 3] == 0) copy[i] = copy[i + 1] = copy[i + 2] = 0;
            return copy;
        }

        /// <summary>
        /// R3DG's _rgb.exr: the linear HDR colour as float32 RGBA, straight alpha (the EXR's A, else the PNG's), RGB 0
        /// where alpha is 0.
        /// </summary>
        public static float[] LinearHdrRgba(ExrImage hdr, byte[] alpha)
        {
            float[] r = hdr.Channel("R"), g = hdr.Channel("G"), b = hdr.Channel("B"), a = hdr.Channel("A");
            var pixels = new float[alpha.Length * 4];
            for (var i = 0; i < alpha.Length; i++)
            {
                var coverage = a != null ? Math.Max(0f, Math.Min(1f, a[i])) : alpha[i] / 255f;
                if (!(coverage > 0)) continue;
                pixels[4 * i] = r[i];
                pixels[4 * i + 1] = g[i];
                pixels[4 * i + 2] = b[i];
                pixels[4 * i + 3] = coverage;
            }
            return pixels;
        }

        /// <summary>
        /// An OpenEXR of RGBA float pixels given top row first (as <see cref="ExrReader"/> returns them): ExrWriter takes
        /// rows bottom-up (texture order), so they are handed over flipped.
        /// </summary>
        public static byte[] EncodeExrTopDown(float[] rgba, int width, int height)
        {
            var flipped = new float[rgba.Length];
            var row = width * 4;
            for (var y = 0; y < height; y++) Array.Copy(rgba, (long)y * row, flipped, (long)(height - 1 - y) * row, row);
            return ExrWriter.Encode(flipped, width, height, 4);
        }
    }
}
