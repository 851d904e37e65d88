using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// SSIM exactly as the Gaussian-splatting papers report it — 3DGS <c>utils/loss_utils.py</c> (<c>ssim</c> / <c>_ssim</c>,
    /// graphdeco-inria/gaussian-splatting at 15d64e6): an 11×11 Gaussian window (σ = 1.5, normalised to sum 1), applied
    /// per channel by <c>F.conv2d(…, padding=5)</c> — 'same' output with zero padding, so border pixels see zeros —,
    /// C1 = 0.01², C2 = 0.03² for data in [0, 1], σ² = E[x²] − μ², and the mean of the SSIM map over every pixel of every
    /// channel (equal to the mean of the per-channel means).
    /// <para>
    /// scikit-image's default (<c>structural_similarity(a, b, channel_axis=-1, data_range=1)</c>) gives another number:
    /// a 7×7 <b>uniform</b> window, sample (N−1) covariances, and the mean over the map after cropping 3 pixels at each
    /// border instead of padding. Only <c>gaussian_weights=True, sigma=1.5, use_sample_covariance=False</c> brings it
    /// close, and its border handling (reflection, cropped) still differs from the zero padding here.
    /// </para>
    /// The Gaussian 2-D window is separable, so each of the five filtered images (μa, μb, E[a²], E[b²], E[ab]) is a
    /// horizontal then a vertical 11-tap pass; zero padding of the input is the same as treating rows and columns outside
    /// the image as zero in both passes. Everything is in double.
    /// </summary>
    public static class Ssim
    {
        public const int WindowSize = 11;
        public const double Sigma = 1.5;
        public const double C1 = 0.01 * 0.01;
        public const double C2 = 0.03 * 0.03;
        const int Radius = WindowSize / 2;

        /// <summary>The 1-D window: exp(−(x − 5)² / (2σ²)) for x = 0 … 10, divided by its sum (3DGS's <c>gaussian</c>).</summary>
        public static double[] Window()
        {
            var w = new double[WindowSize];
            double sum = 0;
            for (var x = 0; x < WindowSize; x++) sum += w[x] = Math.Exp(-(x - Radius) * (x - Radius) / (2 * Sigma * Sigma));
            for (var x = 0; x < WindowSize; x++) w[x] /= sum;
            return w;
        }

        /// <summary>Mean SSIM of two interleaved images (<paramref name="channels"/> samples per pixel, values in [0, 1]).</summary>
        public static double Mean(float[] a, float[] b, int width, int height, int channels)
        {
            Check(a, b, width, height, channels);
            var buffers = new Buffers(width * height);
            double total = 0;
            for (var c = 0; c < channels; c++) total += ChannelSum(a, b, width, height, channels, c, buffers, null);
            return total / ((double)width * height * channels);
        }

        /// <summary>
        /// Mean SSIM as <see cref="Mean"/>, and the per-pixel SSIM averaged over channels into <paramref name="map"/>
        /// (width × height), for error maps.
        /// </summary>
        public static double Mean(float[] a, float[] b, int width, int height, int channels, double[] map)
        {
            Check(a, b, width, height, channels);
            if (map == null || map.Length != width * height) throw new ArgumentException("map must hold width × height values.", nameof(map));
            Array.Clear(map, 0, map.Length);
            var buffers = new Buffers(width * height);
            double total = 0;
            for (var c = 0; c < channels; c++) total += ChannelSum(a, b, width, height, channels, c, buffers, map);
            for (var i = 0; i < map.Length; i++) map[i] /= channels;
            return total / ((double)width * height * channels);
        }

        static void Check(float[] a, float[] b, int width, int height, int channels)
        {
            if (width <= 0 || height <= 0 || channels <= 0) throw new ArgumentException("The image must have a positive size and channel count.");
            var n = (long)width * height * channels;
            if (a == null || b == null || a.Length != n || b.Length != n) throw new ArgumentException("Both images must hold width × height × channels samples.");
        }

        sealed class Buffers
        {
            public readonly double[] Ma, Mb, Saa, Sbb, Sab;
            public readonly double[] W = Window();

            public Buffers(int pixels)
            {
                Ma = new double[pixels];
                Mb = new double[pixels];
                Saa = new double[pixels];
                Sbb = new double[pixels];
                Sab = new double[pixels];
            }
        }

        /// <summary>Sum of the SSIM map of one channel; adds each pixel's value to <paramref name="map"/> when given.</summary>
        static double ChannelSum(float[] a, float[] b, int width, int height, int channels, int c, Buffers buf, double[] map)
        {
            var w = buf.W;
            double[] ma = buf.Ma, mb = buf.Mb, saa = buf.Saa, sbb = buf.Sbb, sab = buf.Sab;
            // Horizontal pass: zero outside [0, width).
            for (var y = 0; y < height; y++)
            {
                var row = y * width;
                for (var x = 0; x < width; x++)
                {
                    double pa = 0, pb = 0, paa = 0, pbb = 0, pab = 0;
                    var from = Math.Max(0, x - Radius);
                    var to = Math.Min(width - 1, x + Radius);
                    for (var xx = from; xx <= to; xx++)
                    {
                        var k = w[xx - x + Radius];
                        var i = (row + xx) * channels + c;
                        double va = a[i], vb = b[i];
                        var ka = k * va;
                        var kb = k * vb;
                        pa += ka;
                        pb += kb;
                        paa += ka * va;
                        pbb += kb * vb;
                        pab += ka * vb;
                    }
                    var o = row + x;
                    ma[o] = pa;
                    mb[o] = pb;
                    saa[o] = paa;
                    sbb[o] = pbb;
                    sab[o] = pab;
                }
            }
            // Vertical pass, zero outside [0, height), and the SSIM formula on the fly.
            double sum = 0;
            for (var y = 0; y < height; y++)
            {
                var from = Math.Max(0, y - Radius);
                var to = Math.Min(height - 1, y + Radius);
                for (var x = 0; x < width; x++)
                {
                    double mua = 0, mub = 0, eaa = 0, ebb = 0, eab = 0;
                    for (var yy = from; yy <= to; yy++)
                    {
                        var k = w[yy - y + Radius];
                        var o = yy * width + x;
                        mua += k * ma[o];
                        mub += k * mb[o];
                        eaa += k * saa[o];
                        ebb += k * sbb[o];
                        eab += k * sab[o];
                    }
                    var value = Formula(mua, mub, eaa - mua * mua, ebb - mub * mub, eab - mua * mub);
                    sum += value;
                    if (map != null) map[y * width + x] += value;
                }
            }
            return sum;
        }

        /// <summary>((2μaμb + C1)(2σab + C2)) / ((μa² + μb² + C1)(σa² + σb² + C2)).</summary>
        public static double Formula(double muA, double muB, double varA, double varB, double cov) =>
            (2 * muA * muB + C1) * (2 * cov + C2) / ((muA * muA + muB * muB + C1) * (varA + varB + C2));
    }
}
