using System;
using System.Buffers.Binary;
using System.IO;
using System.Text;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The binary model byte by byte against COLMAP's documented layout (src/colmap/scene/reconstruction_io_binary.cc
    /// at 5d968cf, WriteCamerasBinary lines 340–356, WriteImagesBinary 408–440, WritePoints3DBinary 449–474;
    /// scripts/python/read_write_model.py: "iiQQ" + "d"·num_params, "idddddddi" + name + NUL + "Q" + "ddq"·n,
    /// "QdddBBBd" + "Q" + "ii"·track_length), all little-endian, offsets counted by hand.
    /// </summary>
    public class ColmapBinaryWriterTests
    {
        static CameraIntrinsics K => CameraIntrinsics.FromVerticalFov(50, 40, 30, 0.05, 0.1);

        /// <summary>Two images (one with a non-ASCII name), two points: point 1 seen by both images, point 2 by the second.</summary>
        static ColmapModel TinyModel()
        {
            var poses = new[]
            {
                ColmapPose.FromCameraToWorld(SphereScene.LookAt(new Vector3d(0, -4, 1), Vector3d.Zero)),
                ColmapPose.FromCameraToWorld(SphereScene.LookAt(new Vector3d(3, -3, 0.5), Vector3d.Zero)),
            };
            var points = new[]
            {
                new CloudPoint(new Vector3d(0.1, 0.2, 0.3), Vector3d.UnitZ, 10, 20, 30),
                new CloudPoint(new Vector3d(-0.25, 0.5, 0), Vector3d.UnitX, 200, 100, 0),
            };
            return new ColmapModel(K, new[] { "train_r_0.png", "val_é.png" }, poses, points, new[] { new[] { 0 }, new[] { 0, 1 } });
        }

        static byte[] Bytes(Action<Stream> write)
        {
            var stream = new MemoryStream();
            write(stream);
            return stream.ToArray();
        }

        static ulong U64(byte[] b, int at) => BinaryPrimitives.ReadUInt64LittleEndian(new ReadOnlySpan<byte>(b, at, 8));
        static uint U32(byte[] b, int at) => BinaryPrimitives.ReadUInt32LittleEndian(new ReadOnlySpan<byte>(b, at, 4));
        static int I32(byte[] b, int at) => BinaryPrimitives.ReadInt32LittleEndian(new ReadOnlySpan<byte>(b, at, 4));
        static double F64(byte[] b, int at) => BitConverter.Int64BitsToDouble(BinaryPrimitives.ReadInt64LittleEndian(new ReadOnlySpan<byte>(b, at, 8)));

        [Test]
        public void CamerasBin_IsCountThenIdModelWidthHeightAndFourParams()
        {
            var b = Bytes(s => ColmapBinaryWriter.WriteCameras(s, K));
            Assert.That(b.Length, Is.EqualTo(8 + 4 + 4 + 8 + 8 + 4 * 8));
            Assert.That(U64(b, 0), Is.EqualTo(1UL), "num_cameras");
            Assert.That(U32(b, 8), Is.EqualTo(1u), "camera_id");
            Assert.That(I32(b, 12), Is.EqualTo(1), "model_id: PINHOLE");
            Assert.That(U64(b, 16), Is.EqualTo(40UL), "width");
            Assert.That(U64(b, 24), Is.EqualTo(30UL), "height");
            Assert.That(new[] { F64(b, 32), F64(b, 40), F64(b, 48), F64(b, 56) }, Is.EqualTo(new[] { K.FlX, K.FlY, K.Cx, K.Cy }));
            Assert.That(b[8], Is.EqualTo(1), "little-endian: the low byte first");
        }

        [Test]
        public void ImagesBin_IsPoseCameraNulTerminatedNameAndPoints2D()
        {
            var model = TinyModel();
            var b = Bytes(s => ColmapBinaryWriter.WriteImages(s, model));
            var name0 = Encoding.UTF8.GetBytes("train_r_0.png");
            var name1 = Encoding.UTF8.GetBytes("val_é.png");
            Assert.That(name1.Length, Is.EqualTo(10), "é is two bytes in UTF-8");
            Assert.That(b.Length, Is.EqualTo(8 + (4 + 56 + 4 + name0.Length + 1 + 8 + 24) + (4 + 56 + 4 + name1.Length + 1 + 8 + 2 * 24)));
            Assert.That(U64(b, 0), Is.EqualTo(2UL), "num_reg_images");
            var at = 8;
            for (var i = 0; i < 2; i++)
            {
                var pose = model.Poses[i];
                Assert.That(U32(b, at), Is.EqualTo((uint)(i + 1)), "image_id");
                var q = pose.Rotation;
                var t = pose.Translation;
                Assert.That(new[] { F64(b, at + 4), F64(b, at + 12), F64(b, at + 20), F64(b, at + 28) }, Is.EqualTo(new[] { q.W, q.X, q.Y, q.Z }), "qvec: w first");
                Assert.That(new[] { F64(b, at + 36), F64(b, at + 44), F64(b, at + 52) }, Is.EqualTo(new[] { t.X, t.Y, t.Z }), "tvec");
                Assert.That(U32(b, at + 60), Is.EqualTo(1u), "camera_id");
                at += 64;
                var name = i == 0 ? name0 : name1;
                Assert.That(new ReadOnlySpan<byte>(b, at, name.Length).ToArray(), Is.EqualTo(name));
                Assert.That(b[at + name.Length], Is.EqualTo(0), "the name ends with NUL");
                at += name.Length + 1;
                var n = i == 0 ? 1 : 2;
                Assert.That(U64(b, at), Is.EqualTo((ulong)n), "num_points2D");
                at += 8;
                for (var k = 0; k < n; k++)
                {
                    // COLMAP's PINHOLE projection of the point, written out here from the pose's quaternion.
                    var p = model.Points[k].Position;
                    var u = new Vector3d(q.X, q.Y, q.Z);
                    var uxp = Vector3d.Cross(u, p);
                    var c = p + 2 * q.W * uxp + 2 * Vector3d.Cross(u, uxp) + t;
                    Assert.That(F64(b, at), Is.EqualTo(K.FlX * c.X / c.Z + K.Cx).Within(1e-9), "x");
                    Assert.That(F64(b, at + 8), Is.EqualTo(K.FlY * c.Y / c.Z + K.Cy).Within(1e-9), "y");
                    Assert.That(U64(b, at + 16), Is.EqualTo((ulong)(k + 1)), "point3D_id (uint64)");
                    at += 24;
                }
            }
            Assert.That(at, Is.EqualTo(b.Length));
        }

        [Test]
        public void Points3DBin_IsIdXyzRgbErrorAndTrack()
        {
            var model = TinyModel();
            var b = Bytes(s => ColmapBinaryWriter.WritePoints3D(s, model));
            Assert.That(b.Length, Is.EqualTo(8 + (8 + 24 + 3 + 8 + 8 + 2 * 8) + (8 + 24 + 3 + 8 + 8 + 1 * 8)));
            Assert.That(U64(b, 0), Is.EqualTo(2UL), "num_points");
            // Point 1: id, xyz, rgb, error, track (image 1, POINTS2D 0), (image 2, POINTS2D 0).
            Assert.That(U64(b, 8), Is.EqualTo(1UL));
            Assert.That(new[] { F64(b, 16), F64(b, 24), F64(b, 32) }, Is.EqualTo(new[] { 0.1, 0.2, 0.3 }));
            Assert.That(new[] { b[40], b[41], b[42] }, Is.EqualTo(new byte[] { 10, 20, 30 }));
            Assert.That(F64(b, 43), Is.EqualTo(0.0), "error: every 2D point is the exact projection");
            Assert.That(U64(b, 51), Is.EqualTo(2UL), "track_length");
            Assert.That(new[] { U32(b, 59), U32(b, 63), U32(b, 67), U32(b, 71) }, Is.EqualTo(new uint[] { 1, 0, 2, 0 }));
            // Point 2, seen by image 2 as its second 2D point.
            Assert.That(U64(b, 75), Is.EqualTo(2UL));
            Assert.That(new[] { F64(b, 83), F64(b, 91), F64(b, 99) }, Is.EqualTo(new[] { -0.25, 0.5, 0.0 }));
            Assert.That(new[] { b[107], b[108], b[109] }, Is.EqualTo(new byte[] { 200, 100, 0 }));
            Assert.That(U64(b, 118), Is.EqualTo(1UL));
            Assert.That(new[] { U32(b, 126), U32(b, 130) }, Is.EqualTo(new uint[] { 2, 1 }));
        }

        [Test]
        public void TheTextModelListsTheSameObservations()
        {
            var model = TinyModel();
            var images = new StringWriter();
            ColmapTextWriter.WriteImages(images, model);
            var lines = images.ToString().Split('\n');
            Assert.That(lines[3], Is.EqualTo("# Number of images: 2, mean observations per image: 1.5"));
            Assert.That(lines[4], Does.StartWith("1 ").And.EndWith(" 1 train_r_0.png"));
            Assert.That(lines[5].Split(' '), Has.Length.EqualTo(3));
            Assert.That(lines[5].Split(' ')[2], Is.EqualTo("1"));
            Assert.That(lines[7].Split(' '), Has.Length.EqualTo(6));
            Assert.That(lines[7].Split(' ')[5], Is.EqualTo("2"));
            var points = new StringWriter();
            ColmapTextWriter.WritePoints3D(points, model);
            var p = points.ToString().Split('\n');
            Assert.That(p[2], Is.EqualTo("# Number of points: 2, mean track length: 1.5"));
            Assert.That(p[3], Is.EqualTo("1 0.1 0.2 0.3 10 20 30 0 1 0 2 0"));
            Assert.That(p[4], Is.EqualTo("2 -0.25 0.5 0 200 100 0 0 2 1"));
        }
    }
}
