using System;
using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 32 items 5 and 9: PLY headers that lie (a count that is no number, negative, 20 digits, 500 M vertices over
    /// a few bytes), ascii garbage, coordinates of 1e300 and degenerate meshes are problems naming the file and the option
    /// that named it — never "unexpected FormatException", an out-of-memory or an IndexOutOfRange in the k-d tree.
    /// </summary>
    public class HostileGeometryTests
    {
        static string Ply(TempFolder temp, string format, string count, byte[] data)
        {
            var path = temp.Combine("recon.ply");
            var header = "ply\nformat " + format + " 1.0\nelement vertex " + count + "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
            File.WriteAllBytes(path, Encoding.ASCII.GetBytes(header).Concat(data).ToArray());
            return path;
        }

        static ValidationProblem Problem(Action read) => Assert.Throws<InvalidParameterException>(() => read()).Problems.Single();

        [TestCase("abc")]
        [TestCase("-5")]
        [TestCase("12345678901234567890")]
        public void AnElementCountThatIsNoCountIsAnUnreadableHeaderLine(string count)
        {
            using (var temp = new TempFolder())
            {
                var path = Ply(temp, "ascii", count, Encoding.ASCII.GetBytes("0 0 0\n"));
                var problem = Problem(() => GeometryFile.Read(path));
                Assert.That((problem.Field, problem.Value, problem.Reason), Is.EqualTo(("--geometry", path, "has an unreadable header line 'element vertex " + count + "'.")));
                Assert.That(PlyHeaderDeclare("element vertex " + count), Is.EqualTo("element vertex " + count));
            }
        }

        static string PlyHeaderDeclare(string elementLine)
        {
            var header = PlyHeader.Read(new MemoryStream(Encoding.ASCII.GetBytes("ply\nformat ascii 1.0\n" + elementLine + "\nproperty float x\nend_header\n")));
            return header.Declare();
        }

        [Test]
        public void AHalfBillionVertexClaimOverAFewBytesIsTruncatedBeforeAnythingIsAllocated()
        {
            using (var temp = new TempFolder())
            {
                // Binary: 3 floats = 12 bytes a vertex, exactly; 500 M vertices need 6 000 000 000 bytes, 12 follow.
                var binary = Ply(temp, "binary_little_endian", "500000000", new byte[12]);
                Assert.That(Problem(() => GeometryFile.Read(binary)).Reason, Is.EqualTo(
                    "is truncated: its header declares element vertex 500000000, at least 6000000000 bytes of binary_little_endian data, but only 12 bytes follow the header."));
                // Ascii: at least a byte per value, 1 500 000 000; 6 follow.
                var ascii = Ply(temp, "ascii", "500000000", Encoding.ASCII.GetBytes("0 0 0\n"));
                Assert.That(Problem(() => GeometryFile.Read(ascii, GeometryFile.Truth)), Has.Property("Field").EqualTo("--gt-mesh").And.Property("Reason").EqualTo(
                    "is truncated: its header declares element vertex 500000000, at least 1500000000 bytes of ascii data, but only 6 bytes follow the header."));
            }
        }

        [Test]
        public void AsciiGarbageIsAValueThatIsNotANumber()
        {
            using (var temp = new TempFolder())
            {
                var path = Ply(temp, "ascii", "2", Encoding.ASCII.GetBytes("0 0 0\n1 x 2\n"));
                Assert.That(Problem(() => GeometryFile.Read(path)).Reason, Is.EqualTo("has the value 'x', which is not a number, in its ascii data."));
                var endless = Ply(temp, "ascii", "2", Encoding.ASCII.GetBytes("0 0 0\n" + new string('7', PlyValueReader.MaxAsciiLine + 10)));
                Assert.That(Problem(() => GeometryFile.Read(endless)).Reason, Does.StartWith("has an ascii line longer than 1048576 characters"));
            }
        }

        [Test]
        public void ACoordinateOf1e300IsRefusedNamingTheVertex()
        {
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("recon.obj");
                File.WriteAllText(path, "v 0 0 0\nv 1e300 0 0\n");
                Assert.That(Problem(() => GeometryFile.Read(path)).Reason, Does.StartWith("has a vertex beyond ±1e30 (number 1: 1E+300, 0, 0)"));
                // The tree itself refuses what it cannot order (it used to run past its arrays).
                Assert.Throws<ArgumentException>(() => new PointKdTree(Enumerable.Repeat(float.PositiveInfinity, 30).ToArray()));
            }
        }

        [Test]
        public void AnUnreadableMeshNamesTheOptionThatNamedIt()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("mesh.ply");
                Directory.CreateDirectory(folder);
                var problem = Problem(() => GeometryFile.Read(folder, GeometryFile.Truth));
                Assert.That((problem.Field, problem.Reason), Is.EqualTo(("--gt-mesh", "does not exist.")));
                var empty = temp.Combine("empty.ply");
                File.WriteAllBytes(empty, new byte[0]);
                problem = Problem(() => GeometryFile.Read(empty, GeometryFile.Truth));
                Assert.That((problem.Field, problem.Reason), Is.EqualTo(("--gt-mesh", "cannot be read: " + empty + " " + ReadableFile.EmptyReason)));
            }
        }
    }
}
