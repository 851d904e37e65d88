using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>One figure side by side: evaluate's, the trainer's, and whether they disagree by more than the tolerance.</summary>
    public sealed class TrainerMetricComparison
    {
        public string Metric;
        public double Ours, Theirs, Tolerance;
        public bool Compared;
        public bool Flagged => Compared && !(Math.Abs(Ours - Theirs) <= Tolerance);
    }

    /// <summary>
    /// Puts a trainer's own figures (<see cref="TrainerFigures"/>) beside evaluate's and flags a disagreement beyond the
    /// stated tolerance: the same renders scored to another PSNR mean the trainer's ground truth was another image —
    /// composited over another background, or at another resolution (issue 35; the background alone moves PSNR by ~0.6 dB).
    /// </summary>
    public static class TrainerComparison
    {
        public static List<TrainerMetricComparison> Means(TrainerFigures t, IReadOnlyList<ViewResult> views, bool comparable)
        {
            var list = new List<TrainerMetricComparison>();
            if (t?.Psnr is double psnr)
                list.Add(new TrainerMetricComparison { Metric = "psnr", Ours = MetricsJson.FiniteMean(views.Select(v => v.Psnr)), Theirs = psnr, Tolerance = t.PsnrTolerance, Compared = comparable });
            if (t?.Ssim is double ssim)
                list.Add(new TrainerMetricComparison { Metric = "ssim", Ours = MetricsJson.Mean(views.Select(v => v.Ssim)), Theirs = ssim, Tolerance = TrainerResults.GaussianSsimTolerance, Compared = comparable && t.SsimComparable });
            return list;
        }

        /// <summary>The frames whose trainer PSNR differs from evaluate's by more than the tolerance, in frame order.</summary>
        public static List<int> FlaggedViews(TrainerFigures t, IReadOnlyList<ViewResult> views)
        {
            var flagged = new List<int>();
            if (t?.Views == null) return flagged;
            foreach (var v in views)
                if (v.FrameIndex < t.Views.Length && t.Views[v.FrameIndex].Psnr is double theirs && !double.IsInfinity(v.Psnr) && !(Math.Abs(v.Psnr - theirs) <= t.PsnrTolerance))
                    flagged.Add(v.FrameIndex);
            return flagged;
        }

        /// <summary>The warning for a flagged mean, naming both figures, the tolerance and the likely causes.</summary>
        public static string Warning(TrainerFigures t, TrainerMetricComparison c, EvaluationBackground background)
        {
            var f = c.Metric == "psnr" ? "0.00" : "0.0000";
            var unit = c.Metric == "psnr" ? " dB" : "";
            return t.Source + "'s " + c.Metric.ToUpperInvariant() + " " + c.Theirs.ToString(f, CultureInfo.InvariantCulture) + unit + " (" + t.File + ") differs from evaluate's " +
                   c.Ours.ToString(f, CultureInfo.InvariantCulture) + unit + " by " + Math.Abs(c.Ours - c.Theirs).ToString(f, CultureInfo.InvariantCulture) + unit +
                   " (tolerance " + c.Tolerance.ToString(c.Metric == "psnr" ? "0.00" : "0.000", CultureInfo.InvariantCulture) + unit + "): the trainer scored against another ground truth — another background than " +
                   background.Name + " (3DGS: -w in cfg_args; nerfstudio: the model's background_color) or another resolution (3DGS -r, nerfstudio --downscale-factor).";
        }
    }
}
