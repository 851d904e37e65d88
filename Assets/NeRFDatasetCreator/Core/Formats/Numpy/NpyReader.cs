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
    /// with <c>descr</c>, <c>fortran_order</c>, <c>shape</c>), little-endian float16/32/64 and uint8 (as floats), C order.
    /// Anything else is refused naming the file.
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

        /// <summary>The longest header read: NumPy pads its dict to 64-byte multiples and writes a few hundred bytes at most.</summary>
        public const int MaxHeaderBytes = 1 << 16;

        /// <summary>
        /// Reads a gzipped .npy, decompressing no more than its header and the data its shape claims: a gzip bomb (1.5 MB
        /// that inflates to 5 GB) is read to the claimed size and no further, and a shape of more than
        /// <paramref name="maxValues"/> values (the caller's image: height × width × channels) is refused before anything is allocated.
        /// </summary>
        public static NpyArray ReadGz(string path, long maxValues = int.MaxValue)
        {
            using (var file = ReadableFile.OpenRead(path, ReadableFile.MaxGeometryBytes))
            using (var gz = new GZipStream(file, CompressionMode.Decompress))
            {
                return Read(new Inflated(gz, path), path, maxValues);
            }
        }

        public static NpyArray Decode(byte[] bytes, string name) => Read(new MemoryStream(bytes, false), name, int.MaxValue);

        static NpyArray Read(Stream stream, string name, long maxValues)
        {
            var prefix = new byte[12];
            if (Fill(stream, prefix, 0, 10) < 10 || prefix[0] != 0x93 || Encoding.ASCII.GetString(prefix, 1, 5) != "NUMPY") throw Bad(name, "is not a NumPy .npy array.");
            int major = prefix[6];
            long headerLength;
            if (major == 1) headerLength = prefix[8] | (prefix[9] << 8);
            else if (major == 2 || major == 3)
            {
                if (Fill(stream, prefix, 10, 2) < 2) throw Bad(name, "is cut short.");
                headerLength = BitConverter.ToUInt32(prefix, 8);
            }
            else throw Bad(name, "has NumPy format version " + major + ", which this reader does not know.");
            if (headerLength > MaxHeaderBytes) throw Bad(name, "declares a header of " + headerLength + " bytes, more than the " + MaxHeaderBytes + " any NumPy writes.");
            var headerBytes = new byte[headerLength];
            if (Fill(stream, headerBytes, 0, headerBytes.Length) < headerBytes.Length) throw Bad(name, "is cut short.");
            var header = Encoding.ASCII.GetString(headerBytes);
            var descr = Value(header, "descr", name).Trim('\'', '"', ' ');
            if (Value(header, "fortran_order", name).Trim() != "False") throw Bad(name, "is stored in Fortran order.");
            var shapeText = Value(header, "shape", name);
            var shape = Shape(shapeText, name);
            long count;
            try
            {
                count = 1;
                foreach (var d in shape) count = checked(count * d); // (2^31)^3 values would wrap a plain product
            }
            catch (OverflowException)
            {
                throw Bad(name, "has shape " + shapeText.Trim() + ", more values than any array holds.");
            }
            if (count > maxValues)
                throw Bad(name, "has shape " + shapeText.Trim() + ": " + count + " values, more than the " + maxValues + " expected.");
            int size;
            switch (descr)
            {
                case "<f2": size = 2; break;
                case "<f4": size = 4; break;
                case "<f8": size = 8; break;
                // uint8 (NumPy writes '|u1': one byte has no order), e.g. flow tracks' state (NumpyFiles.UInt8Array).
                case "|u1":
                case "<u1": size = 1; break;
                default: throw Bad(name, "holds '" + descr + "' values; only little-endian floats (<f2, <f4, <f8) and uint8 (|u1) are read.");
            }
            if (!BitConverter.IsLittleEndian) throw new PlatformNotSupportedException("NpyReader needs a little-endian machine.");
            // The data is read in blocks as it is converted: never more than the shape claims, whatever follows.
            var values = new float[count];
            var block = new byte[size * 8192];
            for (long i = 0; i < count;)
            {
                var n = (int)Math.Min(8192, count - i);
                if (Fill(stream, block, 0, n * size) < n * size) throw Bad(name, "is cut short: its shape needs " + count * size + " bytes of data.");
                for (var k = 0; k < n; k++, i++)
                {
                    var at = k * size;
                    values[i] = size == 4 ? BitConverter.ToSingle(block, at)
                        : size == 8 ? (float)BitConverter.ToDouble(block, at)
                        : size == 1 ? block[at]
                        : HalfFloat.ToFloat((ushort)(block[at] | (block[at + 1] << 8)));
                }
            }
            return new NpyArray(shape, values);
        }

        /// <summary>Reads up to <paramref name="count"/> bytes; fewer only at the end of the stream.</summary>
        static int Fill(Stream stream, byte[] buffer, int offset, int count)
        {
            var read = 0;
            while (read < count)
            {
                var n = stream.Read(buffer, offset + read, count - read);
                if (n <= 0) break;
                read += n;
            }
            return read;
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

        /// <summary>The gzip stream, its InvalidDataException ("not gzip") worded with the file's name.</summary>
        sealed class Inflated : Stream
        {
            readonly Stream gz;
            readonly string path;

            public Inflated(Stream gz, string path)
            {
                this.gz = gz;
                this.path = path;
            }

            public override int Read(byte[] buffer, int offset, int count)
            {
                try { return gz.Read(buffer, offset, count); }
                catch (InvalidDataException e) { throw Bad(path, "is not gzip-compressed (" + e.Message + ")."); }
            }

            public override bool CanRead => true;
            public override bool CanSeek => false;
            public override bool CanWrite => false;
            public override long Length => throw new NotSupportedException();
            public override long Position { get => throw new NotSupportedException(); set => throw new NotSupportedException(); }
            public override void Flush() { }
            public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
            public override void SetLength(long value) => throw new NotSupportedException();
            public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();
        }
    }
}
