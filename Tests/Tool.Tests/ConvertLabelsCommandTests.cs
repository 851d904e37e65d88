using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// <c>nerf-dataset convert --to gaussian-grouping</c> and <c>--object</c> on a dataset captured without labels, as the
    /// installed tool answers: one <c>error:</c> line naming labels.json (exit 1, nothing written), and a usage error
    /// (exit 2) for <c>--object</c> with another target. The exports themselves are read back in the Core tests
    /// (GaussianGroupingExportTests, ObjectMaskExportTests).
    /// </summary>
    [TestFixture]
    public class ConvertLabelsCommandTests
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

        static void AssertOneErrorNamingLabels(ToolRun run)
        {
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            var errors = run.Err.Split('\n').Where(l => l.StartsWith("error:", System.StringComparison.Ordinal)).ToList();
            Assert.That(errors, Has.Count.EqualTo(1), run.ToString());
            Assert.That(errors[0], Does.Contain("labels.json").And.Contain("captured without labels"));
            Assert.That(run.Err, Does.Not.Contain("   at "), "no stack trace");
        }

        [Test]
        public void GaussianGroupingWithoutLabels_IsRefusedNamingLabelsJson()
        {
            AssertOneErrorNamingLabels(ToolRun.Of("convert", _dataset, "--to", "gaussian-grouping"));
            Assert.That(Directory.Exists(Path.Combine(_dataset, "gaussian_grouping")), Is.False, "nothing was written");
        }

        [Test]
        public void ObjectWithoutLabels_IsRefusedNamingLabelsJson()
        {
            AssertOneErrorNamingLabels(ToolRun.Of("convert", _dataset, "--to", "nerfstudio", "--object", "Car"));
            Assert.That(Directory.GetDirectories(_dataset, "object_*"), Is.Empty, "nothing was written");
        }

        [Test]
        public void ObjectWithAnotherTarget_IsAUsageError()
        {
            var run = ToolRun.Of("convert", _dataset, "--to", "colmap", "--object", "Car");
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("--object writes nerfstudio's per-frame mask_path: use it with --to nerfstudio"));
        }
    }
}
