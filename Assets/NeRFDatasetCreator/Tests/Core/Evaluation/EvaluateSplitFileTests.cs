using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary><c>evaluate --split sparse_&lt;n&gt;</c>: only the listed test views are scored, from whole-split renders or from renders of just those views.</summary>
    public class EvaluateSplitFileTests
    {
        const int W = 48, H = 40;

        /// <summary>A split file listing test views 3 and 1 (in that order) of the sphere dataset's 4.</summary>
        static void WriteSplit(string dataset)
        {
            var split = new SparseSplit(2, "hand-written for the test", null, new[] { 0, 5 }, new[] { "./train/r_0", "./train/r_5" }, new[] { 3, 1 }, new[] { "./test/r_3", "./test/r_1" });
            Directory.CreateDirectory(Path.Combine(dataset, "splits"));
            File.WriteAllText(Path.Combine(dataset, "splits", "sparse_2.json"), split.ToJson());
        }

        static int Perturb(int i) => 10 + 5 * i;

        [Test]
        public void OnlyTheListedTestViewsAreScoredFromWholeSplitRenders()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H, test: 4);
                WriteSplit(dataset);
                var renders = temp.Combine("all");
                Directory.CreateDirectory(renders);
                for (var i = 0; i < views.Count; i++)
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], W, H, Perturb(i)), W, H, PngPixelFormat.Rgb8));
                var whole = RenderEvaluator.Run(new EvaluationOptions { DatasetFolder = dataset, RendersFolder = renders, Threads = 2, OutFolder = temp.Combine("whole") });

                var stdout = new StringWriter();
                Assert.That(ToolCommands.Run(new[] { "evaluate", dataset, "--renders", renders, "--split", "sparse_2" }, stdout, new StringWriter()), Is.EqualTo(0));
                Assert.That(stdout.ToString(), Does.Contain("evaluated 2 test views").And.Contain("Scored the 2 of 4 test views that splits/sparse_2.json lists"));
                var metrics = JObject.Parse(File.ReadAllText(Path.Combine(renders, "evaluation-sparse_2", "metrics.json")));
                var scored = (JArray)metrics["views"];
                Assert.That(scored.Count, Is.EqualTo(2));
                Assert.That((double)scored[0]["psnr"], Is.EqualTo(whole.Views[3].Psnr).Within(1e-12), "view 3 first, as listed");
                Assert.That((double)scored[1]["psnr"], Is.EqualTo(whole.Views[1].Psnr).Within(1e-12));
                Assert.That((double)metrics["mean"]["psnr"], Is.EqualTo((whole.Views[3].Psnr + whole.Views[1].Psnr) / 2).Within(1e-9));
                Assert.That(metrics["split_file"]["test"].Select(t => (int)t), Is.EqualTo(new[] { 3, 1 }));
            }
        }

        [Test]
        public void RendersOfJustTheListedViewsAreScoredAndUnknownNamesAreRefusedListingTheFiles()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H, test: 4);
                WriteSplit(dataset);
                var renders = temp.Combine("listed");
                Directory.CreateDirectory(renders);
                foreach (var i in new[] { 1, 3 })
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], W, H, Perturb(i)), W, H, PngPixelFormat.Rgb8));
                var result = RenderEvaluator.Run(new EvaluationOptions { DatasetFolder = dataset, RendersFolder = renders, Threads = 2, SplitFile = "sparse_2" });
                Assert.That(result.Views.Count, Is.EqualTo(2));
                Assert.That(result.Renders.Views.Select(v => v.FramePath), Is.EqualTo(new[] { "./test/r_3", "./test/r_1" }));

                var stderr = new StringWriter();
                Assert.That(ToolCommands.Run(new[] { "evaluate", dataset, "--renders", renders, "--split", "sparse_9" }, new StringWriter(), stderr), Is.EqualTo(1));
                Assert.That(stderr.ToString(), Does.Contain("--split = sparse_9").And.Contain("splits/ holds sparse_2").And.Contain("nerf-dataset splits"));

                // Renders of neither the whole split nor the listed views: both reasons.
                File.Delete(Path.Combine(renders, "r_1.png"));
                Assert.That(ToolCommands.Run(new[] { "evaluate", dataset, "--renders", renders, "--split", "sparse_2" }, new StringWriter(), stderr = new StringWriter()), Is.EqualTo(1));
                Assert.That(stderr.ToString(), Does.Contain("neither of the whole test split"));
            }
        }

        [Test]
        public void ASplitFileWrittenForAnotherDatasetIsRefused()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                AnalyticSphereDataset.Write(dataset, W, H, test: 2);
                WriteSplit(dataset); // lists test view 3 of a 2-view split
                var stderr = new StringWriter();
                Assert.That(ToolCommands.Run(new[] { "evaluate", dataset, "--renders", dataset, "--split", "sparse_2" }, new StringWriter(), stderr), Is.EqualTo(1));
                Assert.That(stderr.ToString(), Does.Contain("test index 3 names ./test/r_3").And.Contain("has only 2 frames"));
            }
        }
    }
}
