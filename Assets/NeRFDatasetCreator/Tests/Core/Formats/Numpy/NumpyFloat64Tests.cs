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
    /// The float64 <c>.npy</c> and multi-key <c>.npz</c> of <see cref="NumpyFiles"/>, read back the way <c>np.load</c>
    /// reads them (NumPy's format.rst: magic, version 1.0, little-endian uint16 header length, dict, data at a multiple
    /// of 64), and the readers the layout tests use.
    /// </summary>
    public class NumpyFloat64Tests
    {
        /// <summary>np.load of a 2-D '&lt;f8' C-order array: (rows, columns, values).</summary>
        internal static (int Rows, int Columns, double[] Values) ParseFloat64(byte[] npy)
        {
            Assert.That(npy[0], Is.EqualTo(0x93));
            Assert.That(Encoding.ASCII.GetString(npy, 1, 5), Is.EqualTo("NUMPY"));
            Assert.That((npy[6], npy[7]), Is.EqualTo(((byte)1, (byte)0)));
            var headerLength = npy[8] | (npy[9] << 8);
            var header = Encoding.ASCII.GetString(npy, 10, headerLength);
            Assert.That((10 + headerLength) % 64, Is.EqualTo(0), "data aligned to 64 bytes");
            Assert.That(header, Does.Contain("'descr': '<f8'").And.Contain("'fortran_order': False"));
            var shape = header.Substring(header.IndexOf("'shape': (", StringComparison.Ordinal) + 10);
            var dims = shape.Substring(0, shape.IndexOf(')')).Split(',').Select(s => s.Trim()).Where(s => s.Length > 0).Select(int.Parse).ToArray();
            Assert.That(dims.Length, Is.EqualTo(2));
            var values = new double[(npy.Length - 10 - headerLength) / 8];
            Assert.That(values.Length, Is.EqualTo(dims[0] * dims[1]));
            for (var i = 0; i < values.Length; i++) values[i] = BitConverter.ToDouble(npy, 10 + headerLength + 8 * i); // little-endian machine
            return (dims[0], dims[1], values);
        }

        /// <summary>np.load of an .npz: every "&lt;key&gt;.npy" entry by key.</summary>
        internal static Dictionary<string, byte[]> ReadNpz(string path)
        {
            var arrays = new Dictionary<string, byte[]>();
            using (var zip = new ZipArchive(File.OpenRead(path), ZipArchiveMode.Read))
                foreach (var entry in zip.Entries)
                {
                    Assert.That(entry.FullName, Does.EndWith(".npy"));
                    using (var s = entry.Open())
                    using (var copy = new MemoryStream())
                    {
                        s.CopyTo(copy);
                        arrays[entry.FullName.Substring(0, entry.FullName.Length - 4)] = copy.ToArray();
                    }
                }
            return arrays;
        }

        [Test]
        public void Float64MatrixKeepsEveryBitOfEachValue()
        {
            var values = new[] { 1.0, -2.5, 0.1, 1e-300, double.MaxValue, -0.0 };
            var (rows, columns, read) = ParseFloat64(NumpyFiles.Float64Matrix(values, 3, 2));
            Assert.That((rows, columns), Is.EqualTo((3, 2)));
            Assert.That(read.Select(BitConverter.DoubleToInt64Bits), Is.EqualTo(values.Select(BitConverter.DoubleToInt64Bits)));
            Assert.Throws<ArgumentException>(() => NumpyFiles.Float64Matrix(new double[5], 2, 3));
        }

        [Test]
        public void NpzHoldsEveryKeyItIsGiven()
        {
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("cameras.npz");
                File.WriteAllBytes(path, NumpyFiles.Npz(new[]
                {
                    new KeyValuePair<string, byte[]>("world_mat_0", NumpyFiles.Float64Matrix(new[] { 1.0, 2 }, 1, 2)),
                    new KeyValuePair<string, byte[]>("scale_mat_0", NumpyFiles.Float64Matrix(new[] { 3.0 }, 1, 1)),
                }));
                var arrays = ReadNpz(path);
                Assert.That(arrays.Keys, Is.EquivalentTo(new[] { "world_mat_0", "scale_mat_0" }));
                Assert.That(ParseFloat64(arrays["world_mat_0"]).Values, Is.EqualTo(new[] { 1.0, 2 }));
                Assert.That(ParseFloat64(arrays["scale_mat_0"]).Values, Is.EqualTo(new[] { 3.0 }));
            }
        }
    }
}
