using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Farthest-point sampling of camera centres, the rule for sparse-view splits of rigs that are not nerf_synthetic's:
    /// the first view is the one farthest from the mean centre; each next view is the one whose distance to the nearest
    /// view already chosen is largest. Ties go to the lower index, and distances are compared exactly, so the same
    /// centres always give the same list (in the order chosen). It spreads the few views around the rig instead of
    /// bunching them, as the sparse-view papers' lists do.
    /// </summary>
    public static class FarthestViews
    {
        public const string Rule =
            "farthest-point sampling of the train camera centres: first the view farthest from their mean, then each time the view farthest from its nearest chosen view (ties: the lower index); every test view";

        /// <summary>The indices of <paramref name="count"/> of <paramref name="centres"/>, in the order chosen.</summary>
        public static IReadOnlyList<int> Select(IReadOnlyList<Vector3d> centres, int count)
        {
            if (centres == null) throw new ArgumentNullException(nameof(centres));
            if (count < 1 || count > centres.Count) throw new ArgumentOutOfRangeException(nameof(count), count, "must be between 1 and the number of views.");
            var mean = Vector3d.Zero;
            foreach (var c in centres) mean += c;
            mean /= centres.Count;
            var nearest = new double[centres.Count];
            for (var i = 0; i < centres.Count; i++) nearest[i] = (centres[i] - mean).LengthSquared;
            var chosen = new List<int>();
            var taken = new bool[centres.Count];
            while (chosen.Count < count)
            {
                var best = -1;
                for (var i = 0; i < centres.Count; i++)
                    if (!taken[i] && (best < 0 || nearest[i] > nearest[best])) best = i;
                chosen.Add(best);
                taken[best] = true;
                // From now on: the squared distance of each view to its nearest chosen view.
                for (var i = 0; i < centres.Count; i++)
                {
                    var d = (centres[i] - centres[best]).LengthSquared;
                    if (chosen.Count == 1 || d < nearest[i]) nearest[i] = d;
                }
            }
            return chosen;
        }
    }
}
