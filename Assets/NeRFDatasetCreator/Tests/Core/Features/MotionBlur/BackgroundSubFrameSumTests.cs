using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 32, R4-2: the sub-frame sum that runs beside the render thread gives exactly the averages of the
    /// accumulator as specified (each half decoded to linear, weighted, summed, divided by the row's weight, rounded to
    /// the nearest half), view after view with one set of buffers, allocates nothing per sub-frame, and reports a
    /// worker's failure to the render thread.
    /// </summary>
    [TestFixture]
    public class BackgroundSubFrameSumTests
    {
        const int W = 24, H = 10;

        /// <summary>Sub-frame k of a view: every channel a different half in [0, 1.5], some over 1, some zero.</summary>
        static void Render(int view, int k, ushort[] black, ushort[] white)
        {
            var random = new Random(1000 * view + k);
            for (var i = 0; i < black.Length; i++)
            {
                black[i] = (i & 3) == 3 ? (ushort)0x3C00 : SubFrameAccumulator.ToHalf(random.Next(4) == 0 ? 0 : random.NextDouble() * 1.5);
                white[i] = (i & 3) == 3 ? (ushort)0x3C00 : SubFrameAccumulator.ToHalf(random.NextDouble() * 1.5);
            }
        }

        /// <summary>The order the test adds a view's sub-frames in: not 0, 1, 2 …, as nothing requires that.</summary>
        static int Order(int j, int subFrames) => subFrames - 1 - j;

        /// <summary>The average as the accumulator's contract states it, computed here sample by sample, summed in the order added.</summary>
        static ushort[] Expected(int view, int subFrames, double readout, bool gamma, bool overWhite)
        {
            var frames = new ushort[subFrames][];
            for (var k = 0; k < subFrames; k++)
            {
                var b = new ushort[W * H * 4];
                var w = new ushort[W * H * 4];
                Render(view, k, b, w);
                frames[k] = overWhite ? w : b;
            }
            var result = new ushort[W * H * 4];
            for (var y = 0; y < H; y++)
                for (var x = 0; x < W; x++)
                {
                    var i = (y * W + x) * 4;
                    for (var c = 0; c < 3; c++)
                    {
                        double sum = 0, weights = 0;
                        for (var j = 0; j < subFrames; j++)
                        {
                            var k = Order(j, subFrames);
                            var weight = RollingShutter.Weight(k, subFrames, RollingShutter.V(y, H), readout);
                            if (weight == 0) continue;
                            double value = HalfFloat.ToFloat(frames[k][i + c]);
                            if (gamma) value = value <= 0 ? 0 : Srgb.DecodeExact(Math.Min(1, value));
                            sum += weight * value;
                            weights += weight;
                        }
                        var mean = weights > 0 ? sum * (1 / weights) : 0;
                        if (gamma) mean = Srgb.EncodeExact(Math.Max(0, Math.Min(1, mean)));
                        result[i + c] = SubFrameAccumulator.ToHalf(mean);
                    }
                    result[i + 3] = 0x3C00;
                }
            return result;
        }

        static void View(BackgroundSubFrameSum sum, int view, int subFrames, ushort[] black, ushort[] white)
        {
            sum.Begin(subFrames);
            for (var j = 0; j < subFrames; j++)
            {
                var k = Order(j, subFrames);
                var input = sum.TakeInput(out var b, out var w);
                Render(view, k, b, w);
                sum.Add(input, k);
            }
            sum.Finish(black, white);
        }

        [TestCase(true, 0.0, false)]
        [TestCase(false, 0.0, false)]
        [TestCase(true, 0.4, false)]
        [TestCase(true, 0.0, true)]
        [TestCase(false, 0.3, true)]
        public void ViewAfterViewTheAveragesAreThoseOfTheContract(bool background, double readout, bool gamma)
        {
            using (var sum = new BackgroundSubFrameSum(W, H, readout, gamma, background))
            {
                // Different counts in turn: the sums of one view must not leak into the next.
                foreach (var (view, subFrames) in new[] { (1, 5), (2, 3), (3, 8), (4, 1) })
                {
                    var black = new ushort[W * H * 4];
                    var white = new ushort[W * H * 4];
                    View(sum, view, subFrames, black, white);
                    sum.WaitIdle();
                    Assert.That(black, Is.EqualTo(Expected(view, subFrames, readout, gamma, false)), "over black, view " + view);
                    Assert.That(white, Is.EqualTo(Expected(view, subFrames, readout, gamma, true)), "over white, view " + view);
                }
            }
        }

        [Test]
        public void ASubFrameAllocatesNothing()
        {
            using (var sum = new BackgroundSubFrameSum(W, H, 0.25, false, background: false))
            {
                var black = new ushort[W * H * 4];
                var white = new ushort[W * H * 4];
                View(sum, 1, 16, black, white); // first use: the colour space's table, the sub-frame flags
                var renderBlack = new ushort[W * H * 4];
                var renderWhite = new ushort[W * H * 4];
                Render(2, 0, renderBlack, renderWhite);
                var before = GC.GetAllocatedBytesForCurrentThread();
                sum.Begin(16);
                for (var k = 0; k < 16; k++)
                {
                    var input = sum.TakeInput(out var b, out var w);
                    Array.Copy(renderBlack, b, b.Length);
                    Array.Copy(renderWhite, w, w.Length);
                    sum.Add(input, k);
                }
                sum.Finish(black, white);
                sum.WaitIdle();
                Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.EqualTo(0), "bytes allocated by a view of 16 sub-frames");
            }
        }

        [Test]
        public void AFailureOnTheWorkerIsThrownToTheRenderThread()
        {
            using (var sum = new BackgroundSubFrameSum(W, H, 0, false))
            {
                sum.Begin(2);
                for (var j = 0; j < 2; j++)
                {
                    var input = sum.TakeInput(out var b, out var w);
                    sum.Add(input, 0); // sub-frame 0 twice
                }
                var e = Assert.Throws<SubFrameSumException>(() => sum.WaitIdle());
                Assert.That(e.Message, Does.Contain("Averaging the motion-blur sub-frames failed").And.Contain("added twice"));
                Assert.Throws<SubFrameSumException>(() => sum.Begin(1), "every later call reports it too");
            }
        }

        [Test]
        public void HalvesRoundToTheNearestEvenEverywhere()
        {
            // Every finite half, the midpoints to its neighbour and the doubles just either side of them, both signs.
            for (var h = 0; h < 0x7BFF; h++)
            {
                double value = HalfFloat.ToFloat((ushort)h), next = HalfFloat.ToFloat((ushort)(h + 1));
                var mid = (value + next) / 2; // exact: both have few significant bits
                var even = (h & 1) == 0 ? h : h + 1;
                foreach (var sign in new[] { 1, -1 })
                {
                    var bit = sign < 0 ? 0x8000 : 0;
                    if (h > 0) Assert.That(SubFrameAccumulator.ToHalf(sign * value), Is.EqualTo(h | bit), "the half " + h + " itself");
                    Assert.That(SubFrameAccumulator.ToHalf(sign * mid), Is.EqualTo(even | bit), "the midpoint above " + h);
                    Assert.That(SubFrameAccumulator.ToHalf(sign * Below(mid)), Is.EqualTo(h | bit), "just below the midpoint above " + h);
                    Assert.That(SubFrameAccumulator.ToHalf(sign * Above(mid)), Is.EqualTo((h + 1) | bit), "just above the midpoint above " + h);
                }
            }
            Assert.That(SubFrameAccumulator.ToHalf(0.0), Is.EqualTo(0));
            Assert.That(SubFrameAccumulator.ToHalf(-0.0), Is.EqualTo(0), "−0 as before");
            Assert.That(SubFrameAccumulator.ToHalf(Math.Pow(2, -25)), Is.EqualTo(0), "half the smallest subnormal ties to 0");
            Assert.That(SubFrameAccumulator.ToHalf(Above(Math.Pow(2, -25))), Is.EqualTo(1));
            Assert.That(SubFrameAccumulator.ToHalf(1e-30), Is.EqualTo(0));
            Assert.That(SubFrameAccumulator.ToHalf(Below(65520)), Is.EqualTo(0x7BFF), "just below the midpoint to infinity");
            Assert.That(SubFrameAccumulator.ToHalf(65520), Is.EqualTo(0x7C00), "the midpoint to infinity ties up");
            Assert.That(SubFrameAccumulator.ToHalf(1e10), Is.EqualTo(0x7C00));
            Assert.That(SubFrameAccumulator.ToHalf(-1e10), Is.EqualTo(0xFC00));
            Assert.That(SubFrameAccumulator.ToHalf(double.PositiveInfinity), Is.EqualTo(0x7C00));
            Assert.That(SubFrameAccumulator.ToHalf(double.NaN), Is.EqualTo(0x7E00));
        }

        static double Above(double v) => BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(v) + 1);

        static double Below(double v) => BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(v) - 1);
    }
}
