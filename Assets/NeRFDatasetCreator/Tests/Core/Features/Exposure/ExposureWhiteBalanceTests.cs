using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ExposureWhiteBalanceTests
    {
        [Test]
        public void ScalesLinearLightByTwoToTheEvTimesTheGain()
        {
            // 0.2 · 2^1 · 1.25 = 0.5; 0.3 · 2^-2 · 0.8 = 0.06; 0.5 · 2 · 1.2 = 1.2 → clipped to 1, as a sensor saturates.
            var e = new ViewExposure(1, 1.25, 1, 1.2);
            Assert.That(ExposureWhiteBalance.Apply(0.2, e.Scale(0)), Is.EqualTo(0.5).Within(1e-15));
            Assert.That(ExposureWhiteBalance.Apply(0.3, new ViewExposure(-2, 0.8, 1, 1).Scale(0)), Is.EqualTo(0.06).Within(1e-15));
            Assert.That(ExposureWhiteBalance.Apply(0.5, e.Scale(2)), Is.EqualTo(1.0));
            Assert.That(ExposureWhiteBalance.Apply(0.25, e.Scale(1)), Is.EqualTo(0.5).Within(1e-15));
        }

        [Test]
        public void EightBitOutputDecodesToTheExpectedLinearValueWithinQuantisation()
        {
            // Byte 128 is linear ((128/255 + 0.055)/1.055)^2.4 = 0.2158605; EV -1, gains (1, 1.5, 3):
            // R 0.10793 → byte 92 (sRGB 0.3618 · 255 = 92.26); G 0.16190 → byte 112; B 0.32379 → byte 154.
            var rgba = new byte[] { 128, 128, 128, 77, 255, 0, 10, 255 };
            ExposureWhiteBalance.ApplyRgba(rgba, new ViewExposure(-1, 1, 1.5, 3));
            Assert.That(rgba[0], Is.EqualTo(92));
            Assert.That(rgba[1], Is.EqualTo(112));
            Assert.That(rgba[2], Is.EqualTo(154));
            Assert.That(rgba[3], Is.EqualTo(77), "alpha unchanged");
            Assert.That(rgba[7], Is.EqualTo(255), "alpha unchanged");
            Assert.That(rgba[5], Is.EqualTo(0), "black stays black");
            var l128 = Math.Pow((128 / 255.0 + 0.055) / 1.055, 2.4);
            foreach (var (b, expected) in new[] { (rgba[0], l128 * 0.5), (rgba[1], l128 * 0.75), (rgba[2], l128 * 1.5) })
            {
                // The byte is the rounding of the expected value's sRGB code: within half a code, and it decodes within one step.
                var code = (expected <= 0.0031308 ? 12.92 * expected : 1.055 * Math.Pow(expected, 1 / 2.4) - 0.055) * 255;
                Assert.That(Math.Abs(code - b), Is.LessThanOrEqualTo(0.5));
                Assert.That(Math.Abs(Srgb.DecodeExact(b / 255.0) - expected), Is.LessThan(Srgb.DecodeExact((b + 1) / 255.0) - Srgb.DecodeExact(b / 255.0)));
            }
        }

        [Test]
        public void BrightByteClipsAtWhite()
        {
            var rgba = new byte[] { 200, 250, 255, 0 };
            ExposureWhiteBalance.ApplyRgba(rgba, new ViewExposure(2, 1, 1, 1));
            Assert.That(rgba, Is.EqualTo(new byte[] { 255, 255, 255, 0 }));
        }

        [Test]
        public void IdentityLeavesEveryByteUnchanged()
        {
            var table = ExposureWhiteBalance.Table(1);
            for (var b = 0; b < 256; b++) Assert.That(table[b], Is.EqualTo((byte)b));
        }

        /// <summary>
        /// The stage scales the clean image's 8-bit values; scaling the linear value before the first rounding could give
        /// another byte. Measured here over 100 001 linear values per gain and printed; bounded by the gain's stretch of
        /// half a code plus the final half code.
        /// </summary>
        [Test]
        public void DifferenceToScalingBeforeTheFirstRoundingIsSmall()
        {
            foreach (var scale in new[] { 0.25, 0.5, 0.8, 1.25, 2, 4 })
            {
                var table = ExposureWhiteBalance.Table(scale);
                int worst = 0, off = 0;
                const int n = 100000;
                for (var i = 0; i <= n; i++)
                {
                    var c = i / (double)n;
                    var direct = Srgb.EncodeByteExact(Math.Min(1, c * scale));
                    var staged = table[Srgb.EncodeByteExact(c)];
                    var d = Math.Abs(direct - staged);
                    if (d > worst) worst = d;
                    if (d > 0) off++;
                }
                TestContext.WriteLine($"gain {scale}: worst {worst} code(s), {off * 100.0 / (n + 1):0.0}% of values differ");
                Assert.That(worst, Is.LessThanOrEqualTo(scale <= 1 ? 1 : (int)Math.Ceiling(scale / 2 + 0.5)));
            }
        }
    }
}
