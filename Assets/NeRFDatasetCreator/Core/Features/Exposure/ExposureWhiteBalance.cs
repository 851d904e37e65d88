using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The exposure and white-balance stage (Documentation~/exposure.md): every colour channel of straight (un-premultiplied)
    /// linear light becomes c' = min(1, c · 2^EV · gain) — clipped at 1, as a real sensor saturates — and alpha is
    /// unchanged. It is the last stage before the PNG: it takes the view's finished 8-bit sRGB straight colour (after
    /// matting, compositing and downsampling), decodes each byte to linear light with the exact sRGB formula, scales,
    /// clips and encodes once more. The clean image written beside it is that same 8-bit colour, so the modified image
    /// is the clean one times the gain in linear light, to one rounding; applying the gain before the first rounding
    /// would differ by the clean image's own quantisation step times the gain (measured in ExposureWhiteBalanceTests).
    /// </summary>
    public static class ExposureWhiteBalance
    {
        /// <summary>The stage on one linear value: min(1, c · <paramref name="scale"/>), negatives and NaN to 0.</summary>
        public static double Apply(double linear, double scale)
        {
            var v = linear * scale;
            return v > 1 ? 1 : v > 0 ? v : 0;
        }

        /// <summary>
        /// The 256-entry table of one channel: byte b → round(255 · sRGB(min(1, decode(b) · scale))), with the standard's
        /// formulas in double precision (<see cref="Srgb.DecodeExact"/>, <see cref="Srgb.EncodeByteExact"/>).
        /// </summary>
        public static byte[] Table(double scale)
        {
            if (!(scale >= 0) || double.IsInfinity(scale)) throw new ArgumentOutOfRangeException(nameof(scale), scale, "a gain is a finite number ≥ 0");
            var table = new byte[256];
            for (var b = 0; b < 256; b++) table[b] = Srgb.EncodeByteExact(Apply(Srgb.DecodeExact(b / 255.0), scale));
            return table;
        }

        /// <summary>Applies <paramref name="exposure"/> in place to tightly packed 8-bit sRGB RGBA pixels; alpha is left as it is.</summary>
        public static void ApplyRgba(byte[] rgba, ViewExposure exposure)
        {
            if (rgba == null) throw new ArgumentNullException(nameof(rgba));
            if (rgba.Length % 4 != 0) throw new ArgumentException("RGBA pixels come in groups of 4 bytes.", nameof(rgba));
            byte[] r = Table(exposure.Scale(0)), g = Table(exposure.Scale(1)), b = Table(exposure.Scale(2));
            for (var i = 0; i < rgba.Length; i += 4)
            {
                rgba[i] = r[rgba[i]];
                rgba[i + 1] = g[rgba[i + 1]];
                rgba[i + 2] = b[rgba[i + 2]];
            }
        }
    }
}
