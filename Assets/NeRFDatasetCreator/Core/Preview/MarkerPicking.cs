using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Which camera marker a click hits, decided in screen space: the caller projects each marker to GUI pixels
    /// (NaN for a marker behind the view or hidden), and the nearest one within the pick radius wins. Deciding in
    /// pixels keeps the hit area the same size however far the rig is zoomed.
    /// </summary>
    public static class MarkerPicking
    {
        /// <summary>
        /// How close, in GUI points, a click must land to a marker to pick it: 5, the distance within which Unity's
        /// <c>HandleUtility.nearestControl</c> reports a control at all (<c>HandleUtility.kPickDistance</c>), so the
        /// preview's pick and Unity's agree.
        /// </summary>
        public const double DefaultRadiusPixels = 5;

        /// <summary>
        /// The index of the point nearest to (<paramref name="clickX"/>, <paramref name="clickY"/>) among the first
        /// <paramref name="count"/> entries, or −1 when none lies within <paramref name="radius"/>. Points with a NaN
        /// coordinate are skipped; on a tie the lower index wins, so the pick is deterministic.
        /// </summary>
        public static int Nearest(IReadOnlyList<double> xs, IReadOnlyList<double> ys, int count, double clickX, double clickY, double radius,
            out double distance)
        {
            if (xs == null) throw new ArgumentNullException(nameof(xs));
            if (ys == null) throw new ArgumentNullException(nameof(ys));
            if (count < 0 || count > xs.Count || count > ys.Count)
                throw new ArgumentOutOfRangeException(nameof(count), count, "count must be between 0 and the length of both coordinate lists.");

            var best = -1;
            var bestSquared = double.PositiveInfinity;
            for (var i = 0; i < count; i++)
            {
                double dx = xs[i] - clickX, dy = ys[i] - clickY;
                var squared = dx * dx + dy * dy;
                if (double.IsNaN(squared)) continue;
                if (squared < bestSquared)
                {
                    bestSquared = squared;
                    best = i;
                }
            }
            distance = Math.Sqrt(bestSquared);
            return best >= 0 && distance <= radius ? best : -1;
        }
    }
}
