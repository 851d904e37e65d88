using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class SrgbTests
    {
        // Values computed by hand from IEC 61966-2-1: ((c/255 + 0.055)/1.055)^2.4, or c/255/12.92 below 0.04045.
        [TestCase(0, 0.0)]
        [TestCase(255, 1.0)]
        [TestCase(10, 0.0030352698)] // linear segment: 10/255/12.92
        [TestCase(128, 0.2158605)]
        [TestCase(188, 0.5028866)]
        public void DecodeMatchesTheStandard(int encoded, double linear)
        {
            Assert.That(Srgb.Decode((byte)encoded), Is.EqualTo(linear).Within(1e-6));
        }

        [TestCase(0.5, 188)] // 1.055·0.5^(1/2.4) − 0.055 = 0.73536 → 187.52
        [TestCase(0.2158605, 128)]
        [TestCase(0.002, 7)] // linear segment: 0.002·12.92·255 = 6.59
        [TestCase(0.0, 0)]
        [TestCase(1.0, 255)]
        [TestCase(-0.5, 0)]
        [TestCase(3.0, 255)]
        public void EncodeMatchesTheStandard(double linear, int expected)
        {
            Assert.That(Srgb.EncodeByteExact(linear), Is.EqualTo((byte)expected));
            Assert.That(Srgb.Encode((float)linear), Is.EqualTo((byte)expected));
        }

        [Test]
        public void EveryByteRoundTrips()
        {
            for (int b = 0; b < 256; b++) Assert.That(Srgb.Encode(Srgb.Decode((byte)b)), Is.EqualTo((byte)b), "byte " + b);
        }

        [Test]
        public void FastEncodeIsWithinOneLsbOfTheFormulaEverywhere()
        {
            // A dense sweep of [0, 1] plus values straddling every rounding threshold, where a table is most likely wrong.
            int worst = 0;
            for (int i = 0; i <= 1000000; i++) worst = System.Math.Max(worst, Difference(i / 1000000f));
            for (int b = 1; b < 256; b++)
            {
                float threshold = (float)Srgb.DecodeExact((b - 0.5) / 255.0);
                for (int step = -3; step <= 3; step++) worst = System.Math.Max(worst, Difference(threshold * (1 + step * 1e-7f)));
            }
            Assert.That(worst, Is.LessThanOrEqualTo(1));
        }

        [Test]
        public void FastEncodeEqualsTheFormulaAwayFromThresholds()
        {
            // Midway between thresholds there is no rounding ambiguity: the result must be exact.
            for (int b = 0; b < 255; b++)
            {
                float mid = (float)Srgb.DecodeExact(b / 255.0 + 0.25 / 255.0);
                Assert.That(Srgb.Encode(mid), Is.EqualTo(Srgb.EncodeByteExact(mid)), "near byte " + b);
            }
        }

        static int Difference(float linear) => System.Math.Abs(Srgb.Encode(linear) - Srgb.EncodeByteExact(linear));
    }
}
