using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ThroughputMeterTests
    {
        [Test]
        public void RateAndTimeLeftFollowFromViewsDoneAndElapsedTime()
        {
            var meter = new ThroughputMeter(100);
            meter.Update(25, 10.0);
            Assert.That(meter.ViewsPerSecond, Is.EqualTo(2.5).Within(1e-12));
            Assert.That(meter.SecondsLeft, Is.EqualTo(30.0).Within(1e-12)); // 75 views at 2.5 views/s
            Assert.That(meter.Fraction, Is.EqualTo(0.25).Within(1e-12));
        }

        [Test]
        public void NoEstimateBeforeTheFirstView()
        {
            var meter = new ThroughputMeter(10);
            meter.Update(0, 3.0);
            Assert.That(meter.ViewsPerSecond, Is.EqualTo(0.0));
            Assert.That(meter.SecondsLeft, Is.Null);
            Assert.That(meter.Describe(), Is.EqualTo("0 / 10 views · 0.0 views/s · estimating time left"));
        }

        [Test]
        public void DescribeUsesInvariantDigits()
        {
            var meter = new ThroughputMeter(8);
            meter.Update(2, 4.0);
            Assert.That(meter.Describe(), Is.EqualTo("2 / 8 views · 0.5 views/s · 0:12 left"));
        }

        [TestCase(0.0, "0:00")]
        [TestCase(59.2, "1:00")]
        [TestCase(61.0, "1:01")]
        [TestCase(3600.0, "1:00:00")]
        [TestCase(3725.0, "1:02:05")]
        public void FormatsDurations(double seconds, string expected)
        {
            Assert.That(ThroughputMeter.FormatDuration(seconds), Is.EqualTo(expected));
        }

        [Test]
        public void RejectsMoreViewsDoneThanTotal()
        {
            var meter = new ThroughputMeter(3);
            Assert.Throws<System.ArgumentOutOfRangeException>(() => meter.Update(4, 1.0));
        }
    }
}
