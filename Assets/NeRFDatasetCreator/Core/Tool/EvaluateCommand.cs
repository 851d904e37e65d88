using System;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset evaluate d --renders r …</c>: <see cref="RenderEvaluator.Run"/>, then the means and where the
    /// report is. Exit 1 when the inputs are refused (nothing written) or a file fails.
    /// </summary>
    public static class EvaluateCommand
    {
        public static int Run(EvaluationOptions options, TextWriter stdout, TextWriter stderr)
        {
            EvaluationResult result;
            try
            {
                result = RenderEvaluator.Run(options, line => stderr.WriteLine("… " + line));
            }
            catch (InvalidParameterException e)
            {
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                stderr.WriteLine("evaluate refused: nothing was written.");
                return ToolExitCodes.Failure;
            }
            catch (InvalidDataException e)
            {
                stderr.WriteLine("error: " + e.Message);
                stderr.WriteLine("evaluate stopped on a file it cannot read.");
                return ToolExitCodes.Failure;
            }
            foreach (var note in result.Notes.Concat(result.Renders.Notes)) stdout.WriteLine("note: " + note);
            var json = MetricsJson.Build(result);
            var mean = json["mean"];
            stdout.WriteLine("evaluated " + result.Views.Count + " " + result.Split + " views (" + RenderLayouts.Name(result.Renders.Layout) + " layout, background " + result.Background.Name + "):");
            var identical = (int)mean["identical_views"];
            stdout.WriteLine("  PSNR " + Show(mean["psnr"], "0.00") + " dB" + (identical > 0 ? " (" + identical + " identical views, PSNR ∞, left out)" : "") + ", SSIM " + Show(mean["ssim"], "0.0000") +
                             (mean["psnr_masked"] != null ? ", PSNR in mask " + Show(mean["psnr_masked"], "0.00") + " dB" : ""));
            if (mean["depth"] != null) stdout.WriteLine("  depth abs-rel " + Show(mean["depth"]["abs_rel"], "0.0000") + ", RMSE " + Show(mean["depth"]["rmse"], "0.0000") + ", δ<1.25 " + Show(mean["depth"]["delta_1_25"], "0.0000"));
            if (mean["normals"] != null) stdout.WriteLine("  normals " + Show(mean["normals"]["mean_degrees"], "0.00") + "° mean angular error");
            if (result.Geometry != null)
            {
                var g = json["geometry"];
                stdout.WriteLine("  geometry: Chamfer " + Show(g["chamfer"], "0.00000") + " (accuracy " + Show(g["accuracy"], "0.00000") + ", completeness " + Show(g["completeness"], "0.00000") +
                                 "), F-score " + Show(g["fscore"], "0.0000") + " at " + Show(g["threshold"], "0.#####") + " output units");
            }
            if (result.GeometrySteps.Count > 0)
            {
                var g = json["geometry_mean_over_steps"];
                stdout.WriteLine("  geometry over " + result.GeometrySteps.Count + " time steps: mean Chamfer " + Show(g["chamfer"], "0.00000") + " (accuracy " + Show(g["accuracy"], "0.00000") +
                                 ", completeness " + Show(g["completeness"], "0.00000") + "), mean F-score " + Show(g["fscore"], "0.0000"));
                foreach (var step in json["geometry_steps"])
                    stdout.WriteLine("    step " + step["step"] + ": Chamfer " + Show(step["chamfer"], "0.00000") + ", F-score " + Show(step["fscore"], "0.0000"));
            }
            else if (result.Geometry?.Step != null) stdout.WriteLine("  geometry at time step " + result.Geometry.Step.Value);
            stdout.WriteLine("  LPIPS is not computed (it needs network weights): 3DGS python metrics.py -m <model>, nerfstudio ns-eval.");
            stdout.WriteLine("wrote " + Path.Combine(result.OutFolder, MetricsJson.FileName) + ", " + Path.Combine(result.OutFolder, ReportHtml.FileName) + " and " + result.Views.Count + " error maps in " +
                             Path.Combine(result.OutFolder, EvaluationOutput.ErrorFolder));
            return ToolExitCodes.Success;
        }

        static string Show(Newtonsoft.Json.Linq.JToken token, string format) =>
            token == null || token.Type == Newtonsoft.Json.Linq.JTokenType.Null ? "—" : ((double)token).ToString(format, System.Globalization.CultureInfo.InvariantCulture);
    }
}
