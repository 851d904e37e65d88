using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// PSNR as 3DGS <c>utils/image_utils.py</c> <c>psnr</c> and nerfstudio compute it for data in [0, 1]:
    /// MSE over every sample (all pixels, all channels), PSNR = 20·log10(1 / √MSE) = −10·log10(MSE). Identical images
    /// give +∞ (written as null in metrics.json). The masked variant averages only over pixels whose mask value is at
    /// least <see cref="MaskThreshold"/> (the target's geometry: mask PNG 255 = target, edge coverage in between).
    /// </summary>
    public static class Psnr
    {
        /// <summary>Mask values ≥ 128 (of 255) count as the target.</summary>
        public const byte MaskThreshold = 128;

        public static double FromMse(double mse) => mse > 0 ? -10 * Math.Log10(mse) : double.PositiveInfinity;

        /// <summary>Mean squared difference over all samples.</summary>
        public static double Mse(float[] a, float[] b)
        {
            if (a == null || b == null || a.Length != b.Length || a.Length == 0) throw new ArgumentException("Both images must hold the same, non-zero number of samples.");
            double sum = 0;
            for (var i = 0; i < a.Length; i++)
            {
                double d = a[i] - b[i];
                sum += d * d;
            }
            return sum / a.Length;
        }

        public static double Of(float[] a, float[] b) => FromMse(Mse(a, b));

        /// <summary>
        /// PSNR over the pixels where <paramref name="mask"/> (one byte per pixel) is ≥ <see cref="MaskThreshold"/>; NaN
        /// when no pixel is inside. <paramref name="pixelsInside"/> says how many were.
        /// </summary>
        public static double Masked(float[] a, float[] b, int channels, byte[] mask, out long pixelsInside)
        {
            if (a == null || b == null || a.Length != b.Length || mask == null || (long)mask.Length * channels != a.Length)
                throw new ArgumentException("The images must hold mask.Length × channels samples.");
            double sum = 0;
            pixelsInside = 0;
            for (var p = 0; p < mask.Length; p++)
            {
                if (mask[p] < MaskThreshold) continue;
                pixelsInside++;
                for (var c = 0; c < channels; c++)
                {
                    double d = a[p * channels + c] - b[p * channels + c];
                    sum += d * d;
                }
            }
            return pixelsInside == 0 ? double.NaN : FromMse(sum / (pixelsInside * channels));
        }
    }
}
