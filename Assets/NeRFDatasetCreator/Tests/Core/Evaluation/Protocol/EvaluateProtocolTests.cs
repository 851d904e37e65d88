using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// evaluate follows eval_protocol.json: the background when none is given, a refusal for a contradicting
    /// --background (accepted with --override-protocol), and a refusal for renders whose own background is another
    /// colour (issue 35: white renders scored over black lost 0.85 dB silently).
    /// </summary>
    public class EvaluateProtocolTests
    {
        const int W = 48, H = 40;

        /// <summary>The sphere's test views as a model trained over <paramref name="background"/> renders them: straight alpha over it, nearest 8-bit code.</summary>
        static string Renders(string folder, IReadOnlyList<AnalyticSphereDataset.View> views, byte background)
        {
            Directory.CreateDirectory(folder);
            for (var i = 0; i < views.Count; i++)
            {
                var rgb = new byte[W * H * 3];
                for (var p = 0; p < W * H; p++)
                {
                    var a = views[i].Rgba[4 * p + 3] / 255.0;
                    for (var c = 0; c < 3; c++) rgb[3 * p + c] = (byte)Math.Round(views[i].Rgba[4 * p + c] * a + background * (1 - a));
                }
                File.WriteAllBytes(Path.Combine(folder, "r_" + i + ".png"), PngWriter.Encode(rgb, W, H, PngPixelFormat.Rgb8));
            }
            return folder;
        }

        static void Protocol(string dataset, string background) =>
            File.WriteAllText(Path.Combine(dataset, EvalProtocolFile.FileName), EvalProtocolFile.Text(EvalProtocol.For(new BackgroundSettings(), background)));

        static EvaluationOptions Options(string dataset, string renders, string background = null) =>
            new EvaluationOptions { DatasetFolder = dataset, RendersFolder = renders, Background = background, Threads = 2 };

        [Test]
        public void TheProtocolsBackgroundIsUsedWhenNoneIsGiven()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H);
                Protocol(dataset, "black");
                var result = RenderEvaluator.Run(Options(dataset, Renders(temp.Combine("black"), views, 0)));
                Assert.That(result.Background.Name, Is.EqualTo("black"));
                Assert.That(result.Protocol.Background, Is.EqualTo("black"));
                // Renders made exactly as the protocol composites: every view identical up to the 8-bit rounding of the edge.
                Assert.That(result.Views.All(v => v.Psnr > 45), Is.True);
                var metrics = JObject.Parse(File.ReadAllText(Path.Combine(temp.Combine("black"), "evaluation-test", "metrics.json")));
                Assert.That((string)metrics["protocol"]["file"], Is.EqualTo(EvalProtocolFile.FileName));
                Assert.That((string)metrics["protocol"]["summary"], Does.StartWith("black; train on train, evaluate on test"));
                Assert.That((bool)metrics["protocol"]["overridden"], Is.False);
                Assert.That((double)metrics["protocol"]["renders_background"]["mean_rgb"][0], Is.EqualTo(0).Within(1e-9));
                Assert.That(File.ReadAllText(Path.Combine(temp.Combine("black"), "evaluation-test", "report.html")), Does.Contain("Protocol: black; train on train"));
            }
        }

        [Test]
        public void ABackgroundThatContradictsTheProtocolIsRefusedAndAcceptedWithTheOverride()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H);
                Protocol(dataset, "white");
                var renders = Renders(temp.Combine("white"), views, 255);
                var refused = Assert.Throws<InvalidParameterException>(() => RenderEvaluator.Run(Options(dataset, renders, "black")));
                Assert.That(refused.Problems[0].Field, Is.EqualTo("--background"));
                Assert.That(refused.Problems[0].Reason, Does.Contain("contradicts the protocol").And.Contain("eval_protocol.json says white"));
                Assert.That(refused.Problems[0].Fix, Does.Contain("--override-protocol"));
                Assert.That(Directory.Exists(Path.Combine(renders, "evaluation-test")), Is.False, "nothing written");

                var options = Options(dataset, renders, "black");
                options.OverrideProtocol = true;
                var result = RenderEvaluator.Run(options);
                Assert.That(result.Background.Name, Is.EqualTo("black"));
                Assert.That(result.Warnings, Has.Some.StartsWith("--override-protocol: scored over black"));
                Assert.That(result.Warnings, Has.Some.Contains("the renders are white"), "the renders' own background is named too");
                var metrics = JObject.Parse(File.ReadAllText(Path.Combine(renders, "evaluation-test", "metrics.json")));
                Assert.That((bool)metrics["protocol"]["overridden"], Is.True);
                Assert.That(metrics["warnings"].Count(), Is.EqualTo(2));

                // The same renders over the protocol's white score far higher: the background pixels are all error over black.
                var right = RenderEvaluator.Run(new EvaluationOptions { DatasetFolder = dataset, RendersFolder = renders, OutFolder = temp.Combine("right"), Threads = 2 });
                Assert.That(right.Views.Min(v => v.Psnr), Is.GreaterThan(result.Views.Max(v => v.Psnr) + 5));
            }
        }

        [Test]
        public void WhiteRendersScoredOverBlackAreRefusedNamingWhiteEvenWithoutAProtocol()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H); // no eval_protocol.json: nerf_synthetic-like
                var renders = Renders(temp.Combine("white"), views, 255);
                var e = Assert.Throws<InvalidParameterException>(() => RenderEvaluator.Run(Options(dataset, renders, "black")));
                Assert.That(e.Problems[0].Field, Is.EqualTo("--background"));
                Assert.That(e.Problems[0].Reason, Does.Contain("the renders are white (mean 1.000, 1.000, 1.000), not black"));
                // Every pixel outside the sphere, in the 3 views measured, counted by hand from the dataset's own alpha.
                var transparent = views.Sum(v => Enumerable.Range(0, W * H).Count(p => v.Rgba[4 * p + 3] == 0));
                Assert.That(e.Problems[0].Reason, Does.Contain("(" + transparent + " pixels in 3 views)"));
                Assert.That(RenderEvaluator.Run(Options(dataset, renders, "white")).Views.Count, Is.EqualTo(3), "over white they are scored");
            }
        }

        [Test]
        public void BlackRendersAgainstAWhiteProtocolAreRefusedAsTrainedWithoutW()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H);
                Protocol(dataset, "white");
                var renders = Renders(temp.Combine("black"), views, 0);
                var e = Assert.Throws<InvalidParameterException>(() => RenderEvaluator.Run(Options(dataset, renders)));
                Assert.That(e.Problems[0].Reason, Does.Contain("the renders are black").And.Contain("not white"));
                Assert.That(e.Problems[0].Fix, Does.Contain("trainer_flags"));
            }
        }

        [Test]
        public void TheProtocolsEvaluationSplitAndResolutionFactorAreRead()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H);
                var text = EvalProtocolFile.Text(EvalProtocol.For(new BackgroundSettings()));
                File.WriteAllText(Path.Combine(dataset, EvalProtocolFile.FileName), text.Replace("\"resolution_factor\": 1", "\"resolution_factor\": 2"));
                var renders = Renders(temp.Combine("white"), views, 255);
                var e = Assert.Throws<InvalidParameterException>(() => RenderEvaluator.Run(Options(dataset, renders)));
                Assert.That(e.Problems[0].Field, Is.EqualTo("eval_protocol.json: resolution_factor"));

                // An evaluation split of train: evaluate looks for train renders when --split is left out.
                File.WriteAllText(Path.Combine(dataset, EvalProtocolFile.FileName), text.Replace("\"evaluation\": \"test\"", "\"evaluation\": \"train\""));
                var wrongCount = Assert.Throws<InvalidParameterException>(() => RenderEvaluator.Run(Options(dataset, renders)));
                Assert.That(wrongCount.Problems[0].ToString(), Does.Contain("train"));
            }
        }
    }
}
