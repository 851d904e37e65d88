using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Chamfer distance and F-score between a reconstruction and the ground-truth surface, both as point sets in output
    /// units (meshes are sampled first, <see cref="GeometryEvaluation"/>):
    /// <list type="bullet">
    /// <item>accuracy = mean over reconstruction points of the distance to the nearest ground-truth point (all of them:
    /// a reconstructed point on an unseen part of the true surface is still accurate);</item>
    /// <item>completeness = mean over the <b>observed</b> ground-truth points of the distance to the nearest reconstruction
    /// point (what no training view saw cannot be asked for; DTU's evaluation likewise keeps only observed points);</item>
    /// <item>Chamfer = (accuracy + completeness) / 2, as DTU's script and 2DGS / GOF / PGSR report it;</item>
    /// <item>precision / recall = the fraction of those distances below the threshold τ, F-score = 2PR / (P + R)
    /// (Tanks and Temples' definition).</item>
    /// </list>
    /// Nearest neighbours come from <see cref="PointKdTree"/> (exact).
    /// </summary>
    public sealed class SurfaceDistances
    {
        public double Accuracy { get; private set; }
        public double Completeness { get; private set; }
        public double Chamfer => 0.5 * (Accuracy + Completeness);
        public double Precision { get; private set; }
        public double Recall { get; private set; }
        public double FScore => Precision + Recall > 0 ? 2 * Precision * Recall / (Precision + Recall) : 0;
        public double Threshold { get; private set; }
        public int ReconstructionPoints { get; private set; }
        public int TruthPoints { get; private set; }
        public int ObservedTruthPoints { get; private set; }

        /// <param name="reconstruction">x, y, z per reconstruction point.</param>
        /// <param name="truth">x, y, z per ground-truth point.</param>
        /// <param name="observed">Per ground-truth point whether a training view saw it; null = all.</param>
        /// <param name="threshold">τ for precision and recall, output units.</param>
        public static SurfaceDistances Compute(float[] reconstruction, float[] truth, bool[] observed, double threshold)
        {
            if (reconstruction == null || reconstruction.Length == 0 || reconstruction.Length % 3 != 0) throw new ArgumentException("The reconstruction needs at least one point.", nameof(reconstruction));
            if (truth == null || truth.Length == 0 || truth.Length % 3 != 0) throw new ArgumentException("The ground truth needs at least one point.", nameof(truth));
            if (observed != null && observed.Length * 3 != truth.Length) throw new ArgumentException("observed needs one flag per ground-truth point.", nameof(observed));
            if (!(threshold > 0)) throw new ArgumentException("The threshold must be positive.", nameof(threshold));
            var result = new SurfaceDistances { Threshold = threshold, ReconstructionPoints = reconstruction.Length / 3, TruthPoints = truth.Length / 3 };

            // Both trees first: each side is then queried in the other tree's spatially coherent order (same sums, far fewer cache misses).
            var truthTree = new PointKdTree(truth);
            var reconstructionTree = new PointKdTree(reconstruction);
            double sum = 0;
            long close = 0;
            var t2 = threshold * threshold;
            for (var i = 0; i < reconstructionTree.Count; i++)
            {
                reconstructionTree.PointAt(i, out var x, out var y, out var z);
                var d2 = truthTree.NearestDistanceSquared(x, y, z);
                sum += Math.Sqrt(d2);
                if (d2 < t2) close++;
            }
            result.Accuracy = sum / result.ReconstructionPoints;
            result.Precision = (double)close / result.ReconstructionPoints;

            sum = 0;
            close = 0;
            var counted = 0;
            for (var i = 0; i < truthTree.Count; i++)
            {
                if (observed != null && !observed[truthTree.OriginalIndex(i)]) continue;
                counted++;
                truthTree.PointAt(i, out var x, out var y, out var z);
                var d2 = reconstructionTree.NearestDistanceSquared(x, y, z);
                sum += Math.Sqrt(d2);
                if (d2 < t2) close++;
            }
            result.ObservedTruthPoints = counted;
            result.Completeness = counted > 0 ? sum / counted : double.NaN;
            result.Recall = counted > 0 ? (double)close / counted : double.NaN;
            return result;
        }
    }
}
