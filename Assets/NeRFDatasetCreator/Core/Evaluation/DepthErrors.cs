using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Depth error against the dataset's metric z-depth, the three figures of the monocular-depth literature (Eigen et
    /// al. 2014): abs-rel = mean |d − d*| / d*, RMSE = √mean (d − d*)², δ &lt; 1.25 = the fraction of pixels with
    /// max(d / d*, d* / d) &lt; 1.25; d the render's depth, d* the ground truth, both in output units. Pixels count when
    /// the ground truth has a surface (d* &gt; 0), the mask (when given) says target (≥ 128) and the render gives a finite
    /// d &gt; 0; the others inside the mask are counted as <see cref="Missing"/>.
    /// </summary>
    public sealed class DepthErrors
    {
        public double AbsRel { get; private set; }
        public double Rmse { get; private set; }
        public double Delta125 { get; private set; }
        public long Pixels { get; private set; }

        /// <summary>Ground-truth surface pixels (inside the mask) where the render has no usable depth.</summary>
        public long Missing { get; private set; }

        public const double DeltaThreshold = 1.25;

        /// <param name="rendered">Render's depth per pixel in output units (NaN or ≤ 0 = none).</param>
        /// <param name="truth">Ground-truth depth per pixel in output units (0 = no surface).</param>
        /// <param name="mask">Target mask (one byte per pixel) or null for every surface pixel.</param>
        public static DepthErrors Compute(float[] rendered, float[] truth, byte[] mask)
        {
            if (rendered == null || truth == null || rendered.Length != truth.Length || (mask != null && mask.Length != truth.Length))
                throw new ArgumentException("Depth images and mask must have one value per pixel.");
            double absRel = 0, squared = 0;
            long inside = 0, pixels = 0, missing = 0;
            for (var i = 0; i < truth.Length; i++)
            {
                double t = truth[i];
                if (!(t > 0) || (mask != null && mask[i] < Psnr.MaskThreshold)) continue;
                double d = rendered[i];
                if (!(d > 0) || double.IsInfinity(d)) { missing++; continue; }
                pixels++;
                var diff = d - t;
                absRel += Math.Abs(diff) / t;
                squared += diff * diff;
                if (Math.Max(d / t, t / d) < DeltaThreshold) inside++;
            }
            var result = new DepthErrors { Pixels = pixels, Missing = missing };
            if (pixels == 0)
            {
                result.AbsRel = result.Rmse = result.Delta125 = double.NaN;
                return result;
            }
            result.AbsRel = absRel / pixels;
            result.Rmse = Math.Sqrt(squared / pixels);
            result.Delta125 = (double)inside / pixels;
            return result;
        }
    }
}
