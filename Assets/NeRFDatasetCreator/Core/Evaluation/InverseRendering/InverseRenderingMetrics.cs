using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The inverse-rendering metrics exactly as the trainers compute them (Documentation~/maintainers/layouts-inverse-rendering.md
    /// cites the lines): TensoIR's median-scaled albedo PSNR (renderer.py:12–53, 274–289, 392–394, 462–468 at
    /// Haian-Jin/TensoIR 8f7b8dd), its normal mean angular error (:359, :367–368, :470), and R3DG's roughness MSE
    /// (eval_relighting_syn4.py:163, :183, :198, :212 at NJU-3DV/Relightable3DGaussian a102f14). Images are per-pixel
    /// arrays, top row first, three values per pixel unless said otherwise.
    /// </summary>
    public static class InverseRenderingMetrics
    {
        /// <summary>One view's albedo: the truth blended over white by its alpha (TensoIR :213), the mask (alpha ≠ 0, :203) and the prediction.</summary>
        public sealed class AlbedoView
        {
            public double[] Truth, Prediction;
            public bool[] Mask;
        }

        /// <summary>How the prediction is scaled to the truth before the PSNR.</summary>
        public enum AlbedoScaling
        {
            /// <summary>TensoIR's headline (test_all): one ratio per channel, the median over the sampled views' masked pixels (renderer.py:12–53, 206–208, 285–289).</summary>
            ThreeChannelGlobal,
            /// <summary>One ratio from the first channel for all three, over the sampled views (:49, :279–283).</summary>
            SingleChannelGlobal,
            /// <summary>One ratio per channel per view, over that view's masked pixels (:288).</summary>
            ThreeChannelPerView,
            /// <summary>One first-channel ratio per view (:282).</summary>
            SingleChannelPerView,
        }

        /// <summary>torch.median: the LOWER of the two middle values for an even count (element (n − 1) // 2 of the sorted values).</summary>
        public static double LowerMedian(IEnumerable<double> values)
        {
            var sorted = values.OrderBy(v => v).ToList();
            if (sorted.Count == 0) return double.NaN;
            return sorted[(sorted.Count - 1) / 2];
        }

        /// <summary>The views compute_rescale_ratio samples (renderer.py:21–24): sampled_num = 20, interval = N // 20, views i·interval (view 0 twenty times when N &lt; 20).</summary>
        public static int[] SampledViews(int count, int sampled = 20)
        {
            var interval = count / sampled;
            return Enumerable.Range(0, sampled).Select(i => i * interval).ToArray();
        }

        /// <summary>The scale ratios of <paramref name="views"/> pooled: per channel (or channel 0 for all) the lower median of truth / max(prediction, 1e-6) over masked pixels (:44–50).</summary>
        public static double[] Ratios(IEnumerable<AlbedoView> views, bool threeChannels)
        {
            var pooled = new[] { new List<double>(), new List<double>(), new List<double>() };
            foreach (var view in views)
                for (var i = 0; i < view.Mask.Length; i++)
                    if (view.Mask[i])
                        for (var c = 0; c < 3; c++) pooled[c].Add(view.Truth[3 * i + c] / Math.Max(view.Prediction[3 * i + c], 1e-6));
            if (!threeChannels)
            {
                var single = LowerMedian(pooled[0]);
                return new[] { single, single, single };
            }
            return pooled.Select(LowerMedian).ToArray();
        }

        /// <summary>
        /// TensoIR's albedo PSNR: the aligned map is 1 (white) everywhere but the mask, clamp(ratio·prediction, 0, 1) inside
        /// (:274–289); truth and aligned map both raised to 1/2.2 (:392–394) and the MSE pooled over every view, pixel and
        /// channel (:462–468).
        /// </summary>
        public static double AlbedoPsnr(IReadOnlyList<AlbedoView> views, AlbedoScaling scaling, out double[] globalRatios)
        {
            globalRatios = null;
            var three = scaling == AlbedoScaling.ThreeChannelGlobal || scaling == AlbedoScaling.ThreeChannelPerView;
            if (scaling == AlbedoScaling.ThreeChannelGlobal || scaling == AlbedoScaling.SingleChannelGlobal)
                globalRatios = Ratios(SampledViews(views.Count).Select(i => views[i]), three);
            double sum = 0;
            long count = 0;
            foreach (var view in views)
            {
                var ratio = globalRatios ?? Ratios(new[] { view }, three);
                for (var i = 0; i < view.Mask.Length; i++)
                    for (var c = 0; c < 3; c++)
                    {
                        var aligned = view.Mask[i] ? Math.Max(0, Math.Min(1, ratio[c] * view.Prediction[3 * i + c])) : 1.0;
                        var d = Math.Pow(view.Truth[3 * i + c], 1 / 2.2) - Math.Pow(aligned, 1 / 2.2);
                        sum += d * d;
                        count++;
                    }
            }
            return Psnr.FromMse(sum / count);
        }

        /// <summary>
        /// Mean angular error in degrees of unit normals: arccos(clip(n_truth · n_prediction, −1, 1)) averaged over every
        /// pixel of every view (TensoIR renderer.py:470, GS-IR normal_eval.py), or only where <paramref name="mask"/> holds.
        /// A zero prediction (F.normalize leaves it zero) is 90° off.
        /// </summary>
        public static double NormalMaeDegrees(IReadOnlyList<(double[] truth, double[] prediction, bool[] mask)> views, bool targetOnly)
        {
            double sum = 0;
            long count = 0;
            foreach (var (truth, prediction, mask) in views)
                for (var i = 0; i < truth.Length / 3; i++)
                {
                    if (targetOnly && !mask[i]) continue;
                    var dot = truth[3 * i] * prediction[3 * i] + truth[3 * i + 1] * prediction[3 * i + 1] + truth[3 * i + 2] * prediction[3 * i + 2];
                    sum += Math.Acos(Math.Max(-1, Math.Min(1, dot))) * 180 / Math.PI;
                    count++;
                }
            return count == 0 ? double.NaN : sum / count;
        }

        /// <summary>F.normalize (eps 1e-12) of a three-value-per-pixel array.</summary>
        public static double[] Normalise(double[] v)
        {
            var n = new double[v.Length];
            for (var i = 0; i < v.Length; i += 3)
            {
                var length = Math.Max(1e-12, Math.Sqrt(v[i] * v[i] + v[i + 1] * v[i + 1] + v[i + 2] * v[i + 2]));
                for (var c = 0; c < 3; c++) n[i + c] = v[i + c] / length;
            }
            return n;
        }

        /// <summary>
        /// R3DG's roughness MSE: per view both maps composited over the background by the mask m (the relit image's alpha,
        /// :142, :163, :183) — so a pixel counts as (m·(prediction − truth))² — averaged over all its pixels, then over the
        /// views (:198, :212). One value per pixel (R = G = B).
        /// </summary>
        public static double RoughnessMse(IReadOnlyList<(double[] truth, double[] prediction, double[] mask)> views)
        {
            double total = 0;
            foreach (var (truth, prediction, mask) in views)
            {
                double sum = 0;
                for (var i = 0; i < truth.Length; i++)
                {
                    var d = mask[i] * (prediction[i] - truth[i]);
                    sum += d * d;
                }
                total += sum / truth.Length;
            }
            return total / views.Count;
        }
    }
}
