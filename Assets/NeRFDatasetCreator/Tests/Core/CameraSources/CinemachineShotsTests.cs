using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class CinemachineShotsTests
    {
        // Wide 0–2 s, Close 1.5–4 s (a 0.5 s blend), a gap, Top 5–6 s.
        static readonly ShotSpan[] Shots = { new ShotSpan("Wide", 0, 2), new ShotSpan("Close", 1.5, 4), new ShotSpan("Top", 5, 6) };

        [Test]
        public void AShotIsActiveFromItsStartUpToButNotAtItsEnd()
        {
            Assert.That(CinemachineShots.Covers(Shots, 0), Is.True);
            Assert.That(CinemachineShots.Covers(Shots, 1.75), Is.True, "inside the blend");
            Assert.That(CinemachineShots.Covers(Shots, 3.999), Is.True);
            Assert.That(CinemachineShots.Covers(Shots, 4), Is.False, "[start, end): Timeline's interval tree");
            Assert.That(CinemachineShots.Covers(Shots, 4.5), Is.False, "the gap");
            Assert.That(CinemachineShots.Covers(Shots, 5), Is.True);
        }

        [Test]
        public void TimesAreComparedInWholeTicks()
        {
            // 4 − 4e-13 s rounds to the tick of 4 s (half a tick is 5e-13): the end, so not covered.
            Assert.That(CinemachineShots.TickOf(4 - 4e-13), Is.EqualTo(4_000_000_000_000L));
            Assert.That(CinemachineShots.Covers(Shots, 4 - 4e-13), Is.False);
            Assert.That(CinemachineShots.Covers(Shots, 4 - 1.2e-12), Is.True);
        }

        [Test]
        public void TheEndOfAShotIsEvaluatedOneTickEarlierAndAGapIsNaN()
        {
            Assert.That(CinemachineShots.EvaluationTime(Shots, 1), Is.EqualTo(1));
            Assert.That(CinemachineShots.EvaluationTime(Shots, 2), Is.EqualTo(2), "Close continues past Wide's end");
            Assert.That(CinemachineShots.TickOf(CinemachineShots.EvaluationTime(Shots, 6)), Is.EqualTo(6_000_000_000_000L - 1));
            Assert.That(CinemachineShots.TickOf(CinemachineShots.EvaluationTime(Shots, 4)), Is.EqualTo(4_000_000_000_000L - 1));
            Assert.That(CinemachineShots.EvaluationTime(Shots, 4.5), Is.NaN);
            Assert.That(CinemachineShots.EvaluationTime(Shots, 7), Is.NaN, "after the last shot");
            Assert.That(CinemachineShots.EvaluationTime(new[] { new ShotSpan("Late", 1, 2) }, 0.5), Is.NaN, "before the first shot");
        }

        [Test]
        public void EvenSamplesOverAWholeTimelineAreAllEvaluated()
        {
            var shots = new[] { new ShotSpan("A", 0, 3), new ShotSpan("B", 2, 6) };
            var times = AnimatedCameraSampling.Times(0, 6, 7, 0, 0);
            var evaluated = CinemachineShots.EvaluationTimes(shots, times, "splits.train.source", "Cams (CinemachineTrack)", out var problem);
            Assert.That(problem, Is.Null);
            for (var i = 0; i < 6; i++) Assert.That(evaluated[i], Is.EqualTo(times[i]), "inside the shots: the sample's own time");
            Assert.That(evaluated[6], Is.EqualTo(6 - 1e-12).Within(1e-14), "the Timeline's end: one tick earlier");
        }

        [Test]
        public void ASampleInAGapIsRefusedWithTheShotsAndAFix()
        {
            var times = AnimatedCameraSampling.Times(0, 6, 13, 0, 0); // every 0.5 s: 4.5 s is the first in the gap
            Assert.That(CinemachineShots.EvaluationTimes(Shots, times, "splits.test.source", "Cams", out var problem), Is.Null);
            Assert.That(problem.Field, Is.EqualTo("splits.test.source.start"));
            Assert.That(problem.Value, Is.EqualTo("4.5 s"));
            Assert.That(problem.Reason, Does.Contain("1 of 13 samples"));
            Assert.That(problem.Reason, Does.Contain("Wide 0–2 s, Close 1.5–4 s, Top 5–6 s"));
            Assert.That(problem.Fix, Does.Contain("start 0, end 6"));
        }

        [Test]
        public void ATrackWithoutShotsIsRefused()
        {
            Assert.That(CinemachineShots.EvaluationTimes(new ShotSpan[0], new[] { 0.0 }, "splits.test.source", "Cams", out var problem), Is.Null);
            Assert.That(problem.Field, Is.EqualTo("splits.test.source.camera"));
            Assert.That(problem.Reason, Does.Contain("has no shot"));
        }
    }
}
