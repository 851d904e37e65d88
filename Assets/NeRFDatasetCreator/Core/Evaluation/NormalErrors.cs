using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Mean (and median) angle in degrees between the render's and the ground truth's unit normals, both in the output
    /// world frame, over pixels where the ground truth has a normal (non-zero), the mask (when given) says target and the
    /// render's normal is non-zero. Vectors are normalised first, so the 8-bit quantisation of the PNG encoding
    /// (round((n·0.5 + 0.5)·255)) costs at most ≈ 0.3°.
    /// </summary>
    public sealed class NormalErrors
    {
        public double MeanDegrees { get; private set; }
        public double MedianDegrees { get; private set; }
        public long Pixels { get; private set; }

        /// <param name="rendered">Three floats per pixel (any length; zero = none).</param>
        /// <param name="truth">Three floats per pixel (zero = background).</param>
        public static NormalErrors Compute(float[] rendered, float[] truth, byte[] mask)
        {
            if (rendered == null || truth == null || rendered.Length != truth.Length || truth.Length % 3 != 0 || (mask != null && mask.Length * 3 != truth.Length))
                throw new ArgumentException("Normal images must have three values per pixel and the mask one.");
            var pixelsTotal = truth.Length / 3;
            var angles = new double[pixelsTotal];
            var n = 0;
            for (var p = 0; p < pixelsTotal; p++)
            {
                if (mask != null && mask[p] < Psnr.MaskThreshold) continue;
                double tx = truth[3 * p], ty = truth[3 * p + 1], tz = truth[3 * p + 2];
                double rx = rendered[3 * p], ry = rendered[3 * p + 1], rz = rendered[3 * p + 2];
                var tl = Math.Sqrt(tx * tx + ty * ty + tz * tz);
                var rl = Math.Sqrt(rx * rx + ry * ry + rz * rz);
                if (!(tl > 0) || !(rl > 0) || double.IsInfinity(rl)) continue;
                var cos = (tx * rx + ty * ry + tz * rz) / (tl * rl);
                angles[n++] = Math.Acos(Math.Max(-1, Math.Min(1, cos))) * 180 / Math.PI;
            }
            var result = new NormalErrors { Pixels = n };
            if (n == 0)
            {
                result.MeanDegrees = result.MedianDegrees = double.NaN;
                return result;
            }
            double sum = 0;
            for (var i = 0; i < n; i++) sum += angles[i];
            result.MeanDegrees = sum / n;
            Array.Sort(angles, 0, n);
            result.MedianDegrees = n % 2 == 1 ? angles[n / 2] : 0.5 * (angles[n / 2 - 1] + angles[n / 2]);
            return result;
        }

        /// <summary>The 8-bit encoding's inverse: v / 255 · 2 − 1 per component; (0, 0, 0) stays zero (background).</summary>
        public static float[] Decode8Bit(byte[] rgb)
        {
            var result = new float[rgb.Length];
            for (var p = 0; p + 2 < rgb.Length; p += 3)
            {
                if (rgb[p] == 0 && rgb[p + 1] == 0 && rgb[p + 2] == 0) continue;
                for (var c = 0; c < 3; c++) result[p + c] = rgb[p + c] / 255f * 2 - 1;
            }
            return result;
        }
    }
}
