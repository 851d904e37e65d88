using System.IO;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// The protocol through the tool (issue 35): evaluate refuses a --background that contradicts eval_protocol.json,
    /// scores it with --override-protocol and a warning, and check --model warns about a 3DGS model trained without -w.
    /// </summary>
    public class EvaluateProtocolCommandTests
    {
        const int W = 40, H = 32;

        [Test]
        public void ABackgroundAgainstTheProtocolIsRefusedThenScoredWithTheOverride()
        {
            using (var scratch = new Scratch())
            {
                var dataset = scratch.PathOf("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H, train: 4, test: 3);
                File.WriteAllText(Path.Combine(dataset, EvalProtocolFile.FileName), EvalProtocolFile.Text(EvalProtocol.For(new BackgroundSettings())));
                var renders = scratch.PathOf("renders");
                Directory.CreateDirectory(renders);
                for (var i = 0; i < views.Count; i++)
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], W, H, 0), W, H, PngPixelFormat.Rgb8));

                var refused = ToolRun.Of("evaluate", dataset, "--renders", renders, "--background", "black");
                Assert.That(refused.ExitCode, Is.EqualTo(1), refused.ToString());
                Assert.That(refused.Err, Does.Contain("error: --background = black: contradicts the protocol").And.Contain("--override-protocol"));
                Assert.That(Directory.Exists(Path.Combine(renders, "evaluation-test")), Is.False);

                var forced = ToolRun.Of("evaluate", dataset, "--renders", renders, "--background", "black", "--override-protocol");
                Assert.That(forced.ExitCode, Is.EqualTo(0), forced.ToString());
                Assert.That(forced.Err, Does.Contain("warning: --override-protocol: scored over black"));
                Assert.That(forced.Out, Does.Contain("protocol: white; train on train, evaluate on test; resolution factor 1 (eval_protocol.json)"));
                Assert.That(forced.Out, Does.Contain("3DGS metrics.py runs it in float32"));
                Assert.That((bool)JObject.Parse(File.ReadAllText(Path.Combine(renders, "evaluation-test", "metrics.json")))["protocol"]["overridden"], Is.True);
            }
        }

        [Test]
        public void CheckModelWarnsAboutAThreeDgsModelTrainedWithoutW()
        {
            using (var scratch = new Scratch())
            {
                var dataset = scratch.PathOf("sphere");
                AnalyticSphereDataset.Write(dataset, W, H, train: 4, test: 3);
                var model = scratch.PathOf("output", "sphere");
                Directory.CreateDirectory(model);
                File.WriteAllText(Path.Combine(model, "cfg_args"), "Namespace(data_device='cuda', eval=True, images='images', model_path='output/sphere', resolution=-1, sh_degree=3, source_path='" + dataset + "', white_background=False)");
                var run = ToolRun.Of("check", dataset, "--model", model);
                Assert.That(run.Out, Does.Contain("trainer config: 3DGS " + Path.Combine(model, "cfg_args") + ": white_background=False (trained and rendered over black)"));
                Assert.That(run.Out, Does.Contain("warning: 3DGS").And.Contain("Train again with -w"));

                var none = ToolRun.Of("check", dataset, "--model", scratch.PathOf("nothing"));
                Assert.That(none.ExitCode, Is.EqualTo(1));
                Assert.That(none.Err, Does.Contain("error: --model = ").And.Contain("holds neither cfg_args"));
            }
        }
    }
}
