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
            // A dataset's own value wins unless its recorded target needs a larger cube (reach 2.5: 2·0.33·2.5 = 1.65 → 2).
        [TestCase(null, null, 1)]   // nerf_synthetic: nothing declared, size unknown → the ±1.5 box
        [TestCase(4, null, 4)]      // the dataset says 4 and nothing contradicts it
        [TestCase(null, 2.5, 2)]
        [TestCase(4, 2.5, 4)]       // a larger declared cube is kept (the user may want the background)
        [TestCase(2, 1.0, 2)]
        public void ForDataset_TakesTheDeclaredValueOrTheTargetsNeed(int? declared, double? reach, int expected)
        {
            var warnings = new List<ValidationProblem>();
            Assert.That(AabbScale.ForDataset(declared, reach, warnings), Is.EqualTo(expected));
            Assert.That(warnings, Is.Empty);
        }

        [Test]
        public void ForDataset_RaisesATooSmallDeclaredCube_AndSaysWhy()
        {
            var warnings = new List<ValidationProblem>();

            // reach 3.5: 2·0.33·3.5 = 2.31 → 4; the declared 1 covers only 1/0.66 = 1.515.
            Assert.That(AabbScale.ForDataset(1, 3.5, warnings), Is.EqualTo(4));

            Assert.That(warnings.Count, Is.EqualTo(1));
            Assert.That(warnings[0].Field, Is.EqualTo("aabb_scale"));
            Assert.That(warnings[0].Reason, Does.Contain("1.515").And.Contain("3.5").And.Contain("uses 4"));
        }

        [TestCase("2", 2)]
        [TestCase("128", 128)]
        [TestCase("4.0", 4)]
        public void Declared_ReadsPowersOfTwo(string json, int expected) =>
            Assert.That(AabbScale.Declared(Newtonsoft.Json.Linq.JToken.Parse(json), "transforms_train.json"), Is.EqualTo(expected));

        [TestCase("3")]
        [TestCase("256")]
        [TestCase("0")]
        [TestCase("1.5")]
        [TestCase("\"2\"")]
        public void Declared_IgnoresWhatInstantNgpRefuses_WithAWarning(string json)
        {
            var warnings = new List<ValidationProblem>();
            Assert.That(AabbScale.Declared(Newtonsoft.Json.Linq.JToken.Parse(json), "transforms_train.json", warnings), Is.Null);
            Assert.That(warnings.Count, Is.EqualTo(1));
            Assert.That(warnings[0].Field, Is.EqualTo("transforms_train.json: aabb_scale"));
        }
    }
}
