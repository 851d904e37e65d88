using System.IO;
using NerfDatasetCreator.Tests;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// Every file and folder the plugin's own commands put into a dataset must count as its own (OwnDataset.WhyNotOurs):
    /// plan's previews and each convert target's default output, camera paths and depth maps included — which is what
    /// clean needs to recognise a dataset a replace moved aside. A replace itself still refuses to delete the exports.
    /// </summary>
    [TestFixture]
    public class ReplaceAfterExportsTests
    {
        Scratch _scratch;

        [SetUp]
        public void SetUp() => _scratch = new Scratch();

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        [Test]
        public void APlannedDatasetWithEveryExportIsTheToolsOwnAndReplaceable()
        {
            var folder = RenderedDataset.PlanOnly(_scratch, "own");
            var png = TestPng.Encode(RenderedDataset.Width, RenderedDataset.Height, 8, PngInfo.ColorTypeRgba);
            foreach (var (split, count) in new[] { ("train", RenderedDataset.Train), ("val", RenderedDataset.Val), ("test", RenderedDataset.Test) })
            {
                Directory.CreateDirectory(Path.Combine(folder, split));
                for (var i = 0; i < count; i++) File.WriteAllBytes(Path.Combine(folder, split, "r_" + i + ".png"), png);
            }
            foreach (var target in new[] { "nerfstudio", "ngp", "colmap" })
            {
                var run = ToolRun.Of("convert", folder, "--to", target);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            }
            Assert.That(File.Exists(Path.Combine(folder, RigPreviewPicture.FileName)), Is.True, "plan drew its picture");
            Assert.That(Directory.Exists(Path.Combine(folder, CameraPathFiles.FolderName)), Is.True, "nerfstudio wrote camera paths");
            Assert.That(Directory.Exists(Path.Combine(folder, NgpWriter.FolderName, CameraPathFiles.FolderName)), Is.True, "ngp wrote camera paths");

            Assert.That(OwnDataset.WhyNotOurs(folder), Is.Null);
            // Its own, but a replace still refuses: the exports were made after the capture, and nothing would bring them back (issue 22).
            Assert.That(OwnDataset.WhyNotReplaceable(folder, rendersImages: true), Does.Contain("is an export made with nerf-dataset convert"));

            File.WriteAllText(Path.Combine(folder, "colmap", "notes.txt"), "mine");
            Assert.That(OwnDataset.WhyNotOurs(folder), Does.Contain("notes.txt"), "a user's file anywhere inside makes it theirs");
        }
    }
}
