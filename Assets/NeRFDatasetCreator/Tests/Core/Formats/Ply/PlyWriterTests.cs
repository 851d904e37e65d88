using System;
using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// 3DGS (scene/dataset_readers.py) writes points3d.ply with plyfile from the dtype
    /// [x f4, y f4, z f4, nx f4, ny f4, nz f4, red u1, green u1, blue u1] and fetchPly reads vertex["x"…"blue"];
    /// plyfile names f4 "float" and u1 "uchar" and writes binary_little_endian by default. The file must be exactly that,
    /// plus one header comment (plyfile keeps comments in PlyData.comments; Open3D's rply skips them) marking it as ours.
    /// </summary>
    public class PlyWriterTests
    {
        const string ExpectedHeader =
            "ply\nformat binary_little_endian 1.0\n" +
            "comment NeRF Dataset Creator: points sampled on the target's surface, output frame; SHA-256 in dataset_config.json\n" +
            "element vertex 2\n" +
            "property float x\nproperty float y\nproperty float z\n" +
            "property float nx\nproperty float ny\nproperty float nz\n" +
            "property uchar red\nproperty uchar green\nproperty uchar blue\n" +
            "end_header\n";

        static readonly CloudPoint[] Points =
        {
            new CloudPoint(new Vector3d(1.5, -2.25, 0.125), new Vector3d(0, 0, 1), 255, 128, 0),
            new CloudPoint(new Vector3d(-0.1, 0.2, 1.3), new Vector3d(0.6, -0.8, 0), 1, 2, 3),
        };

        [Test]
        public void HeaderAndLayout_AreExactlyWhat3dgsReads()
        {
            var stream = new MemoryStream();
            PlyWriter.Write(stream, Points);
            var bytes = stream.ToArray();

            var headerLength = Encoding.ASCII.GetByteCount(ExpectedHeader);
            Assert.That(Encoding.ASCII.GetString(bytes, 0, headerLength), Is.EqualTo(ExpectedHeader));
            Assert.That(bytes.Length, Is.EqualTo(headerLength + 2 * 27), "3 + 3 float32 + 3 uint8 per vertex, no padding");

            // Decoded by hand: little-endian IEEE-754 singles, then three bytes.
            for (var v = 0; v < 2; v++)
            {
                var o = headerLength + 27 * v;
                var p = Points[v];
                var expected = new[] { p.Position.X, p.Position.Y, p.Position.Z, p.Normal.X, p.Normal.Y, p.Normal.Z };
                for (var k = 0; k < 6; k++)
                    Assert.That(LittleEndianSingle(bytes, o + 4 * k), Is.EqualTo((float)expected[k]), "vertex " + v + " float " + k);
                Assert.That(new[] { bytes[o + 24], bytes[o + 25], bytes[o + 26] }, Is.EqualTo(new[] { p.Red, p.Green, p.Blue }));
            }
        }

        [Test]
        public void KnownBytes_ForOneVertex()
        {
            var stream = new MemoryStream();
            PlyWriter.Write(stream, new[] { new CloudPoint(new Vector3d(1, -2, 0.5), Vector3d.Zero, 10, 20, 30) });
            var body = stream.ToArray().Skip(Encoding.ASCII.GetByteCount(PlyWriter.Header(1))).ToArray();

            // 1.0f = 0x3F800000, −2.0f = 0xC0000000, 0.5f = 0x3F000000, stored low byte first.
            Assert.That(body, Is.EqualTo(new byte[]
            {
                0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x00, 0xC0, 0x00, 0x00, 0x00, 0x3F,
                0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                10, 20, 30,
            }));
        }

        [Test]
        public void WriteToPath_NeverOverwrites()
        {
            var path = Path.Combine(Path.GetTempPath(), "nerf-ply-" + Guid.NewGuid().ToString("N") + ".ply");
            try
            {
                PlyWriter.Write(path, Points);
                Assert.Throws<IOException>(() => PlyWriter.Write(path, Points));
            }
            finally
            {
                File.Delete(path);
            }
        }

        [TestCase(0.0, 0)]
        [TestCase(1.0, 255)]
        [TestCase(0.5, 128)] // 127.5 rounds away from zero
        [TestCase(1.7, 255)]
        [TestCase(-0.2, 0)]
        public void ColourChannels_RoundAndClamp(double channel, int expected)
        {
            Assert.That((int)CloudPoint.ToByte(channel), Is.EqualTo(expected));
        }

        [Test]
        public void Reader_RoundTripsTheWriter_AndRefusesOtherLayouts()
        {
            var path = Path.Combine(Path.GetTempPath(), "nerf-ply-" + Guid.NewGuid().ToString("N") + ".ply");
            try
            {
                PlyWriter.Write(path, Points);
                var back = PlyReader.Read(path);
                Assert.That(back.Count, Is.EqualTo(2));
                Assert.That(back[1].Position.Z, Is.EqualTo((double)(float)1.3));
                Assert.That(new[] { back[0].Red, back[0].Green, back[0].Blue }, Is.EqualTo(new byte[] { 255, 128, 0 }));

                File.WriteAllText(path, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n");
                var e = Assert.Throws<InvalidParameterException>(() => PlyReader.Read(path));
                Assert.That(e.Problems[0].Field, Is.EqualTo("points3d.ply"));
            }
            finally
            {
                File.Delete(path);
            }
        }

        static float LittleEndianSingle(byte[] b, int offset)
        {
            var bits = b[offset] | (b[offset + 1] << 8) | (b[offset + 2] << 16) | (b[offset + 3] << 24);
            return BitConverter.ToSingle(BitConverter.GetBytes(bits), 0);
        }
    }
}
