using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary><c>convert --to colmap --binary --min-track N</c> end to end on an analytic dataset with depth, masks and its own cloud.</summary>
    [TestFixture]
    public class ConvertColmapTracksTests
    {
        Scratch _scratch;
        string _dataset;

        [SetUp]
        public void SetUp()
        {
            _scratch = new Scratch();
            _dataset = _scratch.PathOf("spheres");
            var scene = SphereScene.TwoSpheres();
            var k = CameraIntrinsics.FromVerticalFov(40, 64, 48);
            var views = new[] { "train", "train", "train", "val", "test" }
                .Select((split, i) => (split, SphereScene.LookAt(new Vector3d(4.5 * System.Math.Cos(i * 1.2), 4.5 * System.Math.Sin(i * 1.2), 1.5), Vector3d.Zero)))
                .ToList();
            scene.WriteDataset(_dataset, views, k, scene.Sample(800, 3));
        }

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        [Test]
        public void BinaryWithTracksPrintsTheFilesAndBothTrainingCommands()
        {
            var output = _scratch.PathOf("out");
            var run = ToolRun.Of("convert", _dataset, "--to", "colmap", "--binary", "--min-track", "1", "--out", output);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var sparse = Path.Combine(output, "sparse", "0");
            Assert.That(run.Out, Does.Contain("  wrote " + Path.Combine(sparse, "cameras.bin") + "\n")
                .And.Contain("  wrote " + Path.Combine(sparse, "images.bin") + "\n")
                .And.Contain("  wrote " + Path.Combine(sparse, "points3D.bin") + "\n")
                .And.Contain("train with: python train.py -s " + output + " --eval   (3D Gaussian Splatting)\n")
                .And.Contain("train with: python simple_trainer.py default --data_dir " + output + " --data_factor 1 --depth_loss --result_dir results/out"));
            Assert.That(Directory.GetFiles(sparse, "*.txt").Select(Path.GetFileName), Is.EqualTo(new[] { "test.txt" }));
            Assert.That(run.Err, Does.Not.Contain("tracks"), "tracks were computed: no warning about them");
            using (var images = new BinaryReader(File.OpenRead(Path.Combine(sparse, "images.bin"))))
                Assert.That(images.ReadUInt64(), Is.EqualTo(5UL));
        }

        [Test]
        public void ABadPointCountIsAUsageError()
        {
            var run = ToolRun.Of("convert", _dataset, "--to", "colmap", "--points", "0");
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("--points 0: "));
        }
    }
}
