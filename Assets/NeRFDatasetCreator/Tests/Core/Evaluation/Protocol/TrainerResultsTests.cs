using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The trainers' own result files beside evaluate's figures: 3DGS metrics.py's results.json / per_view.json and
    /// ns-eval's JSON, written here exactly as those scripts write them (json.dump(..., indent=True): one-space indent;
    /// json.dumps(..., indent=2)), matched to the split's views, and a planted 0.6 dB background mismatch flagged.
    /// </summary>
    public class TrainerResultsTests
    {
        const int W = 48, H = 40;

        static string N(double v) => v.ToString("R", CultureInfo.InvariantCulture);

        /// <summary>3DGS metrics.py lines 74–77: results.json and per_view.json in the model folder, keyed by the method folder (ours_&lt;iter&gt;).</summary>
        static void WriteMetricsPy(string model, string method, double[] psnr, double[] ssim, double[] lpips)
        {
            string Mean(double[] v) => N(v.Average());
            File.WriteAllText(Path.Combine(model, "results.json"),
                "{\n \"" + method + "\": {\n  \"SSIM\": " + Mean(ssim) + ",\n  \"PSNR\": " + Mean(psnr) + ",\n  \"LPIPS\": " + Mean(lpips) + "\n }\n}");
            string Per(double[] v) => string.Join(",\n", v.Select((x, i) => "   \"" + i.ToString("00000", CultureInfo.InvariantCulture) + ".png\": " + N(x)).Reverse());
            File.WriteAllText(Path.Combine(model, "per_view.json"),
                "{\n \"" + method + "\": {\n  \"SSIM\": {\n" + Per(ssim) + "\n  },\n  \"PSNR\": {\n" + Per(psnr) + "\n  },\n  \"LPIPS\": {\n" + Per(lpips) + "\n  }\n }\n}");
        }

        /// <summary>A 3DGS model folder with render.py's test/ours_30000/renders/0000i.png of the sphere over white, red perturbed by 4·(i+1) inside it.</summary>
        static (string model, double[] psnr, double[] ssim) GaussianModel(TempFolder temp, string dataset)
        {
            var views = AnalyticSphereDataset.Write(dataset, W, H);
            var model = temp.Combine("model");
            var renders = Path.Combine(model, "test", "ours_30000", "renders");
            Directory.CreateDirectory(renders);
            var psnr = new double[views.Count];
            var ssim = new double[views.Count];
            for (var i = 0; i < views.Count; i++)
            {
                var render = AnalyticSphereDataset.Render(views[i], W, H, 4 * (i + 1));
                File.WriteAllBytes(Path.Combine(renders, i.ToString("00000", CultureInfo.InvariantCulture) + ".png"), PngWriter.Encode(render, W, H, PngPixelFormat.Rgb8));
                // The figures metrics.py would print, computed here from the pixels: PSNR by its formula, SSIM by the test suite's direct 3DGS loop.
                var truth = AnalyticSphereDataset.Render(views[i], W, H, 0).Select(b => b / 255f).ToArray();
                var r = render.Select(b => b / 255f).ToArray();
                var mse = truth.Select((t, k) => (double)(r[k] - t) * (r[k] - t)).Average();
                psnr[i] = 20 * Math.Log10(1 / Math.Sqrt(mse));
                ssim[i] = ImageMetricsTests.Direct3dgs(r, truth, W, H, 3);
            }
            return (model, psnr, ssim);
        }

        [Test]
        public void ThreeDgsMetricsPyFiguresAreMatchedToTheViewsAndAgree()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var (model, psnr, ssim) = GaussianModel(temp, dataset);
                var lpips = new[] { 0.011, 0.012, 0.013 };
                WriteMetricsPy(model, "ours_30000", psnr, ssim, lpips);
                var result = RenderEvaluator.Run(new EvaluationOptions { DatasetFolder = dataset, RendersFolder = model, Threads = 2 });
                Assert.That(result.Trainer.Source, Is.EqualTo("3dgs metrics.py"));
                Assert.That(result.Trainer.Method, Is.EqualTo("ours_30000"));
                Assert.That(result.Trainer.Views.Select(v => v.Psnr.Value), Is.EqualTo(psnr), "per_view.json's names in any order, matched 00000.png → frame 0");
                Assert.That(result.Trainer.Lpips.Value, Is.EqualTo(0.012).Within(1e-12));
                Assert.That(result.TrainerMeans.Select(c => (c.Metric, c.Compared, c.Flagged)), Is.EqualTo(new[] { ("psnr", true, false), ("ssim", true, false) }));
                Assert.That(result.TrainerFlaggedViews, Is.Empty);
                Assert.That(result.Warnings, Is.Empty);
                var metrics = JObject.Parse(File.ReadAllText(Path.Combine(model, "evaluation-test", "metrics.json")));
                Assert.That((double)metrics["trainer_metrics"]["lpips"], Is.EqualTo(0.012).Within(1e-12));
                Assert.That((string)metrics["trainer_metrics"]["lpips_variant"], Does.Contain("VGG"));
                Assert.That((double)metrics["trainer_metrics"]["views"][2]["psnr"], Is.EqualTo(psnr[2]));
                var html = File.ReadAllText(Path.Combine(model, "evaluation-test", "report.html"));
                Assert.That(html, Does.Contain("own figures: 3dgs metrics.py (ours_30000)").And.Contain(">agrees<"));
            }
        }

        [Test]
        public void APlantedBackgroundMismatchOfSixTenthsOfADecibelIsFlagged()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var (model, psnr, ssim) = GaussianModel(temp, dataset);
                // As if metrics.py had scored against gt/ composited over another background: every view 0.6 dB higher.
                WriteMetricsPy(model, "ours_30000", psnr.Select(p => p + 0.6).ToArray(), ssim, new[] { 0.02, 0.02, 0.02 });
                var result = RenderEvaluator.Run(new EvaluationOptions { DatasetFolder = dataset, RendersFolder = model, Threads = 2 });
                var mean = result.TrainerMeans.Single(c => c.Metric == "psnr");
                Assert.That(mean.Flagged, Is.True);
                Assert.That(mean.Theirs - mean.Ours, Is.EqualTo(0.6).Within(1e-9));
                Assert.That(result.TrainerFlaggedViews, Is.EqualTo(new[] { 0, 1, 2 }));
                Assert.That(result.Warnings.Single(), Does.Contain("differs from evaluate's").And.Contain("by 0.60 dB (tolerance 0.05 dB)").And.Contain("another background than white"));
                var metrics = JObject.Parse(File.ReadAllText(Path.Combine(model, "evaluation-test", "metrics.json")));
                Assert.That((bool)metrics["trainer_metrics"]["comparison"][0]["flagged"], Is.True);
                Assert.That(File.ReadAllText(Path.Combine(model, "evaluation-test", "report.html")), Does.Contain("DISAGREES"));
            }
        }

        [Test]
        public void APerViewFileOfAnotherViewCountIsNotMatched()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var (model, psnr, ssim) = GaussianModel(temp, dataset);
                WriteMetricsPy(model, "ours_30000", psnr.Take(2).ToArray(), ssim.Take(2).ToArray(), new[] { 0.01, 0.01 });
                var result = RenderEvaluator.Run(new EvaluationOptions { DatasetFolder = dataset, RendersFolder = model, Threads = 2 });
                Assert.That(result.Trainer.Views, Is.Null);
                Assert.That(result.Trainer.Notes.Single(), Does.Contain("lists 2 views (00000.png … 00001.png) but the test split has 3"));
            }
        }

        [Test]
        public void AnotherIterationsResultsAreNamedAndNotCompared()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var (model, psnr, ssim) = GaussianModel(temp, dataset);
                WriteMetricsPy(model, "ours_7000", psnr, ssim, new[] { 0.01, 0.01, 0.01 });
                var result = RenderEvaluator.Run(new EvaluationOptions { DatasetFolder = dataset, RendersFolder = model, Threads = 2 });
                Assert.That(result.Trainer.Psnr, Is.Null);
                Assert.That(result.Trainer.Notes.Single(), Does.Contain("has no entry for ours_30000 (it has ours_7000)"));
                Assert.That(result.TrainerMeans, Is.Empty);
            }
        }

        [Test]
        public void AnNsEvalJsonIsComparedOnPsnrOnly()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H);
                var output = temp.Combine("ns");
                var rgb = Path.Combine(output, "test", "rgb");
                Directory.CreateDirectory(rgb);
                double sum = 0;
                for (var i = 0; i < views.Count; i++)
                {
                    var render = AnalyticSphereDataset.Render(views[i], W, H, 6);
                    File.WriteAllBytes(Path.Combine(rgb, "r_" + i + ".png"), PngWriter.Encode(render, W, H, PngPixelFormat.Rgb8));
                    var truth = AnalyticSphereDataset.Render(views[i], W, H, 0);
                    sum += 20 * Math.Log10(1 / Math.Sqrt(truth.Select((t, k) => Math.Pow((render[k] - t) / 255.0, 2)).Average()));
                }
                var mean = sum / views.Count;
                // nerfstudio scripts/eval.py lines 53–60: json.dumps(benchmark_info, indent=2); results from get_average_image_metrics(get_std=True).
                var nsEval = new StringBuilder()
                    .Append("{\n  \"experiment_name\": \"sphere\",\n  \"method_name\": \"splatfacto\",\n  \"checkpoint\": \"outputs/sphere/splatfacto/2026-12-07_000000/nerfstudio_models/step-000029999.ckpt\",\n")
                    .Append("  \"results\": {\n    \"psnr\": ").Append(N(mean + 0.6)).Append(",\n    \"psnr_std\": 0.5,\n    \"ssim\": 0.97,\n    \"ssim_std\": 0.01,\n    \"lpips\": 0.03,\n    \"lpips_std\": 0.004,\n")
                    .Append("    \"num_rays_per_sec\": 1234567.0,\n    \"num_rays_per_sec_std\": 1000.0,\n    \"fps\": 642.9,\n    \"fps_std\": 0.5\n  }\n}").ToString();
                File.WriteAllText(Path.Combine(output, "output.json"), nsEval);
                var result = RenderEvaluator.Run(new EvaluationOptions { DatasetFolder = dataset, RendersFolder = output, Threads = 2 });
                Assert.That(result.Trainer.Source, Is.EqualTo("nerfstudio ns-eval"));
                Assert.That(result.Trainer.Method, Is.EqualTo("splatfacto"));
                Assert.That(result.TrainerMeans.Select(c => (c.Metric, c.Compared, c.Flagged)), Is.EqualTo(new[] { ("psnr", true, true), ("ssim", false, false) }));
                Assert.That(result.Trainer.Notes.Single(), Does.Contain("means only"));

                var missing = new EvaluationOptions { DatasetFolder = dataset, RendersFolder = output, TrainerMetricsPath = temp.Combine("nope.json"), OutFolder = temp.Combine("out2"), Threads = 2 };
                var e = Assert.Throws<InvalidParameterException>(() => RenderEvaluator.Run(missing));
                Assert.That(e.Problems[0].Field, Is.EqualTo("--trainer-metrics"));
            }
        }
    }
}
