using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class DepthEncodingTests
    {
        [TestCase(4.0, 4000)]
        [TestCase(2.0004, 2000)]
        [TestCase(2.0006, 2001)]
        [TestCase(65.535, 65535)]
        [TestCase(65.6, 0)]     // not representable: unknown, not clamped
        [TestCase(0.0, 0)]      // no hit
        [TestCase(-1.0, 0)]
        [TestCase(double.NaN, 0)]
        [TestCase(double.PositiveInfinity, 0)]
        public void PngValue_IsMillimetresOfOutputUnits(double outputDepth, int expected)
        {
            Assert.That((int)DepthEncoding.ToPngValue(outputDepth), Is.EqualTo(expected));
        }

        [Test]
        public void OutputDepth_IsMetricDepthTimesTheScale()
        {
            // A camera 3.6 m from the target, preset scale 4/3.6: the target centre is 4 output units away.
            Assert.That(DepthEncoding.ToOutputUnits(3.6, 4 / 3.6), Is.EqualTo(4.0).Within(1e-15));
            Assert.That(DepthEncoding.MaxEncodable(), Is.EqualTo(65.535).Within(1e-12));
        }
    }
}
