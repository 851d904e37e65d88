using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class MarkerPickingTests
    {
        static readonly double[] Xs = { 100, 130, 104, double.NaN, 300 };
        static readonly double[] Ys = { 100, 100, 103, 101, 300 };

        [Test]
        public void TheNearestMarkerWithinTheRadiusIsPicked()
        {
            // Click (103, 101): marker 0 is √(9 + 1) ≈ 3.162 away, marker 2 is √(1 + 4) ≈ 2.236 away.
            var picked = MarkerPicking.Nearest(Xs, Ys, Xs.Length, 103, 101, 10, out var distance);
            Assert.That(picked, Is.EqualTo(2));
            Assert.That(distance, Is.EqualTo(System.Math.Sqrt(5)).Within(1e-12));
        }

        [Test]
        public void AClickFartherThanTheRadiusPicksNothing()
        {
            // Nearest is marker 1 at (130, 100), 12 px from (118, 100) (marker 2 is 14.3 px away).
            var picked = MarkerPicking.Nearest(Xs, Ys, Xs.Length, 118, 100, 10, out var distance);
            Assert.That(picked, Is.EqualTo(-1));
            Assert.That(distance, Is.EqualTo(12).Within(1e-12));
        }

        [Test]
        public void MarkersWithNaNCoordinatesAreNeverPicked()
        {
            // Marker 3 (NaN, 101) stands for a camera behind the view; marker 0 at (100, 100) is 1 px away.
            var picked = MarkerPicking.Nearest(Xs, Ys, Xs.Length, 100, 101, 10, out _);
            Assert.That(picked, Is.EqualTo(0));
        }

        [Test]
        public void OnATieTheLowerIndexWins()
        {
            var xs = new double[] { 0, 10, 10 };
            var ys = new double[] { 0, 0, 0 };
            Assert.That(MarkerPicking.Nearest(xs, ys, 3, 10, 0, 5, out _), Is.EqualTo(1));
            Assert.That(MarkerPicking.Nearest(xs, ys, 3, 5, 0, 5, out _), Is.EqualTo(0));
        }

        [Test]
        public void OnlyTheFirstCountEntriesTakePart()
        {
            Assert.That(MarkerPicking.Nearest(Xs, Ys, 4, 300, 300, 1000, out _), Is.EqualTo(1));
            Assert.That(MarkerPicking.Nearest(Xs, Ys, 0, 100, 100, 10, out var distance), Is.EqualTo(-1));
            Assert.That(double.IsPositiveInfinity(distance), Is.True);
        }
    }
}
