using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The motion metrics of <c>evaluate --flow</c>, computed as the 4D papers compute them (citations:
    /// Documentation~/maintainers/evaluate.md, "Flow and tracks").
    /// <list type="bullet">
    /// <item><b>EPE</b> (end-point error): per frame pair the mean of ‖F̂(p) − F(p)‖₂ over the scored pixels, then the
    /// mean over pairs that have any — Shape of Motion's aggregation (scripts/evaluate_iphone.py, evaluate_3d_tracking:
    /// a norm per point, <c>frame_epes.mean()</c> per pair, <c>np.mean</c> over pairs with points).</item>
    /// <item><b>PCK-T</b>: per pair (query frame q, frame t ≠ q) the share of the points visible in both whose predicted
    /// position is nearer than <see cref="PckRatio"/>·max(W, H) to the truth (strictly), then the mean over pairs that have
    /// such points — DyCheck's <c>compute_pck</c> (dycheck/core/metrics/keypoint.py: <c>dists &lt; ratio * max(img_wh)</c>,
    /// ratio 0.05) as its keypoint-transfer task applies it (dycheck/core/tasks/kp_transfer.py: common keypoints visible in
    /// both frames, pairs without any skipped, the mean over pairs).</item>
    /// </list>
    /// A NaN prediction is never within the threshold (NumPy's <c>nan &lt; t</c> is False).
    /// </summary>
    public static class FlowMetrics
    {
        /// <summary>DyCheck's threshold ratio of the image's larger side (compute_pck's and KeypointTransfer's default).</summary>
        public const double PckRatio = 0.05;

        /// <summary>The PCK-T distance threshold, pixels, for a W × H image.</summary>
        public static double PckThreshold(int width, int height) => PckRatio * Math.Max(width, height);

        /// <summary>Mean end-point error over the pixels <paramref name="scored"/> picks; NaN (and 0 pixels) when it picks none.</summary>
        /// <param name="truth">(dx, dy) per pixel.</param>
        /// <param name="predicted">(dx, dy) per pixel, the same size.</param>
        public static double Epe(float[] truth, float[] predicted, Func<int, bool> scored, out int pixels)
        {
            if (truth.Length != predicted.Length) throw new ArgumentException("The predicted flow has " + predicted.Length / 2 + " pixels, the truth " + truth.Length / 2 + ".");
            double sum = 0;
            pixels = 0;
            for (var p = 0; p < truth.Length / 2; p++)
            {
                if (!scored(p)) continue;
                double dx = predicted[2 * p] - truth[2 * p], dy = predicted[2 * p + 1] - truth[2 * p + 1];
                sum += Math.Sqrt(dx * dx + dy * dy);
                pixels++;
            }
            return pixels == 0 ? double.NaN : sum / pixels;
        }

        /// <summary>
        /// PCK-T of one tracks file: per frame t ≠ <paramref name="queryFrame"/>, the share of the points visible at the query
        /// frame and at t (state 1) whose prediction lies strictly within <paramref name="threshold"/> pixels of the truth;
        /// pairs without such points are left out. Arrays are frame-major: xy[(t·N + n)·2 + c], state[t·N + n].
        /// </summary>
        public static List<PckPair> PckT(float[] truthXy, byte[] state, float[] predictedXy, int frames, int points, int queryFrame, double threshold)
        {
            var pairs = new List<PckPair>();
            for (var t = 0; t < frames; t++)
            {
                if (t == queryFrame) continue;
                int common = 0, correct = 0;
                for (var n = 0; n < points; n++)
                {
                    if (state[queryFrame * points + n] != (byte)FlowState.Visible || state[t * points + n] != (byte)FlowState.Visible) continue;
                    common++;
                    var k = 2 * (t * points + n);
                    double dx = predictedXy[k] - truthXy[k], dy = predictedXy[k + 1] - truthXy[k + 1];
                    if (Math.Sqrt(dx * dx + dy * dy) < threshold) correct++;
                }
                if (common > 0) pairs.Add(new PckPair(queryFrame, t, common, (double)correct / common));
            }
            return pairs;
        }

        /// <summary>The mean over pairs of the per-pair figures that exist (not NaN); NaN when none does.</summary>
        public static double MeanOverPairs(IEnumerable<double> perPair)
        {
            var values = perPair.Where(v => !double.IsNaN(v)).ToList();
            return values.Count == 0 ? double.NaN : values.Average();
        }
    }

    /// <summary>One (query frame, frame) pair's PCK-T: how many points were visible in both, and the share within the threshold.</summary>
    public sealed class PckPair
    {
        public PckPair(int queryFrame, int frame, int points, double pck)
        {
            QueryFrame = queryFrame;
            Frame = frame;
            Points = points;
            Pck = pck;
        }

        public int QueryFrame { get; }
        public int Frame { get; }
        public int Points { get; }
        public double Pck { get; }
    }
}
