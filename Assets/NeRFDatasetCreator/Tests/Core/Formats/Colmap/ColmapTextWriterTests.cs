using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class ColmapTextWriterTests
    {
        [Test]
        public void CameraOnMinusYLookingAtTheOrigin_ByHand()
        {
            // OpenGL c2w: right +X, up +Z, back −Y (it looks along +Y), centre (0, −4, 0).
            var c2w = Matrix4x4d.FromColumns(Vector3d.UnitX, Vector3d.UnitZ, -Vector3d.UnitY, new Vector3d(0, -4, 0));

            ColmapTextWriter.WorldToCamera(c2w, out var q, out var t);

            // OpenCV rows: x = +X, y = −Z (down), z = +Y (forward): a +90° turn about X, q = (cos 45°, sin 45°, 0, 0).
            var h = Math.Sqrt(0.5);
            Assert.That(q.W, Is.EqualTo(h).Within(1e-15));
            Assert.That(q.X, Is.EqualTo(h).Within(1e-15));
            Assert.That(q.Y, Is.EqualTo(0.0).Within(1e-15));
            Assert.That(q.Z, Is.EqualTo(0.0).Within(1e-15));
            // The origin is 4 units straight ahead: t = (0, 0, 4).
            Assert.That(t.X, Is.EqualTo(0.0).Within(1e-15));
            Assert.That(t.Y, Is.EqualTo(0.0).Within(1e-15));
            Assert.That(t.Z, Is.EqualTo(4.0).Within(1e-15));
        }

        [Test]
        public void ImagesText_TwoLinesPerImage_WithCommentHeader()
        {
            var frames = new[]
            {
                new ExportFrame("train", "train/r_0.png", Matrix4x4d.Identity),
                new ExportFrame("test", "./test/r_0.png", Matrix4x4d.Identity),
            };

            var names = ColmapTextWriter.ImageNames(frames);
            var lines = ColmapTextWriter.ImagesText(frames, names).Split('\n');

            Assert.That(names, Is.EqualTo(new[] { "train_r_0.png", "test_r_0.png" }));
            Assert.That(lines.Take(4).All(l => l.StartsWith("#")), Is.True);
            Assert.That(lines[3], Is.EqualTo("# Number of images: 2, mean observations per image: 0"));
            // Identity OpenGL c2w → OpenCV rotation diag(1, −1, −1): 180° about X, q = (0, 1, 0, 0); centre 0 → t = 0.
            Assert.That(lines[4], Is.EqualTo("1 0 1 0 0 0 0 0 1 train_r_0.png"));
            Assert.That(lines[5], Is.Empty);
            Assert.That(lines[6], Does.StartWith("2 ").And.EndWith(" 1 test_r_0.png"));
            Assert.That(lines[7], Is.Empty);
        }

        [Test]
        public void ImageNames_MustBeUniqueAndWithoutSpaces()
        {
            var e = Assert.Throws<InvalidParameterException>(() => ColmapTextWriter.ImageNames(new[]
            {
                new ExportFrame("train", "a/b.png", Matrix4x4d.Identity),
                new ExportFrame("train", "a_b.png", Matrix4x4d.Identity),
                new ExportFrame("train", "my image.png", Matrix4x4d.Identity),
            }));

            Assert.That(e.Problems.Select(p => p.Value), Is.EquivalentTo(new[] { "my image.png", "a_b.png" }));
        }

        [Test]
        public void ExportFrame_NeedsTheImageExtension()
        {
            var e = Assert.Throws<InvalidParameterException>(() => new ExportFrame("train", "./train/r_0", Matrix4x4d.Identity));

            Assert.That(e.Problems[0].Field, Is.EqualTo("file_path"));
            Assert.That(new ExportFrame("train", ".\\train\\r_0.png", Matrix4x4d.Identity).ImagePath, Is.EqualTo("train/r_0.png"));
        }

        [Test]
        public void Points3DText_HeaderOnlyWhenEmpty_OtherwiseOneLinePerPoint()
        {
            Assert.That(ColmapTextWriter.Points3DText(null).Split('\n').Where(l => l.Length > 0).All(l => l.StartsWith("#")), Is.True);

            var text = ColmapTextWriter.Points3DText(new[] { new CloudPoint(new Vector3d(0.5, -1, 2), Vector3d.UnitZ, 255, 0, 7) });

            Assert.That(text.Split('\n')[3], Is.EqualTo("1 0.5 -1 2 255 0 7 0"));
        }

        [Test]
        public void CamerasText_IsPinholeWithFxFyCxCy()
        {
            var k = CameraIntrinsics.FromVerticalFov(90, 200, 100);

            var line = ColmapTextWriter.CamerasText(k).Split('\n')[3];

            // vfov 90° on 100 rows: f = 50 / tan 45° = 50 (to rounding).
            var e = line.Split(' ');
            Assert.That(e.Take(4), Is.EqualTo(new[] { "1", "PINHOLE", "200", "100" }));
            Assert.That(double.Parse(e[4], System.Globalization.CultureInfo.InvariantCulture), Is.EqualTo(50.0).Within(1e-12));
            Assert.That(e.Skip(6), Is.EqualTo(new[] { "100", "50" }));
        }
    }
}
