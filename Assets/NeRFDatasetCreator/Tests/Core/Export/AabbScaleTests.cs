using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// By hand: NGP's cube has side k in NGP units (x·0.33 + 0.5), so it covers radius k / 0.66 output units:
    /// k = 1 → 1.515, 2 → 3.030, 4 → 6.061, 128 → 193.94.
    /// </summary>
    public class AabbScaleTests
    {
        [TestCase(0.0, 1)]
        [TestCase(1.0, 1)]
        [TestCase(1.5, 1)]     // 0.99 ≤ 1: nerf_synthetic's box
        [TestCase(1.52, 2)]    // 1.0032 > 1
        [TestCase(3.03, 2)]    // 1.9998
        [TestCase(3.04, 4)]    // 2.0064
        [TestCase(6.06, 4)]    // 3.9996
        [TestCase(6.07, 8)]
        [TestCase(100.0, 128)] // 66
        [TestCase(193.9, 128)] // 127.97
        public void SmallestPowerOfTwoCoveringTheRadius(double radius, int expected)
        {
            var warnings = new List<ValidationProblem>();
            Assert.That(AabbScale.ForRadius(radius, warnings), Is.EqualTo(expected));
            Assert.That(warnings, Is.Empty);
            Assert.That(AabbScale.CoveredRadius(expected), Is.GreaterThanOrEqualTo(radius));
        }

        [Test]
        public void BeyondTheLargestCube_ClampsTo128AndWarns()
        {
            var warnings = new List<ValidationProblem>();

            Assert.That(AabbScale.ForRadius(194, warnings), Is.EqualTo(128));

            Assert.That(warnings.Count, Is.EqualTo(1));
            Assert.That(warnings[0].Field, Is.EqualTo("aabb_scale"));
        }

        [Test]
        public void NegativeRadius_IsAnError()
        {
            var e = Assert.Throws<InvalidParameterException>(() => AabbScale.ForRadius(-1));
            Assert.That(e.Problems[0].Field, Is.EqualTo("sceneRadius"));
        }
    }
}
