using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class HalfFloatTests
    {
        // Bit patterns from the IEEE 754 binary16 layout: 1 sign bit, 5 exponent bits (bias 15), 10 mantissa bits.
        [TestCase((ushort)0x0000, 0f)]
        [TestCase((ushort)0x3C00, 1f)]
        [TestCase((ushort)0x3800, 0.5f)]
        [TestCase((ushort)0x3400, 0.25f)]
        [TestCase((ushort)0x3E00, 1.5f)]
        [TestCase((ushort)0xBC00, -1f)]
        [TestCase((ushort)0xC000, -2f)]
        [TestCase((ushort)0x7BFF, 65504f)]             // largest finite half
        [TestCase((ushort)0x0400, 6.103515625e-05f)]   // smallest normal, 2^-14
        [TestCase((ushort)0x0001, 5.9604644775390625e-08f)] // smallest subnormal, 2^-24
        [TestCase((ushort)0x3555, 0.333251953125f)]    // 1/3 rounded: (1 + 341/1024)·2^-2
        public void DecodesTheValueItsBitsStandFor(ushort bits, float expected)
        {
            Assert.That(HalfFloat.ToFloat(bits), Is.EqualTo(expected));
        }

        [Test]
        public void InfinitiesNaNAndNegativeZeroKeepTheirMeaning()
        {
            Assert.That(float.IsPositiveInfinity(HalfFloat.ToFloat(0x7C00)), Is.True);
            Assert.That(float.IsNegativeInfinity(HalfFloat.ToFloat(0xFC00)), Is.True);
            Assert.That(float.IsNaN(HalfFloat.ToFloat(0x7E00)), Is.True);
            Assert.That(1f / HalfFloat.ToFloat(0x8000), Is.EqualTo(float.NegativeInfinity));
        }
    
        [Test]
        public void EveryHalfRoundTripsThroughFloat()
        {
            for (var bits = 0; bits < 65536; bits++)
            {
                var value = HalfFloat.ToFloat((ushort)bits);
                if (float.IsNaN(value)) { Assert.That(float.IsNaN(HalfFloat.ToFloat(HalfFloat.FromFloat(value))), Is.True); continue; }
                Assert.That(HalfFloat.FromFloat(value), Is.EqualTo((ushort)bits), "bits 0x" + bits.ToString("X4"));
            }
        }

        [Test]
        public void FloatsRoundToTheNearestHalfTiesToEven()
        {
            // Between consecutive halves a and b (normal and subnormal), a value just below the midpoint goes to a, just
            // above to b, and the midpoint to the one with an even mantissa.
            foreach (var a in new ushort[] { 0x3C00, 0x3C01, 0x0400, 0x0001, 0x0002, 0x7BFE, 0xBC00 })
            {
                var b = (ushort)(a + 1);
                double lo = HalfFloat.ToFloat(a), hi = HalfFloat.ToFloat(b), mid = (lo + hi) / 2;
                Assert.That(HalfFloat.FromFloat((float)(mid - (hi - lo) * 0.01)), Is.EqualTo(a));
                Assert.That(HalfFloat.FromFloat((float)(mid + (hi - lo) * 0.01)), Is.EqualTo(b));
                Assert.That(HalfFloat.FromFloat((float)mid), Is.EqualTo((a & 1) == 0 ? a : b));
            }
            Assert.That(HalfFloat.FromFloat(65520f), Is.EqualTo((ushort)0x7C00), "half-way past the largest half rounds to infinity");
            Assert.That(HalfFloat.FromFloat(1e-9f), Is.EqualTo((ushort)0), "below half the smallest subnormal");
        }
    }
}
