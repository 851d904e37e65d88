using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Expected bytes are derived by hand from the compositing equation out = K + T·B (K = render over black,
    /// T = W − K) and the sRGB formula round(255·(1.055·l^(1/2.4) − 0.055)); every input value is exact in half precision.
    /// </summary>
    public class DifferenceMattingTests
    {
        // sRGB bytes of the linear values used below (formula, worked out once): 0.25 → 137, 0.4 → 170 (169.62),
        // 0.5 → 188 (187.52), 0.625 → 207 (207.15), 0.125 → 99 (99.09), 0.875 → 240 (240.44), 0.8333 → 235 (235.32).

        [Test]
        public void OpaqueContentKeepsItsColourWithAlpha255()
        {
            var frame = Pair(1, 1, 1);
            Sample(frame, 0, 0, black: new[] { 0.5f, 0.25f, 1f }, white: new[] { 0.5f, 0.25f, 1f });
            Assert.That(Resolve(frame), Is.EqualTo(new byte[] { 188, 137, 255, 255 }));
        }

        [Test]
        public void ASkyRenderUsedAsBothHalvesIsOpaqueEverywhereEvenWhereItIsBlack()
        {
            // The sky background renders the colour pass once and hands the same image as both halves (K = W): T = 0,
            // so alpha = 1 and colour = K in every sample — a black patch of sky is opaque black, not transparent,
            // and an HDR sun above 1 is clamped after averaging. Linear 0.25 → 137 (see above).
            var frame = Pair(3, 1, 1);
            Sample(frame, 0, 0, black: new[] { 0f, 0f, 0f }, white: new[] { 0f, 0f, 0f });
            Sample(frame, 1, 0, black: new[] { 0.25f, 0.5f, 1f }, white: new[] { 0.25f, 0.5f, 1f });
            Sample(frame, 2, 0, black: new[] { 4f, 4f, 2f }, white: new[] { 4f, 4f, 2f });
            Assert.That(Resolve(frame), Is.EqualTo(new byte[] { 0, 0, 0, 255, 137, 188, 255, 255, 255, 255, 255, 255 }));
        }

        [Test]
        public void EmptyPixelsAndLightWithoutCoverageAreFullyTransparentZeros()
        {
            // Left: nothing (K = 0, W = 1). Right: additive glow, K = 0.25, W = 1.25 → T = 1, alpha 0.
            var frame = Pair(2, 1, 1);
            Sample(frame, 0, 0, black: new[] { 0f, 0f, 0f }, white: new[] { 1f, 1f, 1f });
            Sample(frame, 1, 0, black: new[] { 0.25f, 0.25f, 0.25f }, white: new[] { 1.25f, 1.25f, 1.25f });
            Assert.That(Resolve(frame), Is.EqualTo(new byte[8]));
        }

        [Test]
        public void HalfCoveredEdgeAtK2KeepsItsFullColourWithAlpha128()
        {
            // Left column of the 2×2 block covered by an opaque surface of linear 0.5, right column empty:
            // alpha = 2/4 → round(127.5) = 128; colour = Σ premultiplied / Σ alpha = 2·0.5 / 2 = 0.5 → 188.
            var frame = Pair(1, 1, 2);
            for (int y = 0; y < 2; y++)
            {
                Sample(frame, 0, y, black: new[] { 0.5f, 0.5f, 0.5f }, white: new[] { 0.5f, 0.5f, 0.5f });
                Sample(frame, 1, y, black: new[] { 0f, 0f, 0f }, white: new[] { 1f, 1f, 1f });
            }
            Assert.That(Resolve(frame), Is.EqualTo(new byte[] { 188, 188, 188, 128 }));
        }

        [Test]
        public void SupersampledBlockIsAveragedAsPremultipliedColourInLinearLight()
        {
            // 2×2 block: opaque white (K = W = 1); grey glass of alpha 0.5 and straight colour 0.5 (K = 0.25, W = 0.75);
            // two empty samples. Σ alpha = 1.5 → alpha = round(255·1.5/4 = 95.625) = 96;
            // Σ premultiplied = 1 + 0.25 = 1.25 → straight 1.25/1.5 = 0.8333 → 235. Averaging straight colours
            // instead would give (1 + 0.5)/2 = 0.75 (225), averaging sRGB bytes something else again.
            var frame = Pair(1, 1, 2);
            Sample(frame, 0, 0, black: new[] { 1f, 1f, 1f }, white: new[] { 1f, 1f, 1f });
            Sample(frame, 1, 0, black: new[] { 0.25f, 0.25f, 0.25f }, white: new[] { 0.75f, 0.75f, 0.75f });
            Sample(frame, 0, 1, black: new[] { 0f, 0f, 0f }, white: new[] { 1f, 1f, 1f });
            Sample(frame, 1, 1, black: new[] { 0f, 0f, 0f }, white: new[] { 1f, 1f, 1f });
            Assert.That(Resolve(frame), Is.EqualTo(new byte[] { 235, 235, 235, 96 }));
        }

        [Test]
        public void TwoOpaqueColoursInOneBlockAverageInLinearLightNotInSrgbBytes()
        {
            // Red and blue halves: linear mean (0.5, 0, 0.5) → (188, 0, 188); byte averaging would give 128.
            var frame = Pair(1, 1, 2);
            for (int y = 0; y < 2; y++)
            {
                Sample(frame, 0, y, black: new[] { 1f, 0f, 0f }, white: new[] { 1f, 0f, 0f });
                Sample(frame, 1, y, black: new[] { 0f, 0f, 1f }, white: new[] { 0f, 0f, 1f });
            }
            Assert.That(Resolve(frame), Is.EqualTo(new byte[] { 188, 0, 188, 255 }));
        }

        [Test]
        public void BlendedGlassIsUnpremultiplied()
        {
            // Glass of alpha 0.5 and straight colour 0.625 drawn with Blend SrcAlpha OneMinusSrcAlpha:
            // K = 0.3125, W = 0.3125 + 0.5 = 0.8125 → alpha 0.5 (128), colour 0.3125/0.5 = 0.625 → 207.
            var frame = Pair(1, 1, 1);
            Sample(frame, 0, 0, black: new[] { 0.3125f, 0.3125f, 0.3125f }, white: new[] { 0.8125f, 0.8125f, 0.8125f });
            Assert.That(Resolve(frame), Is.EqualTo(new byte[] { 207, 207, 207, 128 }));
        }

        [Test]
        public void TintedGlassGetsTheLeastSquaresSingleAlpha()
        {
            // Red glass drawn with a multiplicative blend: transmits T = (0.875, 0.125, 0.125), adds nothing (K = 0).
            // One alpha cannot hold three transmissions: alpha = 1 − mean(T) = 0.625 (159.375 → 159),
            // premultiplied = (K + W − (1 − alpha))/2 = (0.25, −0.125, −0.125) → straight (0.4, −0.2, −0.2) → (170, 0, 0).
            // Composited by a loader this reads (0.625, 0.375, 0.375) over white and (0.25, 0, 0) over black instead of
            // (0.875, 0.125, 0.125) and (0, 0, 0): the error is shared between the two backgrounds.
            var frame = Pair(1, 1, 1);
            Sample(frame, 0, 0, black: new[] { 0f, 0f, 0f }, white: new[] { 0.875f, 0.125f, 0.125f });
            Assert.That(Resolve(frame), Is.EqualTo(new byte[] { 170, 0, 0, 159 }));
        }

        [Test]
        public void SolidBackgroundCompositesEachChannelExactlyTintedGlassIncluded()
        {
            // Over white (B = 1): K + T·B = (0.875, 0.125, 0.125) → (240, 99, 99), alpha 255: what rendering over white gives.
            var frame = Pair(2, 1, 1);
            Sample(frame, 0, 0, black: new[] { 0f, 0f, 0f }, white: new[] { 0.875f, 0.125f, 0.125f });
            Sample(frame, 1, 0, black: new[] { 0f, 0f, 0f }, white: new[] { 1f, 1f, 1f });
            Assert.That(Resolve(frame, Background.SolidSrgb(255, 255, 255)),
                Is.EqualTo(new byte[] { 240, 99, 99, 255, 255, 255, 255, 255 }));
        }

        [Test]
        public void GammaProjectValuesAreUnpremultipliedInGammaSpaceAndAveragedInLinearLight()
        {
            // Opaque gamma-space 0.625 → byte round(0.625·255 = 159.375) = 159 (decoded, then encoded again).
            var frame = Pair(1, 1, 1);
            frame.ColorIsGammaEncoded = true;
            Sample(frame, 0, 0, black: new[] { 0.625f, 0.625f, 0.625f }, white: new[] { 0.625f, 0.625f, 0.625f });
            Assert.That(Resolve(frame), Is.EqualTo(new byte[] { 159, 159, 159, 255 }));

            // k = 2, gamma space: top row opaque white and opaque black, bottom row empty → alpha 2/4 (128) and the
            // linear mean of the covered samples, 0.5 → 188 (the gamma-space mean would give 128).
            var mixed = Pair(1, 1, 2);
            mixed.ColorIsGammaEncoded = true;
            Sample(mixed, 0, 0, black: new[] { 1f, 1f, 1f }, white: new[] { 1f, 1f, 1f });
            Sample(mixed, 1, 0, black: new[] { 0f, 0f, 0f }, white: new[] { 0f, 0f, 0f });
            Sample(mixed, 0, 1, black: new[] { 0f, 0f, 0f }, white: new[] { 1f, 1f, 1f });
            Sample(mixed, 1, 1, black: new[] { 0f, 0f, 0f }, white: new[] { 1f, 1f, 1f });
            Assert.That(Resolve(mixed), Is.EqualTo(new byte[] { 188, 188, 188, 128 }));
        }

        [Test]
        public void RowsComeOutTopFirst()
        {
            // Output 1×2: the top pixel (last row of the bottom-up input) opaque, the bottom one empty.
            var frame = Pair(1, 2, 1);
            Sample(frame, 0, 0, black: new[] { 1f, 1f, 1f }, white: new[] { 1f, 1f, 1f });
            Sample(frame, 0, 1, black: new[] { 0f, 0f, 0f }, white: new[] { 1f, 1f, 1f });
            Assert.That(Resolve(frame), Is.EqualTo(new byte[] { 255, 255, 255, 255, 0, 0, 0, 0 }));
        }

        [Test]
        public void AMissingRenderIsNamed()
        {
            var frame = Pair(1, 1, 1);
            frame.ColorOverWhite = null;
            var e = Assert.Throws<InvalidParameterException>(() => Resolve(frame));
            Assert.That(e.Message, Does.Contain("frame.ColorOverWhite"));
            var none = new RawFrame(1, 1, 1);
            e = Assert.Throws<InvalidParameterException>(() => Resolve(none));
            Assert.That(e.Message, Does.Contain("frame.ColorOverBlack"));
        }

        static RawFrame Pair(int outputWidth, int outputHeight, int k)
        {
            var frame = FrameBuilder.Frame(outputWidth, outputHeight, k);
            frame.ColorOverBlack = new ushort[frame.Width * frame.Height * 4];
            frame.ColorOverWhite = new ushort[frame.Width * frame.Height * 4];
            return frame;
        }

        /// <summary>Sets one sample (x, row from the top) of both renders; alpha channels get garbage that must be ignored.</summary>
        static void Sample(RawFrame frame, int x, int yFromTop, float[] black, float[] white)
        {
            int p = 4 * FrameBuilder.Index(frame, x, yFromTop);
            for (int c = 0; c < 3; c++)
            {
                frame.ColorOverBlack[p + c] = ToHalf(black[c]);
                frame.ColorOverWhite[p + c] = ToHalf(white[c]);
            }
            frame.ColorOverBlack[p + 3] = ToHalf(0.75f);
            frame.ColorOverWhite[p + 3] = ToHalf(0.125f);
        }

        static byte[] Resolve(RawFrame frame, Background background = default)
        {
            var rgba = new byte[frame.OutputWidth * frame.OutputHeight * 4];
            DifferenceMatting.Resolve(frame, rgba, background);
            return rgba;
        }

        /// <summary>Bits of a value exactly representable as a normal half (or 0); throws otherwise so no test rounds silently.</summary>
        static ushort ToHalf(float value)
        {
            if (value == 0) return 0;
            int sign = value < 0 ? 0x8000 : 0;
            double v = Math.Abs(value);
            int exponent = (int)Math.Floor(Math.Log(v, 2));
            double mantissa = (v / Math.Pow(2, exponent) - 1) * 1024;
            if (exponent < -14 || exponent > 15 || mantissa != Math.Floor(mantissa))
                throw new ArgumentException(value + " is not exactly a normal half.");
            return (ushort)(sign | ((exponent + 15) << 10) | (int)mantissa);
        }
    }
}
