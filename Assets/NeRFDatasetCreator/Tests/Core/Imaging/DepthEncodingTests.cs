using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class DepthEncodingTests
    {
        static RawFrame Row(params float[] metres) => new RawFrame(metres.Length, 1, 1) { Depth = metres };

        [Test]
        public void KnownDepthsGiveMillimetres()
        {
            var frame = Row(1f, 2.5f, 0.25f, 0.0004f, 0f, -3f, float.NaN, 65.5f, 0.0126f);
            var mm = new ushort[9];
            int clamped = DepthEncoding.ToMillimetres(frame, mm);
            // 0.4 mm is a surface: written as 1, never as the background's 0. Negative and NaN are no surface.
            Assert.That(mm, Is.EqualTo(new ushort[] { 1000, 2500, 250, 1, 0, 0, 0, 65500, 13 }));
            Assert.That(clamped, Is.EqualTo(0));
        }

        /// <summary>
        /// Supersampling 1 (the capture's depth pass) over several rows of odd length, at scale 1 and not: each pixel
        /// is its own sample from the row mirrored top to bottom, round(z·1000) halves up, 1 below 0.5 mm, clamped
        /// and counted beyond 65.535 m; no surface for 0, negatives and NaN.
        /// </summary>
        [TestCase(1.0)]
        [TestCase(0.37)]
        public void OneSamplePerPixelRowsGiveEachPixelsMillimetres(double scale)
        {
            const int w = 13, h = 7;
            var random = new SeededRandom(5);
            float[] specials = { 0f, -0f, -1f, float.NaN, float.PositiveInfinity, 0.0004f, 0.0015f, 0.0025f, 65.5345f, 65.5355f, 200f };
            var depth = new float[w * h];
            for (int i = 0; i < depth.Length; i++)
                depth[i] = random.NextUInt64() % 3 == 0 ? specials[random.NextUInt64() % (ulong)specials.Length] : (float)(random.NextDouble() * 80);
            var mm = new ushort[w * h];
            int clamped = DepthEncoding.ToMillimetres(new RawFrame(w, h, 1) { Depth = depth }, mm, scale);

            int expectedClamped = 0;
            for (int oy = 0; oy < h; oy++)
                for (int ox = 0; ox < w; ox++)
                {
                    float z = depth[(h - 1 - oy) * w + ox]; // source rows are bottom-up
                    double metres = scale == 1 ? z : (float)(z * scale);
                    int expected = !(metres > 0) ? 0 : System.Math.Max(1, (int)System.Math.Floor((float)metres * 1000f + 0.5f));
                    if (expected > 65535)
                    {
                        expected = 65535;
                        expectedClamped++;
                    }
                    Assert.That(mm[oy * w + ox], Is.EqualTo(expected), $"pixel ({ox}, {oy}) from {z:R}");
                }
            Assert.That(clamped, Is.EqualTo(expectedClamped));
            Assert.That(expectedClamped, Is.GreaterThan(0), "some depths are beyond the 16-bit range");
        }

        [Test]
        public void DepthsBeyond65Point535MetresAreClampedAndCounted()
        {
            var frame = Row(65.535f, 65.6f, 100f, float.PositiveInfinity, 3f);
            var mm = new ushort[5];
            int clamped = DepthEncoding.ToMillimetres(frame, mm);
            Assert.That(mm, Is.EqualTo(new ushort[] { 65535, 65535, 65535, 65535, 3000 }));
            Assert.That(clamped, Is.EqualTo(3));
        }

        [Test]
        public void AnEdgeBlockTakesOneSurfaceNeverTheMean()
        {
            // k = 2. Block 1: lower-left background, the rest 5 m → 5 m (not 3.75). Block 2: 1 m and 9 m → the nearest
            // surface, 1 m, never 5 m (nor the harmonic mean 1.8 m). Block 3: nothing → 0.
            var frame = FrameBuilder.Frame(3, 1, 2);
            frame.Depth = new float[frame.Width * frame.Height];
            void Set(int x, int yTop, float z) => frame.Depth[FrameBuilder.Index(frame, x, yTop)] = z;
            Set(0, 1, 0f); Set(1, 1, 5f); Set(0, 0, 5f); Set(1, 0, 5f);
            Set(2, 1, 1f); Set(3, 1, 9f); Set(2, 0, 9f); Set(3, 0, 1f);
            var mm = new ushort[3];
            DepthEncoding.ToMillimetres(frame, mm);
            Assert.That(mm, Is.EqualTo(new ushort[] { 5000, 1000, 0 }));
        }

        [Test]
        public void OddSupersamplingTakesTheCentreSample()
        {
            var frame = FrameBuilder.Frame(1, 1, 3);
            frame.Depth = new float[9];
            for (int i = 0; i < 9; i++) frame.Depth[i] = 7f;
            frame.Depth[4] = 2f;
            var mm = new ushort[1];
            DepthEncoding.ToMillimetres(frame, mm);
            Assert.That(mm[0], Is.EqualTo(2000));
        }

        [Test]
        public void EvenSupersamplingPrefersTheCentralFourSamples()
        {
            // k = 4: the ring of 12 outer samples at 8 m, the central 2×2 at 3 m.
            var frame = FrameBuilder.Frame(1, 1, 4);
            frame.Depth = new float[16];
            for (int y = 0; y < 4; y++)
            for (int x = 0; x < 4; x++)
                frame.Depth[y * 4 + x] = x >= 1 && x <= 2 && y >= 1 && y <= 2 ? 3f : 8f;
            var mm = new ushort[1];
            DepthEncoding.ToMillimetres(frame, mm);
            Assert.That(mm[0], Is.EqualTo(3000));
        }

        [Test]
        public void FloatDepthIsPointSampledUnclampedInEitherRowOrder()
        {
            // k = 2, output 2×2. Readback rows are bottom-up; each block's lower-left sample is its first candidate.
            // Bottom blocks: (100 m, background); top blocks: (1.5 m, NaN → background).
            var frame = FrameBuilder.Frame(2, 2, 2);
            frame.Depth = new float[16];
            frame.Depth[FrameBuilder.Index(frame, 0, 3)] = 100f;
            frame.Depth[FrameBuilder.Index(frame, 1, 0)] = 1.5f;
            frame.Depth[FrameBuilder.Index(frame, 2, 1)] = float.NaN;
            var topFirst = new float[4];
            var bottomFirst = new float[4];
            DepthEncoding.ToMetres(frame, topFirst, RowDirection.TopRowFirst);
            DepthEncoding.ToMetres(frame, bottomFirst, RowDirection.BottomRowFirst);
            Assert.That(topFirst, Is.EqualTo(new[] { 1.5f, 0f, 100f, 0f }));
            Assert.That(bottomFirst, Is.EqualTo(new[] { 100f, 0f, 1.5f, 0f }));
        }

        /// <summary>
        /// Issue 32 item 19. A slanted plane seen by a pinhole has 1/z affine in screen position; at k = 2 the block's four
        /// samples sit at the pixel centre ± ¼ px, so the harmonic mean of their depths is the plane's depth at the centre
        /// (to float rounding), where the lower-left sample alone lay a quarter pixel off it (1/z changing by 0.006 per
        /// pixel across and 0.003 down: ~0.2 % off at k = 2; the block's samples stay within the 2 % of one smooth surface).
        /// </summary>
        [TestCase(2)]
        [TestCase(4)]
        public void EvenSupersamplingGivesAPlanesDepthAtThePixelCentre(int k)
        {
            const int w = 5, h = 4;
            var frame = FrameBuilder.Frame(w, h, k);
            frame.Depth = new float[frame.Width * frame.Height];
            // 1/z at continuous output position (i, j), top-left origin: a plane ~2.4 units away.
            double InverseZ(double i, double j) => 0.4 + 0.006 * i + 0.003 * j;
            for (var ys = 0; ys < frame.Height; ys++)
                for (var xs = 0; xs < frame.Width; xs++)
                    frame.Depth[FrameBuilder.Index(frame, xs, ys)] = (float)(1 / InverseZ((xs + 0.5) / k, (ys + 0.5) / k));
            var metres = new float[w * h];
            DepthEncoding.ToMetres(frame, metres, RowDirection.TopRowFirst);
            for (var oy = 0; oy < h; oy++)
                for (var ox = 0; ox < w; ox++)
                {
                    var centre = 1 / InverseZ(ox + 0.5, oy + 0.5);
                    Assert.That(metres[oy * w + ox], Is.EqualTo(centre).Within(2e-6 * centre), $"pixel ({ox}, {oy})");
                }
        }

        [Test]
        public void AStepInsideTheCentralSamplesTakesTheNearestSurface()
        {
            // k = 2: 2 m and 2.1 m (5 % apart: a step, not one surface) → 2 m, never their mean; 3 m and 3.03 m (1 %: one
            // slanted surface) → their harmonic mean 2 / (1/3 + 1/3.03).
            var frame = FrameBuilder.Frame(2, 1, 2);
            frame.Depth = new float[frame.Width * frame.Height];
            void Set(int x, int yTop, float z) => frame.Depth[FrameBuilder.Index(frame, x, yTop)] = z;
            Set(0, 0, 2.1f); Set(1, 0, 2f); Set(0, 1, 2.1f); Set(1, 1, 2f);
            Set(2, 0, 3f); Set(3, 0, 3.03f); Set(2, 1, 3f); Set(3, 1, 3.03f);
            var metres = new float[2];
            DepthEncoding.ToMetres(frame, metres, RowDirection.TopRowFirst);
            Assert.That(metres[0], Is.EqualTo(2f));
            Assert.That(metres[1], Is.EqualTo(4 / (2 / 3.0 + 2 / 3.03)).Within(1e-6));
        }
    }
}
