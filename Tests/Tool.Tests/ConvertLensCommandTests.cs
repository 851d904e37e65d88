using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary><c>nerf-dataset convert</c> of a distorted dataset: carried where it can be, one <c>error:</c> line (exit 1) where it cannot.</summary>
    [TestFixture]
    public class ConvertLensCommandTests
    {
        Scratch _scratch;
        string _dataset;

        [SetUp]
        public void SetUp()
        {
            _scratch = new Scratch();
            _dataset = RenderedDataset.Create(_scratch, "ds");
            // nerfstudio-style lens keys at the top of every split file.
            foreach (var split in new[] { "train", "val", "test" })
            {
                var path = Path.Combine(_dataset, "transforms_" + split + ".json");
                var json = JObject.Parse(File.ReadAllText(path));
                json["camera_model"] = "OPENCV";
                json["k1"] = -0.1;
                json["k2"] = 0.02;
                json["p1"] = 0.001;
                json["p2"] = -0.002;
                File.WriteAllText(path, json.ToString());
            }
        }

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        [Test]
        public void Dynamic3dgs_RefusesWithOneErrorLine()
        {
            var run = ToolRun.Of("convert", _dataset, "--to", "dynamic3dgs");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            var errors = run.Err.Split('\n').Where(l => l.StartsWith("error:", System.StringComparison.Ordinal)).ToList();
            Assert.That(errors, Has.Count.EqualTo(1), run.ToString());
            Assert.That(errors[0], Does.StartWith("error: --to = dynamic3dgs: cannot hold lens distortion").And.Contain("OPENCV (k1 = -0.1, k2 = 0.02, p1 = 0.001, p2 = -0.002)"));
            Assert.That(run.Err, Does.Not.Contain("   at "), "no stack trace");
            Assert.That(Directory.Exists(Path.Combine(_dataset, "dynamic3dgs")), Is.False);
        }

        [Test]
        public void Colmap_WritesOpenCv_AndWarnsThat3dgsReadsOnlyPinholes()
        {
            var run = ToolRun.Of("convert", _dataset, "--to", "colmap");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var cameras = File.ReadAllLines(Path.Combine(_dataset, "colmap", "sparse", "0", "cameras.txt")).Single(l => !l.StartsWith("#", System.StringComparison.Ordinal));
            Assert.That(cameras, Does.StartWith("1 OPENCV ").And.EndWith(" -0.1 0.02 0.001 -0.002"));
            Assert.That(run.Err, Does.Contain("accepts only PINHOLE and SIMPLE_PINHOLE"));
        }
    }
}
