using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;
using static NerfDatasetCreator.InverseRenderingMetrics;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The inverse-rendering metrics against hand-computed values (the arithmetic is in each test's comments).</summary>
    [TestFixture]
    public class InverseRenderingMetricsTests
    {
        static AlbedoView View(double[][] truth, double[][] prediction, bool[] mask) => new AlbedoView
        {
            Truth = truth.SelectMany(p => p).ToArray(), Prediction = prediction.SelectMany(p => p).ToArray(), Mask = mask,
        };

        static double[] Grey(double v) => new[] { v, v, v };

        [Test]
        public void TheMedianIsTorchsLowerOne()
        {
            Assert.That(LowerMedian(new[] { 4.0, 1, 3, 2 }), Is.EqualTo(2));
            Assert.That(LowerMedian(new[] { 5.0, 1, 3 }), Is.EqualTo(3));
        }

        [Test]
        public void TensoIRSamplesTwentyViewsAtAnIntervalOfNOverTwenty()
        {
            Assert.That(SampledViews(5), Is.EqualTo(Enumerable.Repeat(0, 20)), "interval 5 // 20 = 0: view 0 twenty times");
            Assert.That(SampledViews(40), Is.EqualTo(Enumerable.Range(0, 20).Select(i => 2 * i)));
        }

        [Test]
        public void ThreeChannelScalingTakesTheLowerMedianPerChannelAndPsnrIsOverGammaMaps()
        {
            // Ratios truth/prediction: p0 (2, 1, 1), p1 (1, 4, 1) → lower medians (1, 1, 1): the prediction stays.
            // Errors after ^(1/2.2): p0 red 0.5 vs 0.25, p1 green 0.4 vs 0.1; p2 is outside the mask (aligned 1 = truth 1).
            // MSE = ((0.5^(1/2.2) − 0.25^(1/2.2))² + (0.4^(1/2.2) − 0.1^(1/2.2))²) / 9 → 18.27449590 dB.
            var view = View(new[] { Grey(0.5), Grey(0.4), Grey(1) }, new[] { new[] { 0.25, 0.5, 0.5 }, new[] { 0.4, 0.1, 0.4 }, Grey(0.3) }, new[] { true, true, false });
            Assert.That(AlbedoPsnr(new[] { view }, AlbedoScaling.ThreeChannelGlobal, out var ratios), Is.EqualTo(18.27449590348156).Within(1e-9));
            Assert.That(ratios, Is.EqualTo(new[] { 1.0, 1.0, 1.0 }));
        }

        [Test]
        public void SingleChannelScalingAppliesTheFirstChannelsRatioToAll()
        {
            // Red ratios 2 and 3 → lower median 2: p0 becomes 0.5 (exact), p1 0.4 against 0.6 in all three channels.
            // MSE = 3 (0.6^(1/2.2) − 0.4^(1/2.2))² / 6 → 20.50461574 dB.
            var view = View(new[] { Grey(0.5), Grey(0.6) }, new[] { Grey(0.25), Grey(0.2) }, new[] { true, true });
            Assert.That(AlbedoPsnr(new[] { view }, AlbedoScaling.SingleChannelGlobal, out var ratios), Is.EqualTo(20.504615739519792).Within(1e-9));
            Assert.That(ratios[0], Is.EqualTo(2));
        }

        [Test]
        public void TheGlobalRatioComesFromTheSampledViewsAndPerViewRatiosFromEachView()
        {
            // Two views: with N = 2 TensoIR samples view 0 only (2 // 20 = 0), ratio 2 from it; view 1 (truth 0.3 =
            // prediction) is then scaled to 0.6: MSE = 3 (0.3^(1/2.2) − 0.6^(1/2.2))² / 6 → 16.39147302 dB. Per view, both are exact.
            var a = View(new[] { Grey(0.5) }, new[] { Grey(0.25) }, new[] { true });
            var b = View(new[] { Grey(0.3) }, new[] { Grey(0.3) }, new[] { true });
            Assert.That(AlbedoPsnr(new[] { a, b }, AlbedoScaling.ThreeChannelGlobal, out _), Is.EqualTo(16.39147302100033).Within(1e-9));
            Assert.That(AlbedoPsnr(new[] { a, b }, AlbedoScaling.ThreeChannelPerView, out _), Is.EqualTo(double.PositiveInfinity));
            Assert.That(AlbedoPsnr(new[] { a, b }, AlbedoScaling.SingleChannelPerView, out _), Is.EqualTo(double.PositiveInfinity));
        }

        [Test]
        public void NormalErrorOverAllPixelsAndOverTheTarget()
        {
            // Pixel 0 (target): +Z against +X, 90°; pixel 1 (background): +Z against +Z, 0°; a zero prediction is 90° off.
            var truth = new double[] { 0, 0, 1, 0, 0, 1 };
            var prediction = Normalise(new double[] { 2, 0, 0, 0, 0, 3 });
            var views = new[] { (truth, prediction, new[] { true, false }) };
            Assert.That(NormalMaeDegrees(views, false), Is.EqualTo(45).Within(1e-12));
            Assert.That(NormalMaeDegrees(views, true), Is.EqualTo(90).Within(1e-12));
            Assert.That(NormalMaeDegrees(new[] { (new double[] { 0, 0, 1 }, Normalise(new double[3]), new[] { true }) }, true), Is.EqualTo(90).Within(1e-12));
        }

        [Test]
        public void RoughnessMseIsR3dgsMaskedMeanPerViewThenOverViews()
        {
            // View 1: (1·(0.5 − 0.6))² and (0·…)² over 2 pixels = 0.005; view 2: (0.5·(0.6 − 0.2))² = 0.04; mean 0.0225.
            var views = new[]
            {
                (new[] { 0.6, 0.0 }, new[] { 0.5, 0.9 }, new[] { 1.0, 0.0 }),
                (new[] { 0.2 }, new[] { 0.6 }, new[] { 0.5 }),
            };
            Assert.That(RoughnessMse(views), Is.EqualTo(0.0225).Within(1e-15));
        }
    }

    /// <summary><c>evaluate --inverse</c> on the fixture dataset: perfect predictions score perfectly, and a flat roughness or normal scores what the hand formula gives.</summary>
    [TestFixture]
    public class InverseRenderingEvaluatorTests
    {
        TempFolder _temp;
        string _dataset;

        [OneTimeSetUp] public void Write() { _temp = new TempFolder(); _dataset = InverseRenderingFixture.Write(_temp.Path, "eval", relighting: true); }
        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        [Test]
        public void PerfectPredictionsScorePerfectlyAndFlatOnesScoreTheHandFormula()
        {
            var folder = _temp.Combine("model");
            foreach (var sub in new[] { "albedo", "normal", "roughness", "relit/sunset_090" }) Directory.CreateDirectory(Path.Combine(folder, sub));
            var frames = InverseRenderingFixture.Frames(_dataset, "test");
            double expectedMse = 0, expectedAll = 0;
            foreach (var (stem, _) in frames)
            {
                var image = PngReader.Read(Path.Combine(_dataset, "test", stem + ".png"));
                var normal = PngReader.Read(Path.Combine(_dataset, "test", stem + "_normal_0000.png"));
                var albedo = new float[32 * 32 * 4];
                var up = new float[32 * 32 * 4];
                double sum = 0;
                for (var i = 0; i < 32 * 32; i++)
                {
                    var a = image.Samples[4 * i + 3] / 255.0;
                    var b = InverseRenderingFixture.Base(i % 32, i / 32, 32, 32);
                    for (var c = 0; c < 3; c++)
                        albedo[4 * i + c] = (float)((a > 0 ? Math.Round(b[c] * 0.75 * 255, MidpointRounding.AwayFromZero) / 255 : 0) * a + 1 - a);
                    up[4 * i + 2] = 1;
                    // Roughness predicted 0: (a · 0.6)² per pixel (153/255 = 0.6).
                    sum += Math.Pow(a * 0.6, 2);
                    // Normal predicted +Z: the angle to the truth blended with +Z by alpha.
                    var n = Enumerable.Range(0, 3).Select(c => (normal.Samples[normal.Channels * i + c] / 255.0 - 0.5) * 2 * a + (c == 2 ? 1 - a : 0)).ToArray();
                    expectedAll += Math.Acos(Math.Max(-1, Math.Min(1, n[2] / Math.Sqrt(n.Sum(v => v * v))))) * 180 / Math.PI;
                }
                expectedMse += sum / (32 * 32);
                File.WriteAllBytes(Path.Combine(folder, "albedo", stem + ".exr"), InverseRenderingImages.EncodeExrTopDown(albedo, 32, 32));
                File.WriteAllBytes(Path.Combine(folder, "normal", stem + ".exr"), InverseRenderingImages.EncodeExrTopDown(up, 32, 32));
                File.WriteAllBytes(Path.Combine(folder, "roughness", stem + ".png"), PngWriter.Encode(new byte[32 * 32], 32, 32, PngPixelFormat.Gray8));
                File.Copy(Path.Combine(_dataset, "test", stem + "_light_sunset_090.png"), Path.Combine(folder, "relit", "sunset_090", stem + ".png"));
            }
            using (var stdout = new StringWriter())
            using (var stderr = new StringWriter())
            {
                var code = EvaluateCommand.Run(new EvaluationOptions { DatasetFolder = _dataset, InverseFolder = folder }, stdout, stderr);
                Assert.That(code, Is.EqualTo(ToolExitCodes.Success), stderr.ToString());
                Assert.That(stdout.ToString(), Does.Contain("dB (TensoIR's three-channel global median scaling"), stdout.ToString());
                Assert.That(stdout.ToString(), Does.Contain("relit sunset_090: PSNR — dB, SSIM 1.0000"), stdout.ToString());
            }
            var json = JObject.Parse(File.ReadAllText(Path.Combine(folder, "evaluation-test", InverseRenderingEvaluator.FileName)));
            // The prediction is the truth in float32: only float rounding is left.
            Assert.That((double)json["albedo"]["psnr_tensoir_three_channel_global"], Is.GreaterThan(120));
            Assert.That(json["albedo"]["ratio_three_channel"].ToObject<double[]>(), Is.EqualTo(new[] { 1.0, 1.0, 1.0 }).Within(1e-6));
            Assert.That((double)json["roughness"]["mse"], Is.EqualTo(expectedMse / frames.Count).Within(1e-12));
            Assert.That((double)json["normals"]["mae_degrees_all_pixels"], Is.EqualTo(expectedAll / (frames.Count * 32 * 32)).Within(1e-9));
            Assert.That((double)json["relit"]["sunset_090"]["ssim"], Is.EqualTo(1).Within(1e-12));
            Assert.That(json["relit"]["sunset_090"]["psnr"].Type, Is.EqualTo(JTokenType.Null));
        }

        [Test]
        public void InverseAloneIsAnEvaluateInvocationAndNeitherIsAnError()
        {
            var alone = ToolCommandLine.Parse(new[] { "evaluate", "d", "--inverse", "m" });
            Assert.That(alone.Errors, Is.Empty);
            Assert.That(((EvaluationOptions)alone.Options).InverseFolder, Does.EndWith("m"));
            Assert.That(((EvaluationOptions)alone.Options).RendersFolder, Is.Null);
            var neither = ToolCommandLine.Parse(new[] { "evaluate", "d" });
            Assert.That(neither.Errors, Has.Some.StartWith("evaluate needs --renders <folder>"));
        }

        [Test]
        public void AMissingPredictionIsRefusedNamingItAndNothingIsWritten()
        {
            var folder = _temp.Combine("partial");
            Directory.CreateDirectory(Path.Combine(folder, "roughness"));
            using (var stdout = new StringWriter())
            using (var stderr = new StringWriter())
            {
                var code = EvaluateCommand.Run(new EvaluationOptions { DatasetFolder = _dataset, InverseFolder = folder }, stdout, stderr);
                Assert.That(code, Is.EqualTo(ToolExitCodes.Failure));
                Assert.That(stderr.ToString(), Does.Contain(Path.Combine(folder, "roughness", "r_0.png")));
            }
            Assert.That(Directory.Exists(Path.Combine(folder, "evaluation-test")), Is.False);
        }
    }
}
