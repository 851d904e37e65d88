using System;
using System.IO;
using System.IO.Compression;
using System.Text;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The .npy and .npz files parsed as NumPy's format specification (numpy/lib/format.py, "format.rst") describes
    /// them, byte by byte: what np.load checks before it trusts a file.
    /// </summary>
    public class NumpyFilesTests
    {
        /// <summary>Parses a version-1.0 .npy: its header text and its little-endian float32 data.</summary>
        internal static (string header, float[] values) ParseNpy(byte[] npy)
        {
            Assert.That(npy[0], Is.EqualTo(0x93));
            Assert.That(Encoding.ASCII.GetString(npy, 1, 5), Is.EqualTo("NUMPY"));
            Assert.That((npy[6], npy[7]), Is.EqualTo(((byte)1, (byte)0)), "format version 1.0");
            var headerLength = npy[8] | (npy[9] << 8);
            var header = Encoding.ASCII.GetString(npy, 10, headerLength);
            Assert.That(header, Does.EndWith("\n"));
            Assert.That((10 + headerLength) % 64, Is.EqualTo(0), "data aligned to 64 bytes");
            var values = new float[(npy.Length - 10 - headerLength) / 4];
            for (var i = 0; i < values.Length; i++) values[i] = BitConverter.ToSingle(npy, 10 + headerLength + 4 * i); // little-endian machine
            return (header, values);
        }

        [Test]
        public void NpyHeaderAndDataFollowTheFormat()
        {
            var values = new[] { 1f, -2.5f, 3e-7f, 0f, 1e6f, -0f };
            var (header, read) = ParseNpy(NumpyFiles.Float32Matrix(values, 2, 3));
            Assert.That(header.TrimEnd(' ', '\n'), Is.EqualTo("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }"));
            Assert.That(read, Is.EqualTo(values));
        }

        [Test]
        public void ShapeMustMatchTheValues()
        {
            Assert.Throws<ArgumentException>(() => NumpyFiles.Float32Matrix(new float[5], 2, 3));
        }

        [Test]
        public void NpzIsAZipWithTheKeyAsAnNpyEntry()
        {
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("a.npz");
                var npy = NumpyFiles.Float32Matrix(new[] { 1f, 2f }, 1, 2);
                NumpyFiles.WriteNpz(path, "data", npy);
                using (var zip = new ZipArchive(File.OpenRead(path), ZipArchiveMode.Read))
                {
                    Assert.That(zip.Entries.Count, Is.EqualTo(1));
                    Assert.That(zip.Entries[0].FullName, Is.EqualTo("data.npy"));
                    using (var s = zip.Entries[0].Open())
                    using (var copy = new MemoryStream())
                    {
                        s.CopyTo(copy);
                        Assert.That(copy.ToArray(), Is.EqualTo(npy));
                    }
                }
                Assert.Throws<IOException>(() => NumpyFiles.WriteNpz(path, "data", npy), "never overwrites");
            }
        }
    }
}
