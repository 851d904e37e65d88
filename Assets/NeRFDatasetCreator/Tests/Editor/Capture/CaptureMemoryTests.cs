using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Issue 32, R4-10: a lens capture's views in flight are bounded by this machine's memory as Unity reports it
    /// (<c>SystemInfo.systemMemorySize</c>, MB). The review's example: the 1920×1080 lens's 2167×1219 wide render at
    /// k = 2 with every pass at the colour size, ~0.39 GB a view without labels.
    /// </summary>
    [TestFixture]
    public class CaptureMemoryTests
    {
        [Test]
        public void ALensCapturesViewsInFlightFitAQuarterOfThisMachinesMemory()
        {
            var options = new CaptureOptions { Width = 2167, Height = 1219, Supersampling = 2, DepthAndNormalAtOutputSize = false, Passes = CapturePasses.All };
            Assert.That(SystemInfo.systemMemorySize, Is.GreaterThan(0), "Unity reports the machine's memory");
            var budget = ViewsInFlight.BudgetFor(SystemInfo.systemMemorySize * (1L << 20));
            var view = ViewsInFlight.ViewBytes(4334, 2438, 4334, 2438, true, false, true, false, true, true);
            var limit = CaptureMemory.Bound(options, 8);
            Assert.That(limit.Total * view <= budget || limit.Total == 3, Is.True,
                limit.Total + " views of " + view + " bytes against " + budget);
            Assert.That(limit.Readbacks, Is.InRange(1, options.ReadbacksInFlight));
            Assert.That(limit.Writers, Is.InRange(1, 8));
        }
    }
}
