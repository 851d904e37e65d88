using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class StraightAlphaTests
    {
        [Test]
        public void HalfCoveredEdgeKeepsItsFullColourWithAlpha128()
        {
            // Output 2×1 at k = 2: the left block fully covered, the right block only in its left column (an edge).
            var frame = FrameBuilder.Frame(2, 1, 2).WithSrgb();
            for (int y = 0; y < 2; y++)
            {
                frame.Cover(0, y, 200, 100, 50);
                frame.Cover(1, y, 200, 100, 50);
                frame.Cover(2, y, 200, 100, 50);
            }
            var rgba = new byte[2 * 4];
            StraightAlpha.Resolve(frame, rgba);
            Assert.That(rgba, Is.EqualTo(new byte[] { 200, 100, 50, 255, 200, 100, 50, 128 }));
        }

        [Test]
        public void EveryCoverageOfA4x4BlockGivesBackTheSurfaceColour()
        {
            // k = 4: 1…16 covered samples of one colour; colour must stay exact, alpha = round(255·n/16).
            for (int covered = 1; covered <= 16; covered++)
            {
                var frame = FrameBuilder.Frame(1, 1, 4).WithSrgb();
                for (int i = 0; i < covered; i++) frame.Cover(i % 4, i / 4, 37, 180, 251);
                var rgba = new byte[4];
                StraightAlpha.Resolve(frame, rgba);
                int expectedAlpha = (int)System.Math.Floor(255.0 * covered / 16 + 0.5);
                Assert.That(rgba, Is.EqualTo(new byte[] { 37, 180, 251, (byte)expectedAlpha }), covered + " of 16 covered");
            }
        }

        [Test]
        public void PremultipliedLinearInputRoundTripsWithinOneLsbWhereAlphaIsAtLeast16()
        {
            // k = 1 with fractional coverage: colour given premultiplied (C·a, linear floats), mask = a.
            int worst = 0;
            for (int alpha = 16; alpha <= 255; alpha++)
            for (int c = 0; c <= 255; c += 5)
            {
                var frame = FrameBuilder.Frame(1, 1, 1);
                double a = alpha / 255.0;
                float straight = Srgb.Decode((byte)c);
                frame.ColorLinear = new[] { (float)(straight * a), (float)(straight * a), (float)(straight * a), 1f };
                frame.Mask = new[] { (byte)alpha };
                frame.MaskBytesPerPixel = 1;
                var rgba = new byte[4];
                StraightAlpha.Resolve(frame, rgba);
                Assert.That(rgba[3], Is.EqualTo((byte)alpha));
                worst = System.Math.Max(worst, System.Math.Abs(rgba[0] - c));
            }
            Assert.That(worst, Is.LessThanOrEqualTo(1));
        }

        [Test]
        public void AveragesInLinearLightNotInSrgb()
        {
            // Two white and two black samples, all covered: linear mean 0.5 encodes to 188; averaging the bytes
            // would give 128.
            var frame = FrameBuilder.Frame(1, 1, 2).WithSrgb();
            frame.Cover(0, 0, 255, 255, 255);
            frame.Cover(1, 0, 255, 255, 255);
            frame.Cover(0, 1, 0, 0, 0);
            frame.Cover(1, 1, 0, 0, 0);
            var rgba = new byte[4];
            StraightAlpha.Resolve(frame, rgba);
            Assert.That(rgba, Is.EqualTo(new byte[] { 188, 188, 188, 255 }));
        }

        [Test]
        public void AlphaComesFromTheMaskNotFromTheLitShader()
        {
            // Colour alpha 255 with no coverage, and colour alpha 0 with full coverage.
            var frame = FrameBuilder.Frame(2, 1, 1).WithSrgb();
            frame.ColorSrgb[4 * FrameBuilder.Index(frame, 0, 0) + 3] = 255;
            frame.ColorSrgb[4 * FrameBuilder.Index(frame, 0, 0)] = 90; // stray colour outside the mask
            frame.Cover(1, 0, 10, 20, 30);
            frame.ColorSrgb[4 * FrameBuilder.Index(frame, 1, 0) + 3] = 0;
            var rgba = new byte[8];
            StraightAlpha.Resolve(frame, rgba);
            Assert.That(rgba, Is.EqualTo(new byte[] { 0, 0, 0, 0, 10, 20, 30, 255 }));
        }

        [Test]
        public void RowsAreFlippedToTopFirst()
        {
            // Bottom-up source: row 0 (bottom) covered red. In the output the red pixel must be the bottom row.
            var frame = new RawFrame(1, 2, 1).WithSrgb();
            frame.ColorSrgb[0] = 255;
            frame.Mask[0] = 255;
            var rgba = new byte[8];
            StraightAlpha.Resolve(frame, rgba);
            Assert.That(rgba, Is.EqualTo(new byte[] { 0, 0, 0, 0, 255, 0, 0, 255 }));
        }

        [Test]
        public void SolidBackgroundIsCompositedInLinearLight()
        {
            // Red surface over half of the block, white background: R stays 1; G and B are 0.5 linear → 188.
            var frame = FrameBuilder.Frame(2, 1, 2).WithSrgb();
            frame.Cover(0, 0, 255, 0, 0);
            frame.Cover(0, 1, 255, 0, 0);
            var rgba = new byte[8];
            StraightAlpha.Resolve(frame, rgba, Background.SolidSrgb(255, 255, 255));
            Assert.That(rgba, Is.EqualTo(new byte[] { 255, 188, 188, 255, 255, 255, 255, 255 }));
        }

        [Test]
        public void LinearFloatColourIsClampedAndEncoded()
        {
            var frame = FrameBuilder.Frame(1, 1, 1);
            frame.ColorLinear = new[] { 4f, 0.5f, float.NaN, 0f };
            frame.Mask = new byte[] { 255, 0, 0, 0 };
            var rgba = new byte[4];
            StraightAlpha.Resolve(frame, rgba);
            Assert.That(rgba, Is.EqualTo(new byte[] { 255, 188, 0, 255 }));
        }

        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        public void MatchesTheFormulaInDoublePrecisionOnRandomFrames(int k)
        {
            // Random colours and random binary or fractional coverage; the expectation is §4.5 of the design written
            // out directly: decode, mean, divide by mean coverage, clamp, encode; alpha = round(255·mean coverage).
            const int ow = 9, oh = 7;
            var frame = FrameBuilder.Frame(ow, oh, k).WithSrgb();
            var random = new SeededRandom(100 + k);
            for (int i = 0; i < frame.Width * frame.Height; i++)
            {
                ulong bits = random.NextUInt64();
                int kind = (int)(bits % 4);
                frame.Mask[4 * i] = kind == 0 ? (byte)0 : kind == 1 ? (byte)(bits >> 8) : (byte)255;
                for (int c = 0; c < 3; c++) frame.ColorSrgb[4 * i + c] = frame.Mask[4 * i] == 0 ? (byte)0 : (byte)(bits >> (16 + 8 * c));
            }
            var rgba = new byte[ow * oh * 4];
            var mask = new byte[ow * oh];
            StraightAlpha.Resolve(frame, rgba, Background.Transparent, mask);

            for (int y = 0; y < oh; y++)
            for (int x = 0; x < ow; x++)
            {
                int maskSum = 0;
                var sum = new double[3];
                for (int sy = 0; sy < k; sy++)
                for (int sx = 0; sx < k; sx++)
                {
                    int p = FrameBuilder.Index(frame, x * k + sx, y * k + sy);
                    maskSum += frame.Mask[4 * p];
                    for (int c = 0; c < 3; c++) sum[c] += Srgb.DecodeExact(frame.ColorSrgb[4 * p + c] / 255.0);
                }
                // Coverage in [0, 1]; alpha rounds the exact fraction maskSum / k² (halves up).
                double coverage = maskSum / (255.0 * k * k);
                int o = (y * ow + x) * 4;
                int alpha = (int)System.Math.Floor((double)maskSum / (k * k) + 0.5);
                Assert.That(rgba[o + 3], Is.EqualTo(alpha), $"alpha at {x},{y}");
                Assert.That(mask[y * ow + x], Is.EqualTo(alpha), $"mask at {x},{y}");
                for (int c = 0; c < 3; c++)
                {
                    int expected = alpha == 0 ? 0 : Srgb.EncodeByteExact(System.Math.Min(1, sum[c] / (k * k) / coverage));
                    Assert.That(rgba[o + c], Is.EqualTo(expected).Within(1), $"channel {c} at {x},{y}");
                }
            }
        }

        [Test]
        public void MissingMaskIsReportedByField()
        {
            var frame = FrameBuilder.Frame(1, 1, 1);
            frame.ColorSrgb = new byte[4];
            var e = Assert.Throws<InvalidParameterException>(() => StraightAlpha.Resolve(frame, new byte[4]));
            Assert.That(e.Message, Does.Contain("frame.Mask"));
        }

        [Test]
        public void TooSmallOutputIsReportedByField()
        {
            var frame = FrameBuilder.Frame(2, 2, 1).WithSrgb();
            var e = Assert.Throws<InvalidParameterException>(() => StraightAlpha.Resolve(frame, new byte[15]));
            Assert.That(e.Message, Does.Contain("rgba").And.Contain("16"));
        }
    }
}
