using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.IO.Compression;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// NumPy's file formats, for loaders that <c>np.load</c> their input. A <c>.npy</c> file (NumPy's
    /// "format.rst", version 1.0): the magic <c>\x93NUMPY</c>, bytes 1 and 0 (the version), the header's length as a
    /// little-endian uint16, then the header — a Python dict literal with <c>descr</c>, <c>fortran_order</c> and
    /// <c>shape</c>, padded with spaces and ended by a newline so that the data starts at a multiple of 64 bytes — then
    /// the array's bytes in C order. A <c>.npz</c> is a zip of such files, each named &lt;key&gt;.npy
    /// (<c>np.savez</c> stores them uncompressed, as here).
    /// </summary>
    public static class NumpyFiles
    {
        static readonly byte[] Magic = { 0x93, (byte)'N', (byte)'U', (byte)'M', (byte)'P', (byte)'Y', 1, 0 };

        /// <summary>The alignment of the data that NumPy 1.x/2.x writes (format.rst: "evenly divisible by 64").</summary>
        public const int Alignment = 64;

        /// <summary>A 2-D little-endian float32 array (<c>'&lt;f4'</c>) of <paramref name="rows"/> × <paramref name="columns"/>, row-major.</summary>
        public static byte[] Float32Matrix(float[] values, int rows, int columns)
        {
            if (values == null) throw new ArgumentNullException(nameof(values));
            if (rows < 0 || columns < 0 || (long)rows * columns != values.Length)
                throw new ArgumentException("values holds " + values.Length + " numbers, not " + rows + " × " + columns + ".", nameof(values));
            return Float32Array(values, rows, columns);
        }

        /// <summary>
        /// A little-endian float32 array (<c>'&lt;f4'</c>) of any <paramref name="shape"/>, C order: e.g. DyCheck's depth
        /// maps are (H, W, 1). The header is <see cref="Float32Matrix"/>'s with the shape's tuple (one dimension: "(n,)").
        /// </summary>
        public static byte[] Float32Array(float[] values, params int[] shape)
        {
            if (values == null) throw new ArgumentNullException(nameof(values));
            var tuple = ShapeTuple(shape, values.Length);
            var bytes = Start("<f4", tuple, 4, values.Length, out var data);
            for (var i = 0; i < values.Length; i++)
            {
                var bits = BitConverter.SingleToInt32Bits(values[i]);
                bytes[data + 4 * i] = (byte)bits;
                bytes[data + 4 * i + 1] = (byte)(bits >> 8);
                bytes[data + 4 * i + 2] = (byte)(bits >> 16);
                bytes[data + 4 * i + 3] = (byte)(bits >> 24);
            }
            return bytes;
        }

        /// <summary>A uint8 array (<c>'|u1'</c>) of any <paramref name="shape"/>, C order: e.g. per-pixel or per-point state codes.</summary>
        public static byte[] UInt8Array(byte[] values, params int[] shape)
        {
            if (values == null) throw new ArgumentNullException(nameof(values));
            var tuple = ShapeTuple(shape, values.Length);
            var bytes = Start("|u1", tuple, 1, values.Length, out var data);
            Buffer.BlockCopy(values, 0, bytes, data, values.Length);
            return bytes;
        }

        /// <summary>The header's shape tuple ("(n,)" for one dimension) of <paramref name="shape"/>, which must hold <paramref name="length"/> items.</summary>
        static string ShapeTuple(int[] shape, int length)
        {
            if (shape == null || shape.Length == 0) throw new ArgumentException("an array needs at least one dimension.", nameof(shape));
            long count = 1;
            foreach (var n in shape)
            {
                if (n < 0) throw new ArgumentException("a dimension is never negative.", nameof(shape));
                count *= n;
            }
            if (count != length) throw new ArgumentException("values holds " + length + " numbers, not " + count + ".", "values");
            return string.Join(", ", Array.ConvertAll(shape, n => n.ToString(CultureInfo.InvariantCulture))) + (shape.Length == 1 ? "," : "");
        }

        /// <summary>
        /// A .npy file's bytes up to its data: magic, version, header length and the header dict padded to
        /// <see cref="Alignment"/>, with room for <paramref name="count"/> items of <paramref name="itemSize"/> bytes
        /// starting at <paramref name="data"/>.
        /// </summary>
        static byte[] Start(string descr, string shapeTuple, int itemSize, int count, out int data)
        {
            var dict = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': (" + shapeTuple + "), }";
            var unpadded = Magic.Length + 2 + dict.Length + 1;
            var padding = (Alignment - unpadded % Alignment) % Alignment;
            var header = Encoding.ASCII.GetBytes(dict + new string(' ', padding) + "\n");
            var bytes = new byte[Magic.Length + 2 + header.Length + (long)itemSize * count];
            Buffer.BlockCopy(Magic, 0, bytes, 0, Magic.Length);
            bytes[8] = (byte)(header.Length & 0xFF);
            bytes[9] = (byte)(header.Length >> 8);
            Buffer.BlockCopy(header, 0, bytes, 10, header.Length);
            data = 10 + header.Length;
            return bytes;
        }

        /// <summary>Writes a new <c>.npz</c> holding one array under <paramref name="key"/> (<c>np.load(path)[key]</c>); never overwrites.</summary>
        public static void WriteNpz(string path, string key, byte[] npy) => FileOps.WriteNewBytes(path, Npz(key, npy));

        /// <summary>The bytes of an <c>.npz</c> (a zip archive) holding one array under <paramref name="key"/>.</summary>
        public static byte[] Npz(string key, byte[] npy) => Npz(new[] { new KeyValuePair<string, byte[]>(key, npy) });

        /// <summary>
        /// A 2-D little-endian float64 array (<c>'&lt;f8'</c>) of <paramref name="rows"/> × <paramref name="columns"/>, row-major:
        /// what <c>np.save</c> writes for Python floats (LLFF's <c>poses_bounds.npy</c>, IDR's camera matrices).
        /// </summary>
        public static byte[] Float64Matrix(double[] values, int rows, int columns)
        {
            if (values == null) throw new ArgumentNullException(nameof(values));
            if (rows < 0 || columns < 0 || (long)rows * columns != values.Length)
                throw new ArgumentException("values holds " + values.Length + " numbers, not " + rows + " × " + columns + ".", nameof(values));
            var bytes = Start("<f8", rows.ToString(CultureInfo.InvariantCulture) + ", " + columns.ToString(CultureInfo.InvariantCulture), 8, values.Length, out var data);
            for (var i = 0; i < values.Length; i++)
            {
                var bits = BitConverter.DoubleToInt64Bits(values[i]);
                for (var b = 0; b < 8; b++) bytes[data + 8 * i + b] = (byte)(bits >> (8 * b));
            }
            return bytes;
        }

        /// <summary>The bytes of an <c>.npz</c> holding several arrays, each under its key (<c>np.load(path)[key]</c>), in the order given.</summary>
        public static byte[] Npz(IReadOnlyList<KeyValuePair<string, byte[]>> arrays)
        {
            var buffer = new MemoryStream();
            using (var zip = new ZipArchive(buffer, ZipArchiveMode.Create, leaveOpen: true))
                foreach (var pair in arrays)
                {
                    var entry = zip.CreateEntry(pair.Key + ".npy", CompressionLevel.NoCompression);
                    // A fixed date (the zip format's first, 1980-01-01) instead of the clock's: the same arrays give the same bytes.
                    entry.LastWriteTime = new DateTimeOffset(new DateTime(1980, 1, 1, 0, 0, 0, DateTimeKind.Unspecified), TimeSpan.Zero);
                    using (var stream = entry.Open()) stream.Write(pair.Value, 0, pair.Value.Length);
                }
            return buffer.ToArray();
        }
    }
}
