using System;
using System.IO;
using System.Linq;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Tools ▸ NeRF Dataset Creator ▸ Evaluate Renders…: the same as <c>nerf-dataset evaluate &lt;dataset&gt; --renders
    /// &lt;folder&gt;</c> with its defaults (test split, layout detected, white background, out folder
    /// <c>&lt;renders&gt;/evaluation-test</c>), all in Core's <see cref="RenderEvaluator"/>; then the report opens in the
    /// browser. Two folder pickers (EditorUtility.OpenFolderPanel, as the window's folder picker uses it) and a progress
    /// bar: the evaluation blocks the editor while it runs (a few hundred ms of CPU per 800×800 view). MenuItem paths
    /// with a trailing "…" are Unity's convention for items that open a dialog (Scripting API: MenuItem).
    /// </summary>
    public static class EvaluateRendersMenu
    {
        const string MenuPath = "Tools/NeRF Dataset Creator/Evaluate Renders...";

        [MenuItem(MenuPath)]
        static void Open()
        {
            var project = Path.GetDirectoryName(Application.dataPath);
            var dataset = EditorUtility.OpenFolderPanel("Dataset folder (holds transforms_test.json)", Path.Combine(project, "NeRFDatasets"), "");
            if (string.IsNullOrEmpty(dataset)) return;
            var renders = EditorUtility.OpenFolderPanel("The trainer's renders of the test split (3DGS model folder, ns-render output, screenshots)", Path.GetDirectoryName(dataset), "");
            if (string.IsNullOrEmpty(renders)) return;
            EditorUtility.DisplayProgressBar("NeRF Dataset Creator", "Evaluating the renders in " + renders + "…", 0.5f);
            string message, report;
            bool ok;
            try
            {
                ok = Evaluate(dataset, renders, out message, out report);
            }
            finally
            {
                EditorUtility.ClearProgressBar();
            }
            if (!ok)
            {
                Debug.LogError(message);
                EditorUtility.DisplayDialog("Evaluate renders", message, "OK");
                return;
            }
            Debug.Log(message);
            // Application.OpenURL opens a file:// URL in the default browser (Scripting API: Application.OpenURL).
            Application.OpenURL(new Uri(report).AbsoluteUri);
        }

        /// <summary>Runs the evaluation; the Console line (means, or every problem) and the report's path.</summary>
        public static bool Evaluate(string dataset, string renders, out string message, out string report)
        {
            report = null;
            try
            {
                var result = RenderEvaluator.Run(new EvaluationOptions { DatasetFolder = dataset, RendersFolder = renders });
                report = Path.Combine(result.OutFolder, ReportHtml.FileName);
                var mean = MetricsJson.Build(result)["mean"];
                message = "NeRF Dataset Creator: evaluated " + result.Views.Count + " " + result.Split + " views (" + RenderLayouts.Name(result.Renders.Layout) +
                          " layout): PSNR " + Show(mean["psnr"], "0.00") + " dB, SSIM " + Show(mean["ssim"], "0.0000") +
                          (mean["psnr_masked"] != null ? ", PSNR in mask " + Show(mean["psnr_masked"], "0.00") + " dB" : "") + ". Report: " + report;
                return true;
            }
            catch (InvalidParameterException e)
            {
                message = "NeRF Dataset Creator: nothing was evaluated —\n" + string.Join("\n", e.Problems.Select(p => "  " + p));
                return false;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                message = "NeRF Dataset Creator: the evaluation failed: " + e.Message;
                return false;
            }
        }

        static string Show(Newtonsoft.Json.Linq.JToken token, string format) =>
            token == null || token.Type == Newtonsoft.Json.Linq.JTokenType.Null ? "—" : ((double)token).ToString(format, System.Globalization.CultureInfo.InvariantCulture);
    }
}
