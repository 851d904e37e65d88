using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 32, R4-10: the views a capture keeps alive are bounded by memory. The figures are the review's: the lens
    /// documentation's 1920×1080 example (f = 1000, k1 = −0.12, k2 = 0.03) renders a 2167×1219 wide frame, 4334×2438
    /// samples at k = 2, and with normals and labels a view holds 10 566 292 × (16 colour + 1 mask + 4 labels + 4 depth
    /// + 16 normals) bytes ≈ 433 MB; 3 readbacks + 8 writers + 16 queued = 27 of them were ≈ 11.7 GB.
    /// </summary>
    [TestFixture]
    public class ViewsInFlightTests
    {
        const long LensView = 10_566_292L * 41;

        [Test]
        public void AViewHoldsItsPassesBytes()
        {
            Assert.That(ViewsInFlight.ViewBytes(4334, 2438, 4334, 2438, true, false, true, true, true, true), Is.EqualTo(LensView));
            // Motion blur adds the averaged pair; depth and normals at the output size are k² smaller.
            Assert.That(ViewsInFlight.ViewBytes(1600, 1600, 800, 800, true, true, true, false, true, true),
                Is.EqualTo(1600L * 1600 * (16 + 16 + 1) + 800L * 800 * 20));
            Assert.That(ViewsInFlight.ViewBytes(100, 100, 100, 100, false, true, false, false, false, false), Is.EqualTo(0), "no colour, no average");
        }

        [Test]
        public void ALensCaptureOnA16GBMachineKeepsNineViewsAlive()
        {
            var budget = ViewsInFlight.BudgetFor(16L << 30);
            Assert.That(budget, Is.EqualTo(4L << 30), "a quarter of the machine");
            // 4 GiB / 433 MB = 9.9: nine views. The queue goes first (16 → 1), then writers (8 → 5); the readbacks stay.
            var limit = ViewsInFlight.For(LensView, budget, 3, 8, 16);
            Assert.That((limit.Readbacks, limit.Writers, limit.Queue), Is.EqualTo((3, 5, 1)));
            Assert.That(limit.Total * LensView, Is.LessThanOrEqualTo(budget));
            Assert.That((limit.Total + 1) * LensView, Is.GreaterThan(budget), "no more than needed is taken away");
        }

        [Test]
        public void ACaptureThatFitsIsUnchanged()
        {
            // 800×800 at k = 2 with depth and normals at the output size: 66 MB a view, 27 of them 1.8 GB < 4 GiB.
            var view = ViewsInFlight.ViewBytes(1600, 1600, 800, 800, true, false, true, false, true, true);
            var limit = ViewsInFlight.For(view, ViewsInFlight.BudgetFor(16L << 30), 3, 8, 16);
            Assert.That((limit.Readbacks, limit.Writers, limit.Queue), Is.EqualTo((3, 8, 16)));
        }

        [Test]
        public void AViewLargerThanTheBudgetIsStillCapturedOneOfEachAtATime()
        {
            var limit = ViewsInFlight.For(LensView, LensView / 2, 3, 2, 4);
            Assert.That((limit.Readbacks, limit.Writers, limit.Queue), Is.EqualTo((1, 1, 1)));
            Assert.That(ViewsInFlight.BudgetFor(512L << 20), Is.EqualTo(1L << 30), "at least 1 GiB whatever the machine reports");
            Assert.That(ViewsInFlight.BudgetFor(0), Is.EqualTo(1L << 30), "an unknown size (0) too");
        }
    }
}
