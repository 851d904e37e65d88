using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Net;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>report.html</c>: one self-contained page (pictures as PNG data URIs, the chart as inline SVG, no script, no
    /// external file) — the summary table, the per-view PSNR chart, then per view the ground truth (composited on the
    /// stated background), the render and the error map side by side with that view's figures.
    /// </summary>
    public static class ReportHtml
    {
        public const string FileName = "report.html";

        public static string Build(EvaluationResult r)
        {
            var h = new StringBuilder();
            h.Append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Evaluation: ").Append(E(System.IO.Path.GetFileName(r.DatasetFolder))).Append(" / ").Append(E(r.Split)).Append("</title>\n");
            h.Append("<meta name=\"generator\" content=\"").Append(E(MetricsJson.Generator)).Append("\">\n<style>\n")
             .Append("body{font:14px/1.4 system-ui,sans-serif;margin:24px;color:#222;background:#fafafa}h1{font-size:20px;margin:0 0 4px}h2{font-size:16px;margin:24px 0 8px}")
             .Append("table{border-collapse:collapse}td,th{padding:3px 10px;border-bottom:1px solid #ddd;text-align:right}th{background:#eee}td.l,th.l{text-align:left}")
             .Append(".meta{color:#555;font-size:12px}.view{display:flex;gap:8px;align-items:flex-start;margin:10px 0;padding:8px;background:#fff;border:1px solid #e3e3e3}")
             .Append(".view figure{margin:0}.view figcaption{font-size:11px;color:#666;text-align:center}.view .f{font-size:12px;min-width:190px}img{display:block;image-rendering:auto}\n</style></head><body>\n");
            h.Append("<h1>").Append(E(System.IO.Path.GetFileName(r.DatasetFolder))).Append(" — ").Append(E(r.Split)).Append(" split, ").Append(r.Views.Count).Append(" views</h1>\n");
            h.Append("<div class=\"meta\">Dataset ").Append(E(r.DatasetFolder)).Append("<br>Renders ").Append(E(r.Renders.Folder)).Append(" (").Append(E(RenderLayouts.Name(r.Renders.Layout))).Append(" layout)<br>Background ")
             .Append(E(r.Background.Describe())).Append("<br>").Append(E(r.CreatedUtc)).Append(" · ").Append(E(MetricsJson.Generator)).Append(' ').Append(E(PluginInfo.Version)).Append("</div>\n");
            h.Append("<p class=\"meta\">Protocol: ").Append(E(r.Protocol != null ? r.Protocol.Describe() + " (" + EvalProtocolFile.FileName + ")" : "none (no " + EvalProtocolFile.FileName + "): defaults used")).Append("</p>\n");
            foreach (var warning in r.Warnings) h.Append("<p style=\"color:#b00020;font-weight:bold\">Warning: ").Append(E(warning)).Append("</p>\n");
            foreach (var note in r.Notes.Concat(r.Renders.Notes)) h.Append("<p class=\"meta\">").Append(E(note)).Append("</p>\n");

            // Summary.
            h.Append("<h2>Mean over views</h2>\n<table><tr><th class=\"l\">metric</th><th>value</th><th class=\"l\">definition</th></tr>\n");
            var identical = r.Views.Count(v => double.IsPositiveInfinity(v.Psnr));
            Row(h, "PSNR (dB)", F(MetricsJson.FiniteMean(r.Views.Select(v => v.Psnr)), "0.00") + (identical > 0 ? " (+ " + identical + " identical)" : ""), MetricsJson.Definitions["psnr"]);
            Row(h, "SSIM", F(MetricsJson.Mean(r.Views.Select(v => v.Ssim)), "0.0000"), MetricsJson.Definitions["ssim"]);
            if (r.HasMasks) Row(h, "PSNR in the mask (dB)", F(MetricsJson.FiniteMean(r.Views.Select(v => v.MaskedPsnr)), "0.00"), MetricsJson.Definitions["psnr_masked"]);
            if (r.Views.Count > 0 && r.Views.All(v => v.Depth != null))
            {
                Row(h, "depth abs-rel", F(MetricsJson.Mean(r.Views.Select(v => v.Depth.AbsRel).Where(x => !double.IsNaN(x))), "0.0000"), MetricsJson.Definitions["depth"]);
                Row(h, "depth RMSE (output units)", F(MetricsJson.Mean(r.Views.Select(v => v.Depth.Rmse).Where(x => !double.IsNaN(x))), "0.0000"), "");
                Row(h, "depth δ < 1.25", F(MetricsJson.Mean(r.Views.Select(v => v.Depth.Delta125).Where(x => !double.IsNaN(x))), "0.0000"), "");
            }
            if (r.Views.Count > 0 && r.Views.All(v => v.Normals != null))
                Row(h, "normal error (°)", F(MetricsJson.Mean(r.Views.Select(v => v.Normals.MeanDegrees).Where(x => !double.IsNaN(x))), "0.00"), MetricsJson.Definitions["normals"]);
            Row(h, "LPIPS", r.Trainer?.Lpips is double lp ? F(lp, "0.0000") + " (" + r.Trainer.Source + ")" : "—",
                r.Trainer?.Lpips != null ? r.Trainer.LpipsVariant : MetricsJson.Definitions["lpips"]);
            if (r.Geometry != null)
            {
                var d = r.Geometry.Distances;
                Row(h, "accuracy", F(d.Accuracy, "0.00000"), MetricsJson.Definitions["chamfer"]);
                Row(h, "completeness", F(d.Completeness, "0.00000"), r.Geometry.ObservedRule);
                Row(h, "Chamfer", F(d.Chamfer, "0.00000"), "");
                Row(h, "precision / recall", F(d.Precision, "0.0000") + " / " + F(d.Recall, "0.0000"), MetricsJson.Definitions["fscore"]);
                Row(h, "F-score", F(d.FScore, "0.0000"), "threshold " + F(d.Threshold, "0.#####") + " = " + r.Geometry.ThresholdRule);
                if (r.Geometry.Step.HasValue) Row(h, "time step", r.Geometry.Step.Value.ToString(CultureInfo.InvariantCulture), r.Geometry.TruthSource);
            }
            if (r.GeometrySteps.Count > 0)
            {
                var mean = MetricsJson.GeometryMean(r.GeometrySteps);
                Row(h, "Chamfer, mean over " + r.GeometrySteps.Count + " time steps", F(MetricsJson.Mean(r.GeometrySteps.Select(g => g.Distances.Chamfer)), "0.00000"), (string)mean["rule"]);
                Row(h, "F-score, mean over time steps", F(MetricsJson.Mean(r.GeometrySteps.Select(g => g.Distances.FScore)), "0.0000"), "threshold " + F(r.GeometrySteps[0].Distances.Threshold, "0.#####") + " = " + r.GeometrySteps[0].ThresholdRule);
                foreach (var g in r.GeometrySteps)
                    Row(h, "step " + g.Step + (g.Time.HasValue ? " (time " + F(g.Time.Value, "0.####") + ")" : ""),
                        "Chamfer " + F(g.Distances.Chamfer, "0.00000") + ", F " + F(g.Distances.FScore, "0.0000"), Path.GetFileName(g.ReconstructionPath));
            }
            h.Append("</table>\n");
            if (r.Trainer != null) TrainerTable(h, r);

            h.Append("<h2>PSNR per view</h2>\n").Append(Chart(r)).Append('\n');

            h.Append("<h2>Views: ground truth · render · error</h2>\n");
            foreach (var v in r.Views)
            {
                h.Append("<div class=\"view\"><div class=\"f\"><b>").Append(E(v.FilePath)).Append("</b> (frame ").Append(v.FrameIndex).Append(")<br>PSNR ").Append(F(v.Psnr, "0.00")).Append(" dB<br>SSIM ").Append(F(v.Ssim, "0.0000"));
                if (r.Trainer?.Views != null && v.FrameIndex < r.Trainer.Views.Length && r.Trainer.Views[v.FrameIndex].Psnr is double theirs)
                    h.Append("<br>").Append(E(r.Trainer.Source)).Append(": PSNR ").Append(F(theirs, "0.00")).Append(" dB").Append(r.TrainerFlaggedViews.Contains(v.FrameIndex) ? " <b>(disagrees)</b>" : "");
                if (r.HasMasks) h.Append("<br>PSNR in mask ").Append(F(v.MaskedPsnr, "0.00")).Append(" dB");
                if (v.Depth != null) h.Append("<br>depth abs-rel ").Append(F(v.Depth.AbsRel, "0.0000")).Append(", RMSE ").Append(F(v.Depth.Rmse, "0.0000"));
                if (v.Normals != null) h.Append("<br>normals ").Append(F(v.Normals.MeanDegrees, "0.00")).Append('°');
                h.Append("<br><span class=\"meta\">").Append(E(System.IO.Path.GetFileName(v.RenderPath))).Append("</span></div>");
                Figure(h, v.TruthThumbnail, "ground truth");
                Figure(h, v.RenderThumbnail, "render");
                Figure(h, v.ErrorThumbnail, "|error|, full scale 0.2");
                h.Append("</div>\n");
            }
            h.Append("</body></html>\n");
            return h.ToString();
        }

        /// <summary>The trainer's own figures beside evaluate's, each comparison's tolerance and verdict (<see cref="TrainerComparison"/>).</summary>
        static void TrainerTable(StringBuilder h, EvaluationResult r)
        {
            var t = r.Trainer;
            h.Append("<h2>The trainer's own figures: ").Append(E(t.Source)).Append(" (").Append(E(t.Method)).Append(")</h2>\n<p class=\"meta\">").Append(E(t.File)).Append("</p>\n");
            h.Append("<table><tr><th class=\"l\">metric</th><th>evaluate</th><th>trainer</th><th>tolerance</th><th class=\"l\">verdict</th></tr>\n");
            foreach (var c in r.TrainerMeans)
            {
                var f = c.Metric == "psnr" ? "0.00" : "0.0000";
                h.Append("<tr><td class=\"l\">").Append(E(c.Metric.ToUpperInvariant())).Append("</td><td>").Append(F(c.Ours, f)).Append("</td><td>").Append(F(c.Theirs, f)).Append("</td><td>")
                 .Append(F(c.Tolerance, c.Metric == "psnr" ? "0.00" : "0.000")).Append("</td><td class=\"l\">")
                 .Append(E(!c.Compared ? "shown, not compared (" + (c.Metric == "ssim" ? t.SsimVariant : "another split") + ")" : c.Flagged ? "DISAGREES: another background or resolution?" : "agrees")).Append("</td></tr>\n");
            }
            if (t.Lpips is double lpips) h.Append("<tr><td class=\"l\">LPIPS</td><td>—</td><td>").Append(F(lpips, "0.0000")).Append("</td><td></td><td class=\"l\">").Append(E(t.LpipsVariant)).Append("</td></tr>\n");
            h.Append("</table>\n");
            if (r.TrainerFlaggedViews.Count > 0)
                h.Append("<p class=\"meta\">Views whose trainer PSNR differs beyond the tolerance: frames ").Append(E(string.Join(", ", r.TrainerFlaggedViews))).Append("</p>\n");
            foreach (var note in t.Notes) h.Append("<p class=\"meta\">").Append(E(note)).Append("</p>\n");
        }

        static void Row(StringBuilder h, string name, string value, string definition) =>
            h.Append("<tr><td class=\"l\">").Append(E(name)).Append("</td><td>").Append(E(value)).Append("</td><td class=\"l meta\">").Append(E(definition)).Append("</td></tr>\n");

        static void Figure(StringBuilder h, byte[] png, string caption)
        {
            if (png == null) return;
            h.Append("<figure><img alt=\"").Append(E(caption)).Append("\" src=\"data:image/png;base64,").Append(Convert.ToBase64String(png)).Append("\"><figcaption>").Append(E(caption)).Append("</figcaption></figure>");
        }

        /// <summary>An SVG bar chart of per-view PSNR with the mean as a line; infinite PSNR (identical) is drawn at the top.</summary>
        public static string Chart(EvaluationResult r)
        {
            const int width = 820, height = 220, left = 44, right = 10, top = 10, bottom = 28;
            var finite = r.Views.Select(v => v.Psnr).Where(p => !double.IsInfinity(p) && !double.IsNaN(p)).ToList();
            var max = finite.Count > 0 ? Math.Ceiling(finite.Max() / 5 + 0.2) * 5 : 50;
            var min = finite.Count > 0 ? Math.Max(0, Math.Floor(finite.Min() / 5 - 0.2) * 5) : 0;
            if (max <= min) max = min + 5;
            double Y(double psnr) => top + (height - top - bottom) * (1 - (Math.Min(max, psnr) - min) / (max - min));
            var s = new StringBuilder();
            s.Append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").Append(width).Append("\" height=\"").Append(height).Append("\" viewBox=\"0 0 ").Append(width).Append(' ').Append(height).Append("\" font-size=\"11\" font-family=\"sans-serif\">");
            s.Append("<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>");
            for (var g = min; g <= max + 1e-9; g += 5)
            {
                var y = Y(g);
                s.Append("<line x1=\"").Append(left).Append("\" x2=\"").Append(width - right).Append("\" y1=\"").Append(N(y)).Append("\" y2=\"").Append(N(y)).Append("\" stroke=\"#ddd\"/>");
                s.Append("<text x=\"").Append(left - 4).Append("\" y=\"").Append(N(y + 4)).Append("\" text-anchor=\"end\" fill=\"#555\">").Append(N(g)).Append("</text>");
            }
            var n = Math.Max(1, r.Views.Count);
            var slot = (double)(width - left - right) / n;
            for (var i = 0; i < r.Views.Count; i++)
            {
                var p = r.Views[i].Psnr;
                var y = double.IsNaN(p) ? Y(min) : Y(p);
                s.Append("<rect x=\"").Append(N(left + i * slot + slot * 0.1)).Append("\" y=\"").Append(N(y)).Append("\" width=\"").Append(N(Math.Max(0.5, slot * 0.8))).Append("\" height=\"").Append(N(Y(min) - y))
                 .Append("\" fill=\"#3b7dd8\"><title>").Append(E(r.Views[i].FilePath)).Append(": ").Append(F(p, "0.00")).Append(" dB</title></rect>");
            }
            var mean = MetricsJson.Mean(finite);
            if (!double.IsNaN(mean))
            {
                var y = Y(mean);
                s.Append("<line x1=\"").Append(left).Append("\" x2=\"").Append(width - right).Append("\" y1=\"").Append(N(y)).Append("\" y2=\"").Append(N(y)).Append("\" stroke=\"#d8603b\" stroke-dasharray=\"4 3\"/>");
                s.Append("<text x=\"").Append(width - right).Append("\" y=\"").Append(N(y - 4)).Append("\" text-anchor=\"end\" fill=\"#d8603b\">mean ").Append(F(mean, "0.00")).Append(" dB</text>");
            }
            s.Append("<text x=\"").Append(left).Append("\" y=\"").Append(height - 8).Append("\" fill=\"#555\">view (frame order of transforms_").Append(E(r.Split)).Append(".json), PSNR in dB</text>");
            s.Append("</svg>");
            return s.ToString();
        }

        static string F(double v, string format) => double.IsNaN(v) ? "—" : double.IsPositiveInfinity(v) ? "∞" : v.ToString(format, CultureInfo.InvariantCulture);
        static string N(double v) => v.ToString("0.##", CultureInfo.InvariantCulture);
        static string E(string s) => WebUtility.HtmlEncode(s ?? "");
    }
}
