using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    [TestFixture]
    public class ValidateCommandTests
    {
        Scratch _scratch;
        string _dataset;

        [SetUp]
        public void SetUp()
        {
            _scratch = new Scratch();
            _dataset = _scratch.PathOf("ds");
            // A small rendered-looking dataset: the tool's plan, then an image for every frame, and the
            // plan-only marker removed by rewriting dataset_config.json without it.
            var config = _scratch.WriteText("c.json", "{ \"width\": 32, \"height\": 24, \"splits\": { \"train\": { \"count\": 3 }, \"val\": { \"count\": 2 }, \"test\": { \"count\": 2 } } }");
            Assert.That(ToolRun.Of("plan", "--config", config, "--out", _dataset).ExitCode, Is.EqualTo(0));
            File.Delete(Path.Combine(_dataset, "dataset_config.json"));
            var png = TestPng.Encode(32, 24, 8, 6);
            foreach (var (split, count) in new[] { ("train", 3), ("val", 2), ("test", 2) })
            {
                Directory.CreateDirectory(Path.Combine(_dataset, split));
                for (var i = 0; i < count; i++) File.WriteAllBytes(Path.Combine(_dataset, split, "r_" + i + ".png"), png);
            }
        }

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        [Test]
        public void ValidDatasetExitsZero()
        {
            var run = ToolRun.Of("validate", _dataset);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.StartWith(_dataset + ": train 3, val 2, test 2 frames; 7 images (32×24), 0 extra files; 0 problems, 0 warnings."));
        }

        [Test]
        public void EachProblemIsOneLineAndTheExitCodeIsOne()
        {
            File.Delete(Path.Combine(_dataset, "val", "r_1.png"));
            File.WriteAllBytes(Path.Combine(_dataset, "test", "r_0.png"), TestPng.Encode(16, 16, 8, 6));
            var run = ToolRun.Of("validate", _dataset);
            Assert.That(run.ExitCode, Is.EqualTo(1));
            var problems = run.Out.Split('\n').Where(l => l.StartsWith("problem: ")).ToList();
            Assert.That(problems, Is.EqualTo(new[]
            {
                "problem: transforms_val.json frame 1 (./val/r_1): image ./val/r_1.png is missing.",
                "problem: transforms_test.json frame 0 (./test/r_0): image ./test/r_0.png is 16×16 but ./train/r_0.png is 32×24; loaders stack all images and need one size.",
            }));
            Assert.That(run.Err, Does.Contain("invalid: 2 problems"));
        }

        [Test]
        public void MissingSplitFileFails()
        {
            File.Delete(Path.Combine(_dataset, "transforms_test.json"));
            var run = ToolRun.Of("validate", _dataset);
            Assert.That(run.ExitCode, Is.EqualTo(1));
            Assert.That(run.Out, Does.Contain("problem: transforms_test.json: is missing"));
        }

        [Test]
        public void UsageErrorsExitTwo()
        {
            var run = ToolRun.Of("validate");
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Err, Does.Contain("usage:"));
            Assert.That(ToolRun.Of().ExitCode, Is.EqualTo(2));
            Assert.That(ToolRun.Of("frobnicate").ExitCode, Is.EqualTo(2));
        }

        [Test]
        public void HelpExitsZero()
        {
            var run = ToolRun.Of("--help");
            Assert.That(run.ExitCode, Is.EqualTo(0));
            Assert.That(run.Out, Does.Contain("nerf-dataset plan --config"));
        }
    }
}
