using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class AnimatedCameraSamplingTests
    {
        [Test]
        public void SamplesSpreadEvenlyWithBothEndsIncluded()
        {
            Assert.That(AnimatedCameraSampling.Times(0, 2, 5, 0, 0), Is.EqualTo(new[] { 0, 0.5, 1, 1.5, 2 }));
            Assert.That(AnimatedCameraSampling.Times(1, 4, 4, 0, 0), Is.EqualTo(new[] { 1.0, 2, 3, 4 }));
            Assert.That(AnimatedCameraSampling.Times(0.5, 3, 1, 0, 0), Is.EqualTo(new[] { 0.5 }), "one sample: the start");
        }

        [Test]
        public void AFrameStepTakesEveryKthFrameUpToTheEnd()
        {
            // 2 s at 30 fps with step 10: frames 0, 10, …, 60 — the last one exactly at the end.
            var times = AnimatedCameraSampling.Times(0, 2, 100, 10, 30);
            Assert.That(times, Has.Length.EqualTo(7));
            Assert.That(times[3], Is.EqualTo(1.0));
            Assert.That(times[6], Is.EqualTo(2.0));
            // 1 s at 24 fps with step 7: frames 0, 7, 14, 21 (28 is past the end).
            Assert.That(AnimatedCameraSampling.Times(0, 1, 1, 7, 24), Is.EqualTo(new[] { 0, 7 / 24.0, 14 / 24.0, 21 / 24.0 }));
            // From a start of 0.5 s: frames counted from the start.
            Assert.That(AnimatedCameraSampling.Times(0.5, 1, 1, 6, 12), Is.EqualTo(new[] { 0.5, 1.0 }));
            Assert.That(AnimatedCameraSampling.Times(0, 1, 1, 15, 0), Is.EqualTo(new[] { 0, 0.25, 0.5, 0.75, 1 }), "no rate: 60 fps");
        }

        [Test]
        public void BadSamplingIsRefusedWithTheField()
        {
            var e = Assert.Throws<InvalidParameterException>(() => AnimatedCameraSampling.Times(0, 2, 0, 0, 0, "splits.val.source"));
            Assert.That(e.Problems[0].Field, Is.EqualTo("splits.val.source.samples"));
            e = Assert.Throws<InvalidParameterException>(() => AnimatedCameraSampling.Times(3, 2, 5, 0, 0, "splits.val.source"));
            Assert.That(e.Problems[0].Field, Is.EqualTo("splits.val.source.end"));
            e = Assert.Throws<InvalidParameterException>(() => AnimatedCameraSampling.Times(0, 100, 5, 1, 1000, "splits.val.source"));
            Assert.That(e.Problems[0].Field, Is.EqualTo("splits.val.source.frameStep"));
            Assert.That(e.Problems[0].Reason, Does.Contain("100001 views"));
            Assert.That(AnimatedCameraSampling.Validate("s", 10, -1, 0, 0, 0)[0].Field, Is.EqualTo("s.frameStep"));
            Assert.That(AnimatedCameraSampling.Validate("s", 10, 0, -5, 0, 0)[0].Field, Is.EqualTo("s.frameRate"));
        }

        [Test]
        public void AnEndOfZeroIsTheClipsLength()
        {
            Assert.That(AnimatedCameraSampling.ResolveEnd(0, 12.5), Is.EqualTo(12.5));
            Assert.That(AnimatedCameraSampling.ResolveEnd(3, 12.5), Is.EqualTo(3));
        }
    }
}
