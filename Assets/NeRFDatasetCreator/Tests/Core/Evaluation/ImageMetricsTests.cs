using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// PSNR and SSIM against hand-computed values on tiny images, and SSIM against an independent, direct 2-D
    /// implementation of 3DGS's formula (explicit 11×11 window, explicit zero padding) on larger random images.
    /// </summary>
    public class ImageMetricsTests
    {
        [Test]
        public void PsnrOfAUniformDifferenceOfATenthIs20Decibels()
        {
            var a = new float[12];
            var b = new float[12];
            for (var i = 0; i < b.Length; i++) b[i] = 0.1f;
            // MSE = 0.1² (as float: 0.1f²), PSNR = −10·log10(MSE).
            Assert.That(Psnr.Of(a, b), Is.EqualTo(-10 * Math.Log10(0.1f * (double)0.1f)).Within(1e-12));
            Assert.That(Psnr.Of(a, b), Is.EqualTo(20).Within(1e-5));
        }

        [Test]
        public void IdenticalImagesHaveInfinitePsnrAndSsimOne()
        {
            var a = Random(9, 7, 3, 1);
            Assert.That(Psnr.Of(a, a), Is.EqualTo(double.PositiveInfinity));
            Assert.That(Ssim.Mean(a, a, 9, 7, 3), Is.EqualTo(1).Within(1e-15));
        }

        [Test]
        public void MaskedPsnrAveragesOnlyInsideTheMask()
        {
            // Two RGB pixels: the first (inside) differs by 0.2 in one channel, the second (outside) by 1 everywhere.
            var a = new float[] { 0.2f, 0, 0, 1, 1, 1 };
            var b = new float[6];
            var psnr = Psnr.Masked(a, b, 3, new byte[] { 255, 0 }, out var inside);
            Assert.That(inside, Is.EqualTo(1));
            Assert.That(psnr, Is.EqualTo(-10 * Math.Log10(0.2f * (double)0.2f / 3)).Within(1e-12));
            Assert.That(Psnr.Masked(a, b, 3, new byte[] { 127, 0 }, out inside), Is.NaN, "127 is below the threshold");
        }

        [Test]
        public void SsimOfOnePixelMatchesTheFormulaWorkedByHand()
        {
            // A 1×1 image with zero padding: only the window's centre weight k = g₅² sees the pixel, so
            // μ = k·x, E[x²] = k·x², σ² = k(1 − k)x², σxy = k(1 − k)xy.
            double g5 = 1 / Sum(j => Math.Exp(-j * j / 4.5));
            var k = g5 * g5;
            double x = 0.8, y = 0.3;
            var expected = (2 * k * k * x * y + 1e-4) * (2 * k * (1 - k) * x * y + 9e-4) /
                           ((k * k * (x * x + y * y) + 1e-4) * (k * (1 - k) * (x * x + y * y) + 9e-4));
            var ssim = Ssim.Mean(new[] { (float)x }, new[] { (float)y }, 1, 1, 1);
            Assert.That(ssim, Is.EqualTo(expected).Within(1e-6));
            Assert.That(g5, Is.EqualTo(0.2660117).Within(1e-6), "the normalised centre of a σ 1.5, 11-tap Gaussian");
        }

        [Test]
        public void SsimMatchesADirectImplementationOfThe3dgsFormula([Values(1, 3)] int channels)
        {
            const int w = 37, h = 29;
            var a = Random(w, h, channels, 7);
            var b = Random(w, h, channels, 8);
            // Make b partly similar to a so the structure term is not just noise.
            for (var i = 0; i < a.Length; i += 2) b[i] = 0.7f * a[i] + 0.3f * b[i];
            Assert.That(Ssim.Mean(a, b, w, h, channels), Is.EqualTo(Direct3dgs(a, b, w, h, channels)).Within(1e-6));
            var map = new double[w * h];
            Assert.That(Ssim.Mean(a, b, w, h, channels, map), Is.EqualTo(Direct3dgs(a, b, w, h, channels)).Within(1e-6));
        }

        [Test]
        public void SsimOfAHalfPixelShiftedEdgeIsBelowOne()
        {
            const int w = 24, h = 24;
            var a = new float[w * h];
            var b = new float[w * h];
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    a[y * w + x] = x < 12 ? 1 : 0;
                    b[y * w + x] = x < 12 ? 1 : x == 12 ? 0.5f : 0;
                }
            var ssim = Ssim.Mean(a, b, w, h, 1);
            Assert.That(ssim, Is.LessThan(1).And.GreaterThan(0.8));
            Assert.That(ssim, Is.EqualTo(Direct3dgs(a, b, w, h, 1)).Within(1e-9));
        }

        /// <summary>
        /// 3DGS's _ssim written out without separability: for each output pixel the 11×11 window
        /// w(i)·w(j) over the zero-padded input (conv2d with padding 5, groups = channels), then the SSIM map's mean.
        /// </summary>
        internal static double Direct3dgs(float[] a, float[] b, int w, int h, int channels)
        {
            var g = new double[11];
            for (var i = 0; i < 11; i++) g[i] = Math.Exp(-(i - 5) * (i - 5) / (2 * 1.5 * 1.5));
            var s = 0.0;
            foreach (var v in g) s += v;
            for (var i = 0; i < 11; i++) g[i] /= s;
            double total = 0;
            for (var c = 0; c < channels; c++)
                for (var y = 0; y < h; y++)
                    for (var x = 0; x < w; x++)
                    {
                        double m1 = 0, m2 = 0, e11 = 0, e22 = 0, e12 = 0;
                        for (var i = 0; i < 11; i++)
                            for (var j = 0; j < 11; j++)
                            {
                                int yy = y + i - 5, xx = x + j - 5;
                                if (yy < 0 || yy >= h || xx < 0 || xx >= w) continue; // zero padding
                                var k = g[i] * g[j];
                                double p = a[(yy * w + xx) * channels + c], q = b[(yy * w + xx) * channels + c];
                                m1 += k * p;
                                m2 += k * q;
                                e11 += k * p * p;
                                e22 += k * q * q;
                                e12 += k * p * q;
                            }
                        double s1 = e11 - m1 * m1, s2 = e22 - m2 * m2, s12 = e12 - m1 * m2;
                        total += (2 * m1 * m2 + 0.01 * 0.01) * (2 * s12 + 0.03 * 0.03) / ((m1 * m1 + m2 * m2 + 0.01 * 0.01) * (s1 + s2 + 0.03 * 0.03));
                    }
            return total / ((double)w * h * channels);
        }

        static double Sum(Func<int, double> f)
        {
            double s = 0;
            for (var j = -5; j <= 5; j++) s += f(j);
            return s;
        }

        internal static float[] Random(int w, int h, int channels, int seed)
        {
            var random = new Random(seed);
            var a = new float[w * h * channels];
            for (var i = 0; i < a.Length; i++) a[i] = (float)random.NextDouble();
            return a;
        }
    }

    public class DepthAndNormalErrorTests
    {
        [Test]
        public void DepthFiguresFollowTheirDefinitionsOnTheMask()
        {
            var truth = new float[] { 2, 4, 0, 5, 1 };
            var rendered = new float[] { 2.2f, 3, 7, float.NaN, 9 };
            var mask = new byte[] { 255, 255, 255, 255, 0 };
            var e = DepthErrors.Compute(rendered, truth, mask);
            // Counted: pixels 0 and 1 (2 has no surface, 3 no render depth → missing, 4 outside the mask).
            Assert.That(e.Pixels, Is.EqualTo(2));
            Assert.That(e.Missing, Is.EqualTo(1));
            Assert.That(e.AbsRel, Is.EqualTo((0.2f / 2.0 + 1 / 4.0) / 2).Within(1e-7));
            Assert.That(e.Rmse, Is.EqualTo(Math.Sqrt((Math.Pow(2.2f - 2.0, 2) + 1) / 2)).Within(1e-7));
            Assert.That(e.Delta125, Is.EqualTo(0.5), "4/3 = 1.33 is not below 1.25, 2.2/2 is");
        }

        [Test]
        public void NormalAngleIsMeasuredBetweenUnitVectors()
        {
            // 90° (x against y), 0° (z against 2z), 180° (x against −x); the fourth pixel has no render normal.
            var truth = new float[] { 1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1 };
            var rendered = new float[] { 0, 1, 0, 0, 0, 2, -1, 0, 0, 0, 0, 0 };
            var e = NormalErrors.Compute(rendered, truth, null);
            Assert.That(e.Pixels, Is.EqualTo(3));
            Assert.That(e.MeanDegrees, Is.EqualTo(90).Within(1e-9));
            Assert.That(e.MedianDegrees, Is.EqualTo(90).Within(1e-9));
        }
    }
}
