using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The window's re-check timing (review S3-2): debounced, once per burst of changes, deaf to its own scene events.</summary>
    public class RecheckScheduleTests
    {
        /// <summary>Ticks at 10 Hz from <paramref name="from"/> to <paramref name="to"/>; each due check "runs" for <paramref name="cost"/> s.</summary>
        static int Idle(RecheckSchedule schedule, double from, double to, double cost = 0.05, bool checkRaisesSceneEvents = false)
        {
            int checks = 0;
            for (double now = from; now < to; now += 0.1)
            {
                if (!schedule.Due(now)) continue;
                schedule.Starting();
                if (checkRaisesSceneEvents) schedule.SceneChanged(now); // raised synchronously by the check's copies
                schedule.Finished(now + cost);
                checks++;
                if (checkRaisesSceneEvents) schedule.SceneChanged(now + 0.1); // delivered on the next editor update
            }
            return checks;
        }

        [Test]
        public void AnOpenedWindowChecksOnceAndThenIdles()
        {
            var schedule = new RecheckSchedule();
            Assert.That(schedule.Due(0), Is.True, "the first check is not delayed");
            Assert.That(Idle(schedule, 0, 10), Is.EqualTo(1));
        }

        [Test]
        public void ACheckWhoseCopiesRaiseSceneEventsDoesNotLoop()
        {
            var schedule = new RecheckSchedule();
            Assert.That(Idle(schedule, 0, 10, cost: 0.3, checkRaisesSceneEvents: true), Is.EqualTo(1));
        }

        [Test]
        public void ADragIsOneCheckHalfASecondAfterItStops()
        {
            var schedule = new RecheckSchedule();
            Idle(schedule, 0, 1);
            int checks = 0;
            double lastCheck = 0;
            for (double now = 2; now < 6; now += 0.1)
            {
                if (now < 4) schedule.Changed(now); // the target moves every tick for two seconds
                if (schedule.Due(now))
                {
                    schedule.Starting();
                    schedule.Finished(now);
                    checks++;
                    lastCheck = now;
                }
            }
            Assert.That(checks, Is.EqualTo(1));
            Assert.That(lastCheck, Is.EqualTo(3.9 + RecheckSchedule.DebounceSeconds).Within(0.11));
        }

        [Test]
        public void AUserEditAfterTheQuietWindowIsChecked()
        {
            var schedule = new RecheckSchedule();
            schedule.Starting();
            schedule.Finished(1.0);
            Assert.That(schedule.SceneChanged(1.1), Is.False, "within the check's own-events window");
            Assert.That(schedule.Due(5), Is.False);
            Assert.That(schedule.SceneChanged(1.0 + RecheckSchedule.OwnEventsSeconds + 0.01), Is.True);
            Assert.That(schedule.Due(1.3), Is.False, "debounced");
            Assert.That(schedule.Due(1.8), Is.True);
        }

        [Test]
        public void NoCheckStartsWhileOneRuns()
        {
            var schedule = new RecheckSchedule();
            schedule.Starting();
            schedule.Changed(0);
            Assert.That(schedule.Due(10), Is.False);
            Assert.That(schedule.Checking, Is.True);
            schedule.Finished(10);
            Assert.That(schedule.Due(11), Is.False, "the change made during the check was checked by it");
        }
    }
}
