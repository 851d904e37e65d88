using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The COLMAP model gsplat's normalisation is recomputed from reads the same in binary (written by this plugin's
    /// ColmapBinaryWriter, tracks and 2D points included, so the reader must skip them) and text, and binary wins when
    /// all three .bin files are there (pycolmap's rule).
    /// </summary>
    [TestFixture]
    public class ColmapSparseModelTests
    {
        [Test]
        public void BinaryAndTextHoldTheSameModel()
        {
            using (var temp = new TempFolder())
            {
                var text = ColmapSparseModel.Read(Path.Combine(SplatFixtures.WriteColmapText(temp.Combine("text")), "sparse", "0"));
                var cameras = SplatFixtures.TrainCameras();
                var points = SplatFixtures.SampleOutput();
                var model = new ColmapModel(CameraIntrinsics.FromVerticalFov(60, SplatFixtures.Width, SplatFixtures.Height),
                    cameras.Select((_, i) => "r_" + i + ".png").ToList(), cameras.Select(ColmapPose.FromCameraToWorld).ToList(),
                    points.Select(p => new CloudPoint(p, Vector3d.UnitZ, 1, 2, 3)).ToList(),
                    cameras.Select(_ => Enumerable.Range(0, 10).ToArray()).ToArray());
                var sparse = temp.Combine("binary", "sparse", "0");
                Directory.CreateDirectory(sparse);
                using (var s = File.Create(Path.Combine(sparse, "cameras.bin"))) ColmapBinaryWriter.WriteCameras(s, model.Camera);
                using (var s = File.Create(Path.Combine(sparse, "images.bin"))) ColmapBinaryWriter.WriteImages(s, model);
                using (var s = File.Create(Path.Combine(sparse, "points3D.bin"))) ColmapBinaryWriter.WritePoints3D(s, model);
                File.WriteAllText(Path.Combine(sparse, "points3D.txt"), "1 100 100 100 0 0 0 0\n"); // ignored: the binary model is complete
                var binary = ColmapSparseModel.Read(sparse);
                Assert.That(binary.Source, Does.EndWith("(binary)"));
                Assert.That(binary.Poses.Count, Is.EqualTo(text.Poses.Count));
                Assert.That(binary.Points.Count, Is.EqualTo(text.Points.Count));
                for (var i = 0; i < text.Poses.Count; i++)
                {
                    Assert.That(binary.Poses[i].Rotation, Is.EqualTo(text.Poses[i].Rotation));
                    Assert.That(binary.Poses[i].Translation, Is.EqualTo(text.Poses[i].Translation));
                }
                for (var i = 0; i < text.Points.Count; i++) Assert.That(binary.Points[i], Is.EqualTo(text.Points[i]));
                Assert.That(ColmapSparseModel.FolderOf(temp.Combine("binary")), Is.EqualTo(sparse));
            }
        }
    }
}
