using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Reads the figures trainers write about their own test renders, so LPIPS (which needs network weights this tool
    /// does not ship) and the trainer's PSNR/SSIM stand beside evaluate's:
    /// <list type="bullet">
    /// <item>3DGS <c>metrics.py</c> (graphdeco-inria/gaussian-splatting 15d64e6, lines 67–77): <c>&lt;model&gt;/results.json</c>
    /// = <c>{"ours_&lt;iter&gt;": {"SSIM", "PSNR", "LPIPS"}}</c> (means) and <c>per_view.json</c> = <c>{"ours_&lt;iter&gt;": {"SSIM":
    /// {"00000.png": v, …}, "PSNR": …, "LPIPS": …}}</c>, one entry per file of <c>test/ours_&lt;iter&gt;/renders</c>;</item>
    /// <item>nerfstudio <c>ns-eval</c> (nerfstudio 50e0e3c scripts/eval.py lines 50–60): <c>{"experiment_name", "method_name",
    /// "checkpoint", "results": {"psnr", "psnr_std", "ssim", …, "lpips", …}}</c>, means only (base_pipeline.py
    /// get_average_image_metrics, lines 402–416).</item>
    /// </list>
    /// Per-view figures are matched to the split's frames by name (3DGS's 00000.png is frame 0) and used only when the
    /// file lists exactly the split's views.
    /// </summary>
    public static class TrainerResults
    {
        public const string GaussianResults = "results.json", GaussianPerView = "per_view.json";

        /// <summary>3DGS metrics.py's SSIM is this tool's formula (in float32); its PSNR is over the same 8-bit PNGs.</summary>
        public const double GaussianPsnrTolerance = 0.05, GaussianSsimTolerance = 0.001;

        /// <summary>ns-eval scores the model's float output, evaluate the 8-bit PNGs ns-render wrote: quantisation alone moves PSNR by a few hundredths of a dB.</summary>
        public const double NerfstudioPsnrTolerance = 0.1;

        /// <summary>
        /// The trainer's figures for these renders: from <paramref name="explicitPath"/> (<c>--trainer-metrics</c>), else
        /// found beside a 3DGS model (<c>results.json</c>) or an ns-eval JSON in the renders folder; null when there are none.
        /// </summary>
        public static TrainerFigures Find(string explicitPath, RenderSet renders, string rendersRoot, string split, int frames)
        {
            if (explicitPath != null)
            {
                if (!File.Exists(explicitPath))
                    throw Refuse(explicitPath, "does not exist.", "Name 3DGS metrics.py's results.json (in the model folder) or the JSON ns-eval wrote (its --output-path).");
                var json = Parse(explicitPath);
                if (IsNerfstudio(json)) return Nerfstudio(explicitPath, json);
                if (IsGaussian(json)) return Gaussian(explicitPath, json, IterationOf(renders), split, frames);
                throw Refuse(explicitPath, "is neither 3DGS metrics.py's results.json ({\"ours_<iter>\": {\"PSNR\": …}}) nor ns-eval's JSON ({\"method_name\": …, \"results\": {\"psnr\": …}}).",
                    "Name one of those two files.");
            }
            if (renders.Layout == RenderLayout.GaussianSplatting)
            {
                // renders.Folder is <model>/<split>/ours_<iter>/renders (RenderFolder.GaussianSplatting).
                var model = Path.GetDirectoryName(Path.GetDirectoryName(Path.GetDirectoryName(renders.Folder)));
                var results = model == null ? null : Path.Combine(model, GaussianResults);
                if (results == null || !File.Exists(results)) return null;
                try
                {
                    var json = Parse(results);
                    return IsGaussian(json) ? Gaussian(results, json, IterationOf(renders), split, frames) : null;
                }
                catch (InvalidParameterException e)
                {
                    // Found, not asked for: a damaged file is reported beside the figures, never a reason to stop.
                    var unread = new TrainerFigures { Source = "3dgs metrics.py", File = results };
                    unread.Notes.Add(string.Join(" ", e.Problems.Select(p => p.Value + " " + p.Reason)) + " The trainer's figures are not shown.");
                    return unread;
                }
            }
            // ns-eval writes where --output-path says; one put in the renders folder is found.
            if (Directory.Exists(rendersRoot))
                foreach (var file in Directory.GetFiles(rendersRoot, "*.json").OrderBy(f => f, StringComparer.Ordinal).Take(20))
                {
                    if (new FileInfo(file).Length > 1 << 20) continue;
                    JToken json;
                    try { json = Parse(file); }
                    catch (InvalidParameterException) { continue; }
                    if (IsNerfstudio(json)) return Nerfstudio(file, json);
                }
            return null;
        }

        static string IterationOf(RenderSet renders) =>
            renders.Layout == RenderLayout.GaussianSplatting ? Path.GetFileName(Path.GetDirectoryName(renders.Folder)) : null;

        static bool IsNerfstudio(JToken json) => json is JObject o && o["results"] is JObject r && o["method_name"] != null && r["psnr"] != null;

        static bool IsGaussian(JToken json) => json is JObject o && o.Count > 0 && o.Properties().All(p => p.Value is JObject m && m["PSNR"] != null);

        static TrainerFigures Nerfstudio(string path, JToken json)
        {
            var results = (JObject)json["results"];
            var method = json["method_name"]?.ToString() ?? "";
            var figures = new TrainerFigures
            {
                Source = "nerfstudio ns-eval",
                File = path,
                Method = method,
                Psnr = Number(results["psnr"]),
                Ssim = Number(results["ssim"]),
                Lpips = Number(results["lpips"]),
                // splatfacto.py 50e0e3c line 242 pytorch_msssim SSIM (11×11 Gaussian, no padding); nerfacto.py line 251 torchmetrics structural_similarity_index_measure.
                SsimVariant = method.Contains("splatfacto") ? "pytorch_msssim SSIM (no padding): not this tool's variant" : "torchmetrics structural_similarity_index_measure: not this tool's variant",
                // splatfacto.py line 243, nerfacto.py line 252: LearnedPerceptualImagePatchSimilarity(normalize=True), torchmetrics' default net_type alex.
                LpipsVariant = "AlexNet, inputs [0, 1] normalised to [-1, 1] (torchmetrics LearnedPerceptualImagePatchSimilarity(normalize=True))",
                SsimComparable = false,
                PsnrTolerance = NerfstudioPsnrTolerance,
            };
            figures.Notes.Add("ns-eval's JSON holds means only (no per-view figures, no view count): compared as means; it scores nerfstudio's own eval split of the model's float output over the model's evaluation background.");
            return figures;
        }

        static TrainerFigures Gaussian(string path, JToken json, string iteration, string split, int frames)
        {
            var o = (JObject)json;
            var figures = new TrainerFigures
            {
                Source = "3dgs metrics.py",
                File = path,
                // metrics.py line 61: lpips(..., net_type='vgg') on images in [0, 1] (lpipsPyTorch does not rescale: graphdeco #1239).
                LpipsVariant = "VGG, inputs [0, 1] not rescaled to [-1, 1] (3DGS lpipsPyTorch)",
                SsimVariant = "3DGS utils/loss_utils.py ssim in float32 (this tool's formula, in double precision)",
                SsimComparable = true,
                PsnrTolerance = GaussianPsnrTolerance,
            };
            var keys = o.Properties().Select(p => p.Name).ToList();
            string method;
            if (iteration != null && o[iteration] is JObject) method = iteration;
            else if (iteration != null)
            {
                figures.Notes.Add(path + " has no entry for " + iteration + " (it has " + string.Join(", ", keys) + "): run python metrics.py -m <model> again after render.py; no figures compared.");
                figures.Method = iteration;
                return figures;
            }
            else method = keys.OrderBy(k => IterationNumber(k)).Last();
            figures.Method = method;
            var means = (JObject)o[method];
            figures.Psnr = Number(means["PSNR"]);
            figures.Ssim = Number(means["SSIM"]);
            figures.Lpips = Number(means["LPIPS"]);
            if (split != "test")
                figures.Notes.Add("3DGS metrics.py scores the test renders only (test_dir = <model>/test); these are the " + split + " split's, so its figures are not compared.");

            var perViewPath = Path.Combine(Path.GetDirectoryName(path) ?? "", GaussianPerView);
            if (!File.Exists(perViewPath)) { figures.Notes.Add("No " + GaussianPerView + " beside " + path + ": means only."); return figures; }
            if (!(Parse(perViewPath) is JObject perView) || !(perView[method] is JObject entry) || !(entry["PSNR"] is JObject psnrs))
            {
                figures.Notes.Add(perViewPath + " has no PSNR per view for " + method + ": means only.");
                return figures;
            }
            // metrics.py lists os.listdir(renders) in any order; the names are render.py's '{0:05d}.png' of the n-th test camera.
            var names = psnrs.Properties().Select(p => p.Name).ToList();
            var expected = Enumerable.Range(0, frames).Select(i => i.ToString("00000", CultureInfo.InvariantCulture) + ".png").ToList();
            if (names.Count != frames || !expected.All(names.Contains))
            {
                var sorted = names.OrderBy(n => n, FileNameOrder.Instance).ToList();
                figures.Notes.Add(perViewPath + " lists " + names.Count + " views (" + (sorted.Count > 0 ? sorted.First() + " … " + sorted.Last() : "none") + ") but the " + split + " split has " + frames +
                                  " (00000.png … " + (frames - 1).ToString("00000", CultureInfo.InvariantCulture) + ".png): not matched per view. Render and score this dataset's test split again.");
                return figures;
            }
            figures.Views = expected.Select(name => new TrainerViewFigures
            {
                Name = name,
                Psnr = Number(psnrs[name]),
                Ssim = Number((entry["SSIM"] as JObject)?[name]),
                Lpips = Number((entry["LPIPS"] as JObject)?[name]),
            }).ToArray();
            return figures;
        }

        static long IterationNumber(string key) =>
            key.StartsWith("ours_", StringComparison.Ordinal) && long.TryParse(key.Substring(5), NumberStyles.None, CultureInfo.InvariantCulture, out var n) ? n : -1;

        static double? Number(JToken t) => t != null && (t.Type == JTokenType.Float || t.Type == JTokenType.Integer) ? (double?)(double)t : null;

        static JToken Parse(string path)
        {
            try { return JToken.Parse(FileOps.ReadText(path)); }
            catch (JsonException e) { throw Refuse(path, "is not valid JSON (" + e.Message + ").", "Run the trainer's evaluation again, or leave --trainer-metrics out."); }
            catch (IOException e) { throw Refuse(path, "cannot be read (" + e.Message + ").", "Check the file's permissions."); }
            catch (UnauthorizedAccessException e) { throw Refuse(path, "cannot be read (" + e.Message + ").", "Check the file's permissions."); }
        }

        static InvalidParameterException Refuse(string path, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem("--trainer-metrics", path, reason, fix) });
    }
}
