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
            _dataset = RenderedDataset.Create(_scratch, "ds");
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
            var lines = run.Out.TrimEnd('\n').Split('\n');
            Assert.That(lines[0], Is.EqualTo("usage: nerf-dataset <command> [arguments]"));
            Assert.That(lines.Skip(1).Take(11).Select(l => l.Trim().Split(' ')[0]), Is.EqualTo(new[] { "plan", "validate", "merge", "convert", "clean", "check", "evaluate", "splits", "demo", "place-splat", "flow" }), "one line per command");
            Assert.That(lines[1], Does.StartWith("  plan --config <settings.json> --out <dir>"));
            Assert.That(lines[3], Does.StartWith("  merge --out <dir> [--files copy|move] <shard-dir>..."));
            Assert.That(lines[4], Does.StartWith("  convert <dir> --to nerfstudio|colmap|ngp|dynamic3dgs|gaussian-grouping|nerfies|dycheck|llff|dynerf|neus|replica|tum|multiscale|hdr-nerf|tensoir|gs-ir|r3dg|kubric|nsff|shape-of-motion [--out <dir>]"));
            Assert.That(lines[5], Does.StartWith("  clean <dir> [--dry-run]"));
            Assert.That(lines[6], Does.StartWith("  check <dir> [--split S] [--json FILE] [--max-views N] [--model <dir>]"));
            Assert.That(lines[7], Does.StartWith("  evaluate <dir> --renders <dir> [--inverse <dir>] [--split test|sparse_<n>]"));
            Assert.That(lines[8], Does.StartWith("  splits <dir> [--views 8[,3,...]]"));
            Assert.That(lines[9], Does.StartWith("  demo <dir> [--preset static|dynamic|labels|lens|exposure|blur|monocular|hdr|materials|relight|flow]"));
            Assert.That(lines[10], Does.StartWith("  place-splat <dir> --model <trained output> [--trainer 3dgs|nerfstudio|gsplat]"));
            Assert.That(lines[11], Does.StartWith("  flow <dir> [--spans 1[,2,...]] [--no-backward] [--no-scene-flow] [--tracks Q[,Q,...]]"));
            Assert.That(lines[12], Does.StartWith("exit codes:"));
            Assert.That(lines[13], Is.EqualTo("nerf-dataset <command> --help prints that command's options; nerf-dataset --version its version."));
            Assert.That(lines, Has.Length.EqualTo(14));
            Assert.That(ToolRun.Of("help").Out, Is.EqualTo(run.Out));
        }
    }
}
