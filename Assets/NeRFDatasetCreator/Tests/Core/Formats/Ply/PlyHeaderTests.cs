using System;
using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The one PLY header reader (<see cref="PlyHeader"/>) and data reader (<see cref="PlyValueReader"/>) every PLY
    /// reader goes through. Expectations follow the PLY format (Greg Turk, "The PLY Polygon File Format"): header lines
    /// up to "end_header", then the elements in header order.
    /// </summary>
    public class PlyHeaderTests
    {
        static MemoryStream Bytes(string text, params byte[] data)
        {
            var bytes = Encoding.ASCII.GetBytes(text).Concat(data).ToArray();
            return new MemoryStream(bytes);
        }

        [Test]
        public void TheHeaderEndsAtEndHeaderAndTheStreamStandsAtTheData()
        {
            var stream = Bytes("ply\r\nformat binary_little_endian 1.0\r\ncomment made by hand\r\nelement vertex 1\r\nproperty uchar red\r\nend_header\r\n", 7, 8);
            var header = PlyHeader.Read(stream);
            Assert.That(header.Ended, Is.True);
            Assert.That(header.CutShort, Is.False);
            Assert.That(header.Lines, Is.EqualTo(new[] { "ply", "format binary_little_endian 1.0", "comment made by hand", "element vertex 1", "property uchar red", "end_header" }),
                "Windows line ends are not part of a line");
            Assert.That(stream.ReadByte(), Is.EqualTo(7), "nothing after end_header is read");
            Assert.That(header.Text, Does.EndWith("end_header\r\n"));
        }

        [Test]
        public void ACutShortOrEndlessHeaderSaysSoWithinItsLimits()
        {
            var cut = PlyHeader.Read(Bytes("ply\nformat ascii 1.0\nelem"));
            Assert.That((cut.Ended, cut.CutShort, cut.Lines.Count, cut.Text), Is.EqualTo((false, true, 2, "ply\nformat ascii 1.0\nelem")));

            var lines = PlyHeader.Read(Bytes("ply\ncomment a\ncomment b\ncomment c\nend_header\n"), maxLines: 3);
            Assert.That((lines.Ended, lines.CutShort, lines.Lines.Count), Is.EqualTo((false, false, 3)));

            var bytes = PlyHeader.Read(Bytes("ply\ncomment a\nend_header\n"), maxBytes: 6);
            Assert.That((bytes.Ended, bytes.CutShort, bytes.Text), Is.EqualTo((false, false, "ply\nco")));
        }

        [Test]
        public void DeclareReadsTheFormatAndTheElementsInOrder()
        {
            var header = PlyHeader.Read(Bytes("ply\nformat ascii 1.0\nobj_info x\nelement vertex 3\nproperty double x\nproperty\tfloat  y\n" +
                                              "element face 1\nproperty list uchar int vertex_indices\nend_header\n"));
            Assert.That(header.Declare(), Is.Null);
            Assert.That(header.Format, Is.EqualTo("ascii"));
            Assert.That(header.Elements.Select(e => (e.Name, e.Count)), Is.EqualTo(new[] { ("vertex", 3L), ("face", 1L) }));
            Assert.That(header.Elements[0].Properties.Select(p => (p.Name, p.Type, p.IsList)), Is.EqualTo(new[] { ("x", "double", false), ("y", "float", false) }));
            var list = header.Elements[1].Properties.Single();
            Assert.That((list.Name, list.Type, list.CountType, list.IsList), Is.EqualTo(("vertex_indices", "int", "uchar", true)));

            var bad = PlyHeader.Read(Bytes("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x y\nend_header\n"));
            Assert.That(bad.Declare(), Is.EqualTo("property float x y"));
        }

        [Test]
        public void ValuesAreReadInEveryByteOrderAndAsAscii()
        {
            // 1.5f is 0x3FC00000; -2 as int16 is 0xFFFE.
            var little = new PlyValueReader(new MemoryStream(new byte[] { 0x00, 0x00, 0xC0, 0x3F, 0xFE, 0xFF, 200 }), "binary_little_endian", r => new InvalidDataException(r));
            Assert.That((little.Read("float"), little.Read("short"), little.Read("uchar")), Is.EqualTo((1.5, -2.0, 200.0)));
            var big = new PlyValueReader(new MemoryStream(new byte[] { 0x3F, 0xC0, 0x00, 0x00, 0xFF, 0xFE }), "binary_big_endian", r => new InvalidDataException(r));
            Assert.That((big.Read("float32"), big.Read("int16")), Is.EqualTo((1.5, -2.0)));
            var ascii = new PlyValueReader(Bytes("\n1.5 -2\n"), "ascii", r => new InvalidDataException(r));
            ascii.NextLine();
            Assert.That((ascii.Read("float"), ascii.Read("short")), Is.EqualTo((1.5, -2.0)));
            Assert.That(() => ascii.Read("float"), Throws.TypeOf<InvalidDataException>().With.Message.EqualTo("has a short ascii line."));
            var cut = new PlyValueReader(new MemoryStream(new byte[] { 1, 2 }), "binary_little_endian", r => new InvalidDataException(r));
            Assert.That(() => cut.Read("int"), Throws.TypeOf<InvalidDataException>().With.Message.EqualTo("ends before all its elements."));
            Assert.That(() => cut.Read("half"), Throws.TypeOf<InvalidDataException>().With.Message.EqualTo("has a property of unknown type 'half'."));
        }

        [Test]
        public void EveryPlyReaderGoesThroughTheOneHeaderReader()
        {
            // A 3DGS-style points3d.ply (no comment) with Windows line ends: both readers see the same lines, and each
            // refuses or reads it with its own rules — the points3d reader wants PlyWriter's exact bytes.
            var header = "ply\r\nformat binary_little_endian 1.0\r\nelement vertex 1\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\nend_header\r\n";
            var path = Path.Combine(Path.GetTempPath(), "nerf-plyheader-" + Guid.NewGuid().ToString("N") + ".ply");
            try
            {
                File.WriteAllBytes(path, Encoding.ASCII.GetBytes(header).Concat(new byte[] { 0, 0, 0xC0, 0x3F, 0, 0, 0, 0, 0, 0, 0x80, 0xBF }).ToArray());
                Assert.That(GeometryFile.Read(path).Vertices.Single(), Is.EqualTo(new Vector3d(1.5, 0, -1)));
                var e = Assert.Throws<InvalidParameterException>(() => PlyReader.Read(path));
                Assert.That(e.Problems.Single().Reason, Is.EqualTo("has an unreadable vertex count."), "\"1\\r\" is not a count");
            }
            finally
            {
                File.Delete(path);
            }
        }
    }
}
