using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Which part of the shutter interval each image row sees. With readout ρ the rows open one after the other, top row
    /// first: the row at v ∈ (0, 1) (v = (row from the top + ½)/H) is exposed over [ρ·v, ρ·v + (1 − ρ)] of the interval;
    /// ρ = 0 is a global shutter. That is instant-ngp's model exactly: its per-pixel time is
    /// t = A + B·u + C·v + D·r with r uniform in [0, 1] (<c>get_xform_given_rolling_shutter</c>,
    /// include/neural-graphics-primitives/common_device.cuh; read from <c>rolling_shutter</c> in src/nerf_loader.cu
    /// <c>read_lens</c>), so the written vector is [0, 0, ρ, 1 − ρ].
    /// <para>
    /// The rows come from the same sub-frames as the blur: sub-frame k stands for the slice [k/N, (k+1)/N], and a row
    /// takes each sub-frame with the weight of its slice's overlap with the row's window (the weights sum to 1). A
    /// global shutter gives every sub-frame 1/N.
    /// </para>
    /// </summary>
    public static class RollingShutter
    {
        /// <summary>instant-ngp's <c>rolling_shutter</c> [A, B, C, D] for readout ρ.</summary>
        public static double[] InstantNgpVector(double readout) => new[] { 0.0, 0.0, readout, 1 - readout };

        /// <summary>The row's vertical pixel coordinate in (0, 1), top = 0, for a row counted from the bottom (readback order).</summary>
        public static double V(int rowFromBottom, int height) => 1 - (rowFromBottom + 0.5) / height;

        /// <summary>The fraction of the interval at which the row at <paramref name="v"/> opens.</summary>
        public static double Opens(double v, double readout) => readout * v;

        /// <summary>The weight of sub-frame <paramref name="k"/> of <paramref name="count"/> in the row at <paramref name="v"/>.</summary>
        public static double Weight(int k, int count, double v, double readout)
        {
            if (readout <= 0) return 1.0 / count;
            var exposure = 1 - readout;
            var open = readout * v;
            var close = open + exposure;
            var overlap = Math.Min(close, (k + 1.0) / count) - Math.Max(open, (double)k / count);
            return overlap > 0 ? overlap / exposure : 0;
        }
    }
}
