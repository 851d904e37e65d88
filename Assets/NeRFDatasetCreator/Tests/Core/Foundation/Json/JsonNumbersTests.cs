using System;
using System.Globalization;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class JsonNumbersTests
    {
        [TestCase(1.0, "1.0")]
        [TestCase(4.0, "4.0")]
        [TestCase(0.0, "0.0")]
        [TestCase(-0.0, "0.0")]
        [TestCase(0.1, "0.1")]
        [TestCase(0.6911112070083618, "0.6911112070083618")]
        [TestCase(1e-16, "1e-16")]
        [TestCase(-2.5e20, "-2.5e+20")]
        [TestCase(123456789.0, "123456789.0")]
        public void FormatsLikePythonsJsonModule(double value, string expected)
        {
            Assert.That(JsonNumbers.Format(value), Is.EqualTo(expected));
        }

        [Test]
        public void EveryFormattedNumberReadsBackExactly()
        {
            var random = new SeededRandom(2024);
            for (var i = 0; i < 20000; i++)
            {
                var bits = (long)random.NextUInt64();
                var value = BitConverter.Int64BitsToDouble(bits);
                if (double.IsNaN(value) || double.IsInfinity(value)) continue;
                var text = JsonNumbers.Format(value);
                Assert.That(double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture), Is.EqualTo(value), text);
            }
        }

        [Test]
        public void ExportsWriteNumbersAsTheSplitFilesDo()
        {
            // nerfstudio's and instant-ngp's transforms.json are written by ExportJson: the same number text as
            // transforms_<split>.json (lowercase exponent, no negative zero), not Newtonsoft's "1E-16" and "-0.0".
            var json = new JObject { ["tiny"] = 1e-16, ["negativeZero"] = -0.0, ["whole"] = 400.0, ["count"] = 3 };
            Assert.That(ExportJson.Serialise(json),
                Is.EqualTo("{\n  \"tiny\": 1e-16,\n  \"negativeZero\": 0.0,\n  \"whole\": 400.0,\n  \"count\": 3\n}\n"));
        }

        [TestCase(double.NaN)]
        [TestCase(double.PositiveInfinity)]
        [TestCase(double.NegativeInfinity)]
        public void NonFiniteNumbersAreRefused(double value)
        {
            Assert.Throws<ArgumentException>(() => JsonNumbers.Format(value));
        }
    }
}
