using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Linq;
using System.Text;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The one .npy reader (<see cref="NpyReader"/>), against files laid out by hand as NumPy's format specification
    /// (numpy/lib/format.py, "format.rst") and np.save write them: magic, version, header length (uint16 in 1.0,
    /// uint32 in 2.0), a dict padded with spaces and ended by '\n', then the data in C order.
    /// </summary>
    public class NpyReaderTests
    {
        /// <summary>np.save's bytes for <paramref name="descr"/> values, in format <paramref name="major"/>.0.</summary>
        internal static byte[] Npy(string descr, int[] shape, byte[] data, int major = 1, string fortranOrder = "False")
        {
            var dict = "{'descr': '" + descr + "', 'fortran_order': " + fortranOrder + ", 'shape': (" + string.Join(", ", shape) + (shape.Length == 1 ? "," : "") + "), }";
            var prefix = major == 1 ? 10 : 12;
            var total = prefix + dict.Length + 1;
            var padded = dict + new string(' ', (64 - total % 64) % 64) + "\n";
            var head = new List<byte> { 0x93 };
            head.AddRange(Encoding.ASCII.GetBytes("NUMPY"));
            head.Add((byte)major);
            head.Add(0);
            head.Add((byte)(padded.Length & 0xff));
            head.Add((byte)(padded.Length >> 8));
            if (major != 1) head.AddRange(new byte[] { 0, 0 });
            head.AddRange(Encoding.ASCII.GetBytes(padded));
            return head.Concat(data).ToArray();
        }

        static byte[] Float32s(params float[] values) => values.SelectMany(v => BitConverter.GetBytes(v)).ToArray(); // little-endian machine

        /// <summary>np.save of little-endian float32 values into gzip.open(path), as nerfstudio's ns-render writes raw outputs.</summary>
        internal static void WriteNpyGz(string path, int[] shape, float[] values)
        {
            var bytes = Npy("<f4", shape, Float32s(values));
            using (var file = File.Create(path))
            using (var gz = new GZipStream(file, CompressionMode.Compress))
                gz.Write(bytes, 0, bytes.Length);
        }

        [Test]
        public void NpyReaderReadsNerfstudiosGzippedFloatArrays()
        {
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("r_0.npy.gz");
                WriteNpyGz(path, new[] { 2, 3, 1 }, new[] { 1f, 2f, 3f, 4f, 5.5f, -1f });
                var array = NpyReader.ReadGz(path);
                Assert.That(array.Shape, Is.EqualTo(new[] { 2, 3, 1 }));
                Assert.That(array.Values, Is.EqualTo(new[] { 1f, 2f, 3f, 4f, 5.5f, -1f }));
            }
        }

        [Test]
        public void HalfAndDoubleFloatsAndFormat2AreRead()
        {
            // float16 1.5 is 0x3E00; -2 is 0xC000.
            var half = NpyReader.Decode(Npy("<f2", new[] { 2 }, new byte[] { 0x00, 0x3E, 0x00, 0xC0 }), "h.npy");
            Assert.That(half.Values, Is.EqualTo(new[] { 1.5f, -2f }));
            var wide = NpyReader.Decode(Npy("<f8", new[] { 1, 1 }, BitConverter.GetBytes(0.25), major: 2), "d.npy");
            Assert.That(wide.Shape, Is.EqualTo(new[] { 1, 1 }));
            Assert.That(wide.Values, Is.EqualTo(new[] { 0.25f }));
        }

        [Test]
        public void UInt8IsReadAsNumpyWritesItAndAsNumpyFilesWritesIt()
        {
            // np.save(np.array([[0, 1], [255, 3]], np.uint8)) writes descr '|u1' (a byte has no byte order).
            var byHand = NpyReader.Decode(Npy("|u1", new[] { 2, 2 }, new byte[] { 0, 1, 255, 3 }), "state.npy");
            Assert.That(byHand.Shape, Is.EqualTo(new[] { 2, 2 }));
            Assert.That(byHand.Values, Is.EqualTo(new[] { 0f, 1f, 255f, 3f }));
            var ours = NpyReader.Decode(NumpyFiles.UInt8Array(new byte[] { 2, 3, 1 }, 1, 3), "tracks state");
            Assert.That(ours.Shape, Is.EqualTo(new[] { 1, 3 }));
            Assert.That(ours.Values, Is.EqualTo(new[] { 2f, 3f, 1f }));
            Assert.That(() => NpyReader.Decode(Npy("|u1", new[] { 3 }, new byte[2]), "s.npy"), Throws.TypeOf<InvalidDataException>().With.Message.EqualTo("s.npy is cut short: its shape needs 3 bytes of data."));
        }

        [Test]
        public void WhatItCannotReadIsRefusedNamingTheFile()
        {
            Assert.That(() => NpyReader.Decode(Encoding.ASCII.GetBytes("PK not numpy"), "a.npy"), Throws.TypeOf<InvalidDataException>().With.Message.EqualTo("a.npy is not a NumPy .npy array."));
            Assert.That(() => NpyReader.Decode(Npy("<i4", new[] { 1 }, new byte[4]), "b.npy"), Throws.TypeOf<InvalidDataException>().With.Message.StartWith("b.npy holds '<i4' values"));
            Assert.That(() => NpyReader.Decode(Npy("<f4", new[] { 1 }, new byte[4], fortranOrder: "True"), "c.npy"), Throws.TypeOf<InvalidDataException>().With.Message.EqualTo("c.npy is stored in Fortran order."));
            Assert.That(() => NpyReader.Decode(Npy("<f4", new[] { 3 }, new byte[8]), "d.npy"), Throws.TypeOf<InvalidDataException>().With.Message.EqualTo("d.npy is cut short: its shape needs 12 bytes of data."));
        }

        [Test]
        public void AShapeWhoseProductOverflowsIsRefusedNamingTheFile()
        {
            // 2147483647³ wraps a 64-bit product (it used to end in a negative-size allocation).
            var huge = Npy("<f4", new[] { int.MaxValue, int.MaxValue, int.MaxValue }, new byte[4]);
            Assert.That(() => NpyReader.Decode(huge, "e.npy"), Throws.InstanceOf<InvalidDataException>().With.Message.EqualTo("e.npy has shape (2147483647, 2147483647, 2147483647), more values than any array holds."));
            var tooMany = Npy("<f4", new[] { 100000, 100000, 1 }, new byte[4]);
            Assert.That(() => NpyReader.Decode(tooMany, "f.npy"), Throws.InstanceOf<InvalidDataException>().With.Message.EqualTo("f.npy has shape (100000, 100000, 1): 10000000000 values, more than the 2147483647 expected."));
        }

        [Test]
        public void AGzipBombIsReadNoFurtherThanItsShapeAndAnArrayLargerThanTheImageIsRefusedUnread()
        {
            using (var temp = new TempFolder())
            {
                // A 2 × 3 array followed by 256 MiB of zeros: about 2.5 MB of gzip at the fastest level.
                var path = temp.Combine("bomb.npy.gz");
                var npy = Npy("<f4", new[] { 2, 3, 1 }, Float32s(1, 2, 3, 4, 5, 6));
                var zeros = new byte[1 << 20];
                using (var file = File.Create(path))
                using (var gz = new GZipStream(file, CompressionLevel.Fastest))
                {
                    gz.Write(npy, 0, npy.Length);
                    for (var i = 0; i < 256; i++) gz.Write(zeros, 0, zeros.Length);
                }
                Assert.That(new FileInfo(path).Length, Is.LessThan(4 << 20));
                var before = GC.GetAllocatedBytesForCurrentThread();
                var array = NpyReader.ReadGz(path, 6);
                var allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                Assert.That(array.Values, Is.EqualTo(new[] { 1f, 2f, 3f, 4f, 5f, 6f }));
                Assert.That(allocated, Is.LessThan(8 << 20), "the 256 MiB of zeros after the data are never inflated into memory");
                // The header's claim is checked against the image the caller expects before the data is read.
                Assert.That(() => NpyReader.ReadGz(path, 5), Throws.InstanceOf<InvalidDataException>().With.Message.EqualTo(path + " has shape (2, 3, 1): 6 values, more than the 5 expected."));
                var header = temp.Combine("header.npy.gz");
                File.WriteAllBytes(header, Gzip(new byte[] { 0x93, (byte)'N', (byte)'U', (byte)'M', (byte)'P', (byte)'Y', 2, 0, 0, 0, 0, 0x40 }));
                Assert.That(() => NpyReader.ReadGz(header), Throws.InstanceOf<InvalidDataException>().With.Message.EqualTo(header + " declares a header of 1073741824 bytes, more than the 65536 any NumPy writes."));
                var plain = temp.Combine("plain.npy.gz");
                File.WriteAllBytes(plain, npy);
                Assert.That(() => NpyReader.ReadGz(plain), Throws.InstanceOf<InvalidDataException>().With.Message.StartsWith(plain + " is not gzip-compressed"));
            }
        }

        static byte[] Gzip(byte[] bytes)
        {
            var memory = new MemoryStream();
            using (var gz = new GZipStream(memory, CompressionMode.Compress, true)) gz.Write(bytes, 0, bytes.Length);
            return memory.ToArray();
        }
    }
}
