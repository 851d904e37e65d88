using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary><c>validate</c> on nerf_synthetic's real lego transforms with generated 800×800 images, whole and broken.</summary>
    [TestFixture]
    public class ValidateLegoTests
    {
        Scratch _scratch;
        string _lego;

        [SetUp]
        public void SetUp()
        {
            _scratch = new Scratch();
            _lego = _scratch.PathOf("lego");
            TestDatasets.Lego(_lego);
        }

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        [Test]
        public void RealLegoPasses()
        {
            var run = ToolRun.Of("validate", _lego);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.Contain("train 100, val 100, test 100 frames; 300 images (800×800), 0 extra files; 0 problems, 0 warnings."));
        }

        [Test]
        public void EachBreakageFailsWithItsLine()
        {
            File.Delete(Path.Combine(_lego, "train", "r_4.png"));
            var path = Path.Combine(_lego, "test", "r_8.png");
            File.WriteAllBytes(path, File.ReadAllBytes(path).Take(100).ToArray());
            var run = ToolRun.Of("validate", _lego);
            Assert.That(run.ExitCode, Is.EqualTo(1));
            var problems = run.Out.Split('\n').Where(l => l.StartsWith("problem: ")).ToList();
            Assert.That(problems, Has.Count.EqualTo(2), run.ToString());
            Assert.That(problems[0], Is.EqualTo("problem: transforms_train.json frame 4 (./train/r_4): image ./train/r_4.png is missing."));
            Assert.That(problems[1], Does.StartWith("problem: transforms_test.json frame 8 (./test/r_8): ./test/r_8.png is truncated"));
        }
    }
}
