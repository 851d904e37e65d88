using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The sub-frame average of analytic renders of a moving edge against the integrated blur in closed form. A grey
    /// half-plane (linear colour 0.5) covers x &lt; e(t) = x0 + L·t over a transparent background; each render's pixel
    /// [p, p + 1] holds the exact box-filtered coverage clamp(e − p, 0, 1), as supersampling approximates, rendered over
    /// black and over white like the capture. Over the shutter the coverage averages to
    /// (G(x0 + L − p) − G(x0 − p)) / L with G(u) = 0 (u ≤ 0), u²/2 (0 ≤ u ≤ 1), u − ½ (u ≥ 1).
    /// </summary>
    [TestFixture]
    public class SubFrameAccumulatorTests
    {
        const int Width = 48;
        const double Grey = 0.5;
        // The renders are halves: one rounding of a value ≤ 1 is ≤ 2⁻¹², the matting's difference of two ≤ 2⁻¹¹.
        const double HalfRounding = 1.0 / 2048;

        static double G(double u) => u <= 0 ? 0 : u <= 1 ? u * u / 2 : u - 0.5;

        static double Integrated(double x0, double pixels, double open, double close, int p) =>
            (G(x0 + pixels * close - p) - G(x0 + pixels * open - p)) / (pixels * (close - open));

        static void Render(double edge, int height, ushort[] black, ushort[] white)
        {
            for (var y = 0; y < height; y++)
                for (var x = 0; x < Width; x++)
                {
                    var coverage = Math.Max(0, Math.Min(1, edge - x));
                    var i = (y * Width + x) * 4;
                    for (var c = 0; c < 3; c++)
                    {
                        black[i + c] = SubFrameAccumulator.ToHalf(coverage * Grey);
                        white[i + c] = SubFrameAccumulator.ToHalf(coverage * Grey + (1 - coverage));
                    }
                    black[i + 3] = white[i + 3] = 0x3C00;
                }
        }

        /// <summary>The averaged coverage per pixel of each row, from the averaged pair: α = 1 − (white − black).</summary>
        static double[,] Blur(double x0, double pixels, int subFrames, int height, double readout)
        {
            var accumulator = new SubFrameAccumulator(Width, height, subFrames, readout, false);
            var black = new ushort[Width * height * 4];
            var white = new ushort[Width * height * 4];
            foreach (var frame in SubFrameSchedule.For(ShutterMotion.Centred(new UnityPose(Vector3d.Zero, Quaterniond.Identity), Vector3d.Zero, Vector3d.Zero, SceneNormalisation.Identity, 0, 1), subFrames))
            {
                Render(x0 + pixels * frame.Seconds.Value, height, black, white); // the content time runs 0 … 1 over the shutter
                accumulator.Add(frame.Index, black, white);
            }
            accumulator.Finish(black, white);
            var alpha = new double[height, Width];
            for (var y = 0; y < height; y++)
                for (var x = 0; x < Width; x++)
                {
                    var i = (y * Width + x) * 4;
                    alpha[y, x] = 1 - (HalfFloat.ToFloat(white[i]) - HalfFloat.ToFloat(black[i]));
                }
            return alpha;
        }

        static double WorstError(double pixels, int subFrames)
        {
            var worst = 0.0;
            for (var s = 0; s < 40; s++)
            {
                var x0 = 12 + s / 40.0;
                var alpha = Blur(x0, pixels, subFrames, 1, 0);
                for (var p = 0; p < Width; p++) worst = Math.Max(worst, Math.Abs(alpha[0, p] - Integrated(x0, pixels, 0, 1, p)));
            }
            return worst;
        }

        [TestCase(10.0, 16)]
        [TestCase(16.0, 16)]
        [TestCase(6.0, 32)]
        public void TheAverageIsTheIntegratedBlurWithinTheDocumentedBoundWhenSubFramesAreAPixelApart(double pixels, int subFrames)
        {
            var bound = SubFrameSchedule.ErrorBound(pixels, subFrames);
            Assert.That(bound, Is.EqualTo(pixels / (8.0 * subFrames * subFrames)), "L/(8N²) while L/N ≤ 1 pixel");
            var worst = WorstError(pixels, subFrames);
            TestContext.WriteLine("L = " + pixels + " px, N = " + subFrames + ": worst error " + worst.ToString("R") + ", bound " + bound.ToString("R"));
            Assert.That(worst, Is.LessThanOrEqualTo(bound + HalfRounding));
            Assert.That(worst, Is.GreaterThan(0.3 * bound), "the bound is the size of the real error, not a loose one");
        }

        [Test]
        public void TooFewSubFramesStayWithinHalfASubFramesShareAndAreVisiblyWorse()
        {
            // L/N = 5 px: the average is a staircase of 4 steps; the midpoint rule on a monotone edge errs by at most 1/(2N).
            var worst = WorstError(20, 4);
            Assert.That(SubFrameSchedule.ErrorBound(20, 4), Is.EqualTo(0.125));
            Assert.That(worst, Is.LessThanOrEqualTo(0.125 + HalfRounding));
            Assert.That(worst, Is.GreaterThanOrEqualTo(0.09), "ghosting, which the default of 16 sub-frames avoids for motions up to 16 px");
        }

        [Test]
        public void ARollingShutterRowSeesItsOwnSliceOfTheInterval()
        {
            // Readout 0.5: the row at v (top = 0) is exposed over [0.5 v, 0.5 v + 0.5]. Each row's blur is the integral over
            // its own window; the bottom row's edge lies almost 0.5·L further than the top row's.
            const int height = 8, subFrames = 64;
            const double readout = 0.5, pixels = 16, x0 = 10.3;
            var alpha = Blur(x0, pixels, subFrames, height, readout);
            for (var y = 0; y < height; y++)
            {
                var v = RollingShutter.V(y, height);
                var open = readout * v;
                var worst = 0.0;
                for (var p = 0; p < Width; p++) worst = Math.Max(worst, Math.Abs(alpha[y, p] - Integrated(x0, pixels, open, open + 1 - readout, p)));
                // Bins cut by the window's ends carry their share at the bin's centre: at most one bin's worth, L/N px.
                Assert.That(worst, Is.LessThan(pixels / subFrames * 0.5 + HalfRounding), "row " + y + " (v = " + v + ")");
            }
            double Sum(int row)
            {
                var sum = 0.0;
                for (var p = 0; p < Width; p++) sum += alpha[row, p];
                return sum;
            }
            // The covered area of a row is its mean edge position: x0 + L·(open + (1 − ρ)/2).
            Assert.That(Sum(0) - Sum(height - 1), Is.EqualTo(pixels * readout * (RollingShutter.V(0, height) - RollingShutter.V(height - 1, height))).Within(0.01));
        }

        [Test]
        public void RollingShutterWeightsOfARowSumToOneAndAGlobalShutterWeighsEverySubFrameEqually()
        {
            for (var n = 2; n <= 40; n += 7)
                foreach (var readout in new[] { 0.0, 0.3, 0.9 })
                    foreach (var v in new[] { 0.0001, 0.25, 0.5, 0.9999 })
                    {
                        var sum = 0.0;
                        for (var k = 0; k < n; k++) sum += RollingShutter.Weight(k, n, v, readout);
                        Assert.That(sum, Is.EqualTo(1).Within(1e-12));
                    }
            Assert.That(RollingShutter.Weight(3, 8, 0.7, 0), Is.EqualTo(0.125));
            // Readout 0.5, N = 4, top row (v → 0): window [0, 0.5] = sub-frames 0 and 1, half each.
            Assert.That(RollingShutter.Weight(0, 4, 0, 0.5), Is.EqualTo(0.5));
            Assert.That(RollingShutter.Weight(1, 4, 0, 0.5), Is.EqualTo(0.5));
            Assert.That(RollingShutter.Weight(2, 4, 0, 0.5), Is.EqualTo(0));
            Assert.That(RollingShutter.InstantNgpVector(0.25), Is.EqualTo(new[] { 0.0, 0.0, 0.25, 0.75 }));
        }

        [Test]
        public void HalvesRoundToTheNearest()
        {
            foreach (var value in new[] { 0.0, 1.0, 0.5, 0.1, 0.999, 1e-5, 3.14159, 60000.0, 1e-7 })
            {
                var half = SubFrameAccumulator.ToHalf(value);
                var back = HalfFloat.ToFloat(half);
                // Neighbours are no closer.
                Assert.That(Math.Abs(back - value), Is.LessThanOrEqualTo(Math.Abs(HalfFloat.ToFloat((ushort)(half + 1)) - value)));
                if (half > 0) Assert.That(Math.Abs(back - value), Is.LessThanOrEqualTo(Math.Abs(HalfFloat.ToFloat((ushort)(half - 1)) - value)));
            }
        }
    }
}
