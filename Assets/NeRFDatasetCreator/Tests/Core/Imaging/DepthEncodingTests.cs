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
            // k = 2. Block 1: lower-left background, the rest 5 m → 5 m (not 3.75). Block 2: 1 m and 9 m → one of
            // them by the documented order (lower-left first), never 5 m. Block 3: nothing → 0.
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
    }
}
