using System;
using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>The menu item's work (Core's RenderEvaluator) on a two-view dataset of flat images, and its refusal.</summary>
    public class EvaluateRendersMenuTests
    {
        string _root;

        [SetUp]
        public void SetUp()
        {
            _root = Path.Combine(Path.GetTempPath(), "nerf-evaluate-menu-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(Path.Combine(_root, "dataset", "test"));
            Directory.CreateDirectory(Path.Combine(_root, "renders"));
            var frames = "";
            for (var i = 0; i < 2; i++)
            {
                var truth = new byte[8 * 8 * 4];
                var render = new byte[8 * 8 * 3];
                for (var p = 0; p < 64; p++)
                {
                    truth[4 * p] = truth[4 * p + 1] = truth[4 * p + 2] = 100;
                    truth[4 * p + 3] = 255;
                    render[3 * p] = render[3 * p + 1] = render[3 * p + 2] = 110; // 10 levels off: PSNR 20·log10(255/10) = 28.13 dB
                }
                File.WriteAllBytes(Path.Combine(_root, "dataset", "test", "r_" + i + ".png"), PngWriter.Encode(truth, 8, 8, PngPixelFormat.Rgba8));
                File.WriteAllBytes(Path.Combine(_root, "renders", "r_" + i + ".png"), PngWriter.Encode(render, 8, 8, PngPixelFormat.Rgb8));
                frames += (i > 0 ? "," : "") + "{\"file_path\": \"./test/r_" + i + "\", \"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]]}";
            }
            File.WriteAllText(Path.Combine(_root, "dataset", "transforms_test.json"), "{\"camera_angle_x\": 0.69, \"frames\": [" + frames + "]}");
        }

        [TearDown]
        public void TearDown()
        {
            if (Directory.Exists(_root)) Directory.Delete(_root, true);
        }

        [Test]
        public void EvaluatesAndPointsAtTheReport()
        {
            var ok = EvaluateRendersMenu.Evaluate(Path.Combine(_root, "dataset"), Path.Combine(_root, "renders"), out var message, out var report);
            Assert.That(ok, Is.True, message);
            Assert.That(message, Does.Contain("evaluated 2 test views (plain layout): PSNR 28.13 dB"));
            Assert.That(File.Exists(report), Is.True);
        }

        [Test]
        public void AMissingRenderIsReportedNotThrown()
        {
            File.Delete(Path.Combine(_root, "renders", "r_1.png"));
            var ok = EvaluateRendersMenu.Evaluate(Path.Combine(_root, "dataset"), Path.Combine(_root, "renders"), out var message, out _);
            Assert.That(ok, Is.False);
            Assert.That(message, Does.Contain("nothing was evaluated").And.Contain("r_1.png"));
        }
    }
}
