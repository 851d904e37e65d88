using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.IO.Compression;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Reads the float arrays nerfstudio's <c>ns-render dataset</c> writes for raw outputs (<c>np.save</c> into
    /// <c>gzip.open(…npy.gz)</c>): the NumPy format v1–v3 (magic <c>\x93NUMPY</c>, header length, a Python dict literal
    /// with <c>descr</c>, <c>fortran_order</c>, <c>shape</c>), little-endian float16/32/64, C order. Anything else is
    /// refused naming the file.
    /// </summary>
    public static class NpyReader
    {
        public sealed class NpyArray
        {
            public NpyArray(int[] shape, float[] values)
            {
                Shape = shape;
                Values = values;
            }

            public int[] Shape { get; }
            public float[] Values { get; }
        }

        public static NpyArray ReadGz(string path)
        {
            using (var file = ReadableFile.OpenRead(path, ReadableFile.MaxGeometryBytes))
            using (var gz = new GZipStream(file, CompressionMode.Decompress))
            using (var memory = new MemoryStream())
            {
                try { gz.CopyTo(memory); }
                catch (InvalidDataException) { throw Bad(path, "is not gzip-compressed."); }
                return Decode(memory.ToArray(), path);
            }
        }

        public static NpyArray Decode(byte[] bytes, string name)
        {
            if (bytes.Length < 10 || bytes[0] != 0x93 || Encoding.ASCII.GetString(bytes, 1, 5) != "NUMPY") throw Bad(name, "is not a NumPy .npy array.");
            int major = bytes[6];
            int headerLength, start;
            if (major == 1) { headerLength = bytes[8] | (bytes[9] << 8); start = 10; }
            else if (major == 2 || major == 3)
            {
                if (bytes.Length < 12) throw Bad(name, "is cut short.");
                headerLength = BitConverter.ToInt32(bytes, 8);
                start = 12;
            }
            else throw Bad(name, "has NumPy format version " + major + ", which this reader does not know.");
            if (headerLength < 0 || start + headerLength > bytes.Length) throw Bad(name, "is cut short.");
            var header = Encoding.ASCII.GetString(bytes, start, headerLength);
            var descr = Value(header, "descr", name).Trim('\'', '"', ' ');
            if (Value(header, "fortran_order", name).Trim() != "False") throw Bad(name, "is stored in Fortran order.");
            var shape = Shape(Value(header, "shape", name), name);
            long count = 1;
            foreach (var d in shape) count *= d;
            int size;
            switch (descr)
            {
                case "<f2": size = 2; break;
                case "<f4": size = 4; break;
                case "<f8": size = 8; break;
                default: throw Bad(name, "holds '" + descr + "' values; only little-endian floats (<f2, <f4, <f8) are read.");
            }
            var data = start + headerLength;
            if (data + count * size > bytes.Length) throw Bad(name, "is cut short: its shape needs " + count * size + " bytes of data.");
            var values = new float[count];
            for (long i = 0; i < count; i++)
            {
                var at = (int)(data + i * size);
                values[i] = size == 4 ? BitConverter.ToSingle(bytes, at)
                    : size == 8 ? (float)BitConverter.ToDouble(bytes, at)
                    : HalfFloat.ToFloat((ushort)(bytes[at] | (bytes[at + 1] << 8)));
            }
            if (!BitConverter.IsLittleEndian) throw new PlatformNotSupportedException("NpyReader needs a little-endian machine.");
            return new NpyArray(shape, values);
        }

        /// <summary>The text of one key's value in the header dict: up to the next top-level comma (tuples kept whole).</summary>
        static string Value(string header, string key, string name)
        {
            var at = header.IndexOf("'" + key + "'", StringComparison.Ordinal);
            if (at < 0) throw Bad(name, "has no '" + key + "' in its header.");
            var colon = header.IndexOf(':', at);
            var depth = 0;
            var i = colon + 1;
            for (; i < header.Length; i++)
            {
                var c = header[i];
                if (c == '(') depth++;
                else if (c == ')') depth--;
                else if ((c == ',' || c == '}') && depth == 0) break;
            }
            return header.Substring(colon + 1, i - colon - 1).Trim();
        }

        static int[] Shape(string text, string name)
        {
            var inner = text.Trim().TrimStart('(').TrimEnd(')');
            var dims = new List<int>();
            foreach (var part in inner.Split(','))
            {
                var p = part.Trim();
                if (p.Length == 0) continue;
                if (!int.TryParse(p, NumberStyles.None, CultureInfo.InvariantCulture, out var d)) throw Bad(name, "has an unreadable shape " + text + ".");
                dims.Add(d);
            }
            return dims.ToArray();
        }

        static InvalidDataException Bad(string name, string reason) => new InvalidDataException(name + " " + reason);
    }
}
