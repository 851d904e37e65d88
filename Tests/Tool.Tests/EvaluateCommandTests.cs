using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary><c>nerf-dataset evaluate</c> end to end on an analytically rendered sphere, with 3DGS's render.py layout.</summary>
    public class EvaluateCommandTests
    {
        const int W = 40, H = 32;

        /// <summary>The dataset and a 3DGS model folder whose test renders are the ground truth on white, red + <paramref name="perturb"/> on the sphere.</summary>
        static (string dataset, string model) Setup(Scratch scratch, int perturb = 6)
        {
            var dataset = scratch.PathOf("sphere");
            var views = AnalyticSphereDataset.Write(dataset, W, H, train: 4, test: 3);
            var model = scratch.PathOf("output", "sphere");
            var renders = Path.Combine(model, "test", "ours_30000", "renders");
            Directory.CreateDirectory(renders);
            Directory.CreateDirectory(Path.Combine(model, "test", "ours_30000", "gt"));
            for (var i = 0; i < views.Count; i++)
                File.WriteAllBytes(Path.Combine(renders, i.ToString("00000") + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], W, H, perturb), W, H, PngPixelFormat.Rgb8));
            return (dataset, model);
        }

        [Test]
        public void EvaluatesA3dgsModelFolderAndWritesTheReport()
        {
            using (var scratch = new Scratch())
            {
                var (dataset, model) = Setup(scratch);
                var recon = scratch.PathOf("recon.ply");
                using (var file = File.Create(recon))
                    TargetMeshPly.Write(file, new[] { AnalyticSphereDataset.UvSphere(1.004, 24, 48) });
                var run = ToolRun.Of("evaluate", dataset, "--renders", model, "--geometry", recon, "--threshold", "0.02");
                Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
                Assert.That(run.Out, Does.Contain("evaluated 3 test views (3dgs layout, background white)"));
                Assert.That(run.Out, Does.Contain("PSNR ").And.Contain("SSIM ").And.Contain("PSNR in mask").And.Contain("F-score").And.Contain("LPIPS is not computed"));
                var outFolder = Path.Combine(model, "evaluation-test");
                var metrics = JObject.Parse(File.ReadAllText(Path.Combine(outFolder, "metrics.json")));
                Assert.That((string)metrics["renders"]["layout"], Is.EqualTo("3dgs"));
                Assert.That(metrics["views"].Select(v => (string)v["render"]).Select(Path.GetFileName), Is.EqualTo(new[] { "00000.png", "00001.png", "00002.png" }));
                Assert.That((double)metrics["geometry"]["fscore"], Is.GreaterThan(0.9));
                Assert.That((double)metrics["geometry"]["threshold"], Is.EqualTo(0.02));
                Assert.That(Directory.GetFiles(Path.Combine(outFolder, "errors")).Select(Path.GetFileName).OrderBy(n => n), Is.EqualTo(new[] { "r_0_error.png", "r_1_error.png", "r_2_error.png" }));
                Assert.That(File.ReadAllText(Path.Combine(outFolder, "report.html")), Does.Contain("<svg"));

                // Again into the same folder: it is provably ours, so it is replaced.
                Assert.That(ToolRun.Of("evaluate", dataset, "--renders", model).ExitCode, Is.EqualTo(0));
                Assert.That(JObject.Parse(File.ReadAllText(Path.Combine(outFolder, "metrics.json")))["geometry"], Is.Null);
            }
        }

        [Test]
        public void FlowIsScoredOnItsOwnAndImageOptionsBesideItAreUsageMistakes()
        {
            using (var scratch = new Scratch())
            {
                var dataset = AnalyticDataset.Write(scratch.Root, "moving", new AnalyticDataset.Options
                {
                    Width = 32, Height = 24, Supersampling = 1, Train = 3, Val = 1, Test = 1, TimeSteps = 3, Monocular = true, PointCloud = 0,
                    MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
                });
                FlowWriter.Write(dataset, new FlowSettings { On = true, TrackQueryFrames = new[] { 0 }, TrackStride = 4 });
                // The model's flow is the dataset's own: EPE 0 (no tracks rendered: not scored).
                var predictions = scratch.PathOf("model-flow");
                Directory.CreateDirectory(Path.Combine(predictions, "train"));
                foreach (var file in Directory.GetFiles(Path.Combine(dataset, "flow", "train"), "flow_*.flo"))
                    File.Copy(file, Path.Combine(predictions, "train", Path.GetFileName(file)));
                var run = ToolRun.Of("evaluate", dataset, "--flow", predictions);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
                Assert.That(run.Out, Does.Contain("flow of 4 frame pairs: EPE 0.000 px on pixels visible in both frames, 0.000 px on all pixels with a surface"));
                Assert.That(run.Out, Does.Contain("tracks: not scored"));
                Assert.That(File.Exists(Path.Combine(predictions, "evaluation-flow", "metrics.json")), Is.True);

                var mixed = ToolRun.Of("evaluate", dataset, "--flow", predictions, "--renders", predictions);
                Assert.That(mixed.ExitCode, Is.EqualTo(2), mixed.ToString());
                Assert.That(mixed.Err, Does.StartWith("error: --renders is for rendered images; --flow scores motion on its own: evaluate <dataset> --flow <folder> [--out <dir>]."));
            }
        }

        /// <summary>
        /// A nerf_synthetic-style split (frames without depth_path, 8-bit r_&lt;i&gt;_depth_0000.png pictures beside the
        /// images) with renders that carry depth: evaluate scores the colour and skips depth with a note (keys only, as
        /// check), instead of exiting 1 with "… is not a 16-bit grey depth PNG".
        /// </summary>
        [Test]
        public void ANerfSyntheticStyleSplitIsScoredWithoutTheDepthItsFramesDoNotName()
        {
            using (var scratch = new Scratch())
            {
                var dataset = scratch.PathOf("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H, train: 4, test: 3);
                AnalyticSphereDataset.MakeNerfSyntheticStyle(dataset, "test", views, W, H);
                var renders = scratch.PathOf("renders");
                Directory.CreateDirectory(renders);
                for (var i = 0; i < views.Count; i++)
                {
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], W, H, 6), W, H, PngPixelFormat.Rgb8));
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + "_depth_0000.png"), PngWriter.EncodeGray16(views[i].Depth, W, H));
                }
                var run = ToolRun.Of("evaluate", dataset, "--renders", renders);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
                Assert.That(run.Out, Does.Contain("PSNR ").And.Contain("SSIM "));
                Assert.That(run.ToString(), Does.Not.Contain("16-bit grey depth PNG"));
                var metrics = JObject.Parse(File.ReadAllText(Path.Combine(renders, "evaluation-test", "metrics.json")));
                Assert.That((double)metrics["mean"]["psnr"], Is.GreaterThan(20));
                Assert.That(metrics["notes"].Select(n => (string)n), Has.Some.Contains("name no depth file (depth_path; files are never guessed from the image names): depth not scored"));
            }
        }

        [Test]
        public void AForeignOutFolderIsRefusedAndLeftAlone()
        {
            using (var scratch = new Scratch())
            {
                var (dataset, model) = Setup(scratch);
                var outFolder = scratch.PathOf("results");
                Directory.CreateDirectory(outFolder);
                File.WriteAllText(Path.Combine(outFolder, "metrics.json"), "{\"psnr\": 31}");
                var run = ToolRun.Of("evaluate", dataset, "--renders", model, "--out", outFolder);
                Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
                Assert.That(run.Err, Does.Contain("error: --out").And.Contain("no metrics.json written by").And.Contain("nothing was written"));
                Assert.That(File.ReadAllText(Path.Combine(outFolder, "metrics.json")), Is.EqualTo("{\"psnr\": 31}"));
                Assert.That(Directory.GetFileSystemEntries(outFolder), Has.Length.EqualTo(1));
            }
        }

        [Test]
        public void StepOnAStaticDatasetIsRefusedNamingStep()
        {
            using (var scratch = new Scratch())
            {
                var (dataset, model) = Setup(scratch);
                var recon = scratch.PathOf("recon.ply");
                File.Copy(Path.Combine(dataset, TargetMeshPly.RelativePath), recon);
                var run = ToolRun.Of("evaluate", dataset, "--renders", model, "--geometry", recon, "--step", "0");
                Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
                Assert.That(run.Err, Does.Contain("error: --step").And.Contain("static capture").And.Contain("evaluate refused: nothing was written."));
                Assert.That(Directory.Exists(Path.Combine(model, "evaluation-test")), Is.False);
            }
        }

        [Test]
        public void RendersOfAnotherCountAreRefusedWithOneLinePerProblem()
        {
            using (var scratch = new Scratch())
            {
                var (dataset, model) = Setup(scratch);
                File.Delete(Path.Combine(model, "test", "ours_30000", "renders", "00002.png"));
                var run = ToolRun.Of("evaluate", dataset, "--renders", model);
                Assert.That(run.ExitCode, Is.EqualTo(1));
                Assert.That(run.Err, Does.Contain("holds 2 renders").And.Contain("lists 3 frames"));
                Assert.That(run.Err, Does.Not.Contain("   at "), "no stack trace");
            }
        }

        [TestCase(new[] { "evaluate", "d" }, "evaluate needs --renders <folder>")]
        [TestCase(new[] { "evaluate", "--renders", "r" }, "evaluate needs exactly one dataset folder")]
        [TestCase(new[] { "evaluate", "d", "--renders", "r", "--layout", "mipnerf" }, "--layout = mipnerf: is not 3dgs, nerfstudio, ngp, plain, nerf-pytorch.")]
        [TestCase(new[] { "evaluate", "d", "--renders", "r", "--background", "grey" }, "--background = grey: is not white, black or dataset.")]
        [TestCase(new[] { "evaluate", "d", "--renders", "r", "--split", "Test" }, "--split = Test: is not train, val or test.")]
        [TestCase(new[] { "evaluate", "d", "--renders", "r", "--threshold", "0.01" }, "--threshold is the F-score threshold of --geometry")]
        [TestCase(new[] { "evaluate", "d", "--renders", "r", "--geometry", "g.ply", "--threshold", "-1" }, "--threshold = -1: must be a distance > 0")]
        [TestCase(new[] { "evaluate", "d", "--renders", "r", "--render-depth", "median" }, "--render-depth = median: is not z")]
        [TestCase(new[] { "evaluate", "d", "--renders", "r", "--step", "1" }, "--step picks the time step of --geometry")]
        [TestCase(new[] { "evaluate", "d", "--renders", "r", "--geometry", "g.ply", "--step", "-1" }, "--step = -1: must be a time step number ≥ 0")]
        [TestCase(new[] { "evaluate", "d", "--renders", "r", "--geometry", "g.ply", "--step", "one" }, "--step = one: must be a time step number")]
        public void UsageErrorsExitTwo(string[] args, string error)
        {
            var run = ToolRun.Of(args);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("error: " + error).And.Contain("usage:"));
        }
    }
}
