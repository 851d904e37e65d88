using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>EPE and PCK-T (<see cref="FlowMetrics"/>) on small fields whose figures are worked out by hand below.</summary>
    public class FlowMetricsTests
    {
        [Test]
        public void EpeIsTheMeanEuclideanErrorOverTheScoredPixels()
        {
            // 2 × 2 pixels: truth (0, 0), (1, 0), NaN, (3, 4); prediction (3, 4), (1, 0), (5, 5), (0, 0).
            // Errors: |(3, 4)| = 5, 0, not scored, |(−3, −4)| = 5 → mean over the three pixels with flow 10/3.
            var truth = new[] { 0f, 0f, 1f, 0f, float.NaN, float.NaN, 3f, 4f };
            var predicted = new[] { 3f, 4f, 1f, 0f, 5f, 5f, 0f, 0f };
            var all = FlowMetrics.Epe(truth, predicted, p => !float.IsNaN(truth[2 * p]), out var pixels);
            Assert.That(pixels, Is.EqualTo(3));
            Assert.That(all, Is.EqualTo(10.0 / 3).Within(1e-12));
            // Only pixel 1 visible: its error 0.
            Assert.That(FlowMetrics.Epe(truth, predicted, p => p == 1, out pixels), Is.EqualTo(0));
            Assert.That(pixels, Is.EqualTo(1));
            Assert.That(double.IsNaN(FlowMetrics.Epe(truth, predicted, p => false, out pixels)), Is.True);
            // The mean over pairs leaves out pairs with no pixel (NaN): (5 + 1) / 2.
            Assert.That(FlowMetrics.MeanOverPairs(new[] { 5, double.NaN, 1 }), Is.EqualTo(3));
        }

        [Test]
        public void PckTCountsPointsVisibleInBothFramesStrictlyWithinFivePercentOfTheLargerSide()
        {
            // A 40 × 20 image: threshold 0.05 · 40 = 2 px. Three frames, three points, query frame 0.
            Assert.That(FlowMetrics.PckThreshold(40, 20), Is.EqualTo(2));
            var truth = new float[]
            {
                10, 10, 20, 10, 30, 10, // frame 0
                11, 10, 21, 10, 31, 10, // frame 1
                12, 10, 22, 10, 32, 10, // frame 2
            };
            var state = new byte[] { 1, 1, 1, /* frame 1: */ 1, 2, 1, /* frame 2: */ 1, 1, 3 };
            var predicted = new float[]
            {
                0, 0, 0, 0, 0, 0,             // the query frame is not scored
                11, 11.5f, 99, 99, 31, 12,    // point 0 off by 1.5 (correct), point 1 hidden (not scored), point 2 off by exactly 2 (not < 2)
                12, 10, float.NaN, 10, 0, 0,  // point 0 exact, point 1 NaN (never correct), point 2 outside (not scored)
            };
            var pairs = FlowMetrics.PckT(truth, state, predicted, 3, 3, 0, 2);
            Assert.That(pairs.Select(p => (p.QueryFrame, p.Frame, p.Points)), Is.EqualTo(new[] { (0, 1, 2), (0, 2, 2) }));
            Assert.That(pairs.Select(p => p.Pck), Is.EqualTo(new[] { 0.5, 0.5 }));
            // A perfect prediction: 1 on every pair.
            Assert.That(FlowMetrics.PckT(truth, state, truth, 3, 3, 0, 2).Select(p => p.Pck), Is.EqualTo(new[] { 1.0, 1.0 }));
            // A point hidden in the query frame is not scored anywhere; a pair with no common point is left out.
            var hiddenAtQuery = new byte[] { 2, 2, 2, 1, 1, 1, 1, 1, 1 };
            Assert.That(FlowMetrics.PckT(truth, hiddenAtQuery, truth, 3, 3, 0, 2), Is.Empty);
        }
    }
}
