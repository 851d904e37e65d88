using System;
using System.Globalization;
using System.IO;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>The scalar types of PLY properties (the spec's char … double, or their sized names int8 … float64).</summary>
    public enum PlyScalar
    {
        Int8,
        UInt8,
        Int16,
        UInt16,
        Int32,
        UInt32,
        Float32,
        Float64,
    }

    /// <summary>
    /// Reads the data after a PLY header (<see cref="PlyHeader"/>): scalars of any PLY type, from ascii lines or
    /// binary little- or big-endian bytes, as doubles (every PLY scalar type fits one exactly). What is wrong is
    /// reported through the caller's <c>fail</c>, so each reader keeps its own messages. It reads the stream ahead in
    /// blocks: nothing else reads the stream after it.
    /// </summary>
    public sealed class PlyValueReader
    {
        /// <summary>The longest ascii element line read (a face of 1 M indices would need more; no mesh has one).</summary>
        public const int MaxAsciiLine = 1 << 20;

        readonly Stream stream;
        readonly bool ascii, swap;
        readonly Func<string, Exception> fail;
        readonly byte[] value = new byte[8];
        readonly byte[] block = new byte[1 << 16];
        int blockStart, blockEnd;
        string[] tokens = new string[0];
        int next;

        /// <param name="format">The header's format: ascii, binary_little_endian or binary_big_endian.</param>
        /// <param name="fail">Makes the exception for a reason such as "ends before all its elements.".</param>
        public PlyValueReader(Stream stream, string format, Func<string, Exception> fail)
        {
            this.stream = stream;
            this.fail = fail;
            ascii = format == "ascii";
            swap = (format == "binary_big_endian") == BitConverter.IsLittleEndian;
        }

        /// <summary>The type a header names (<c>float</c>, <c>uint8</c> …); an unknown name fails.</summary>
        public PlyScalar Scalar(string type)
        {
            switch (type)
            {
                case "char": case "int8": return PlyScalar.Int8;
                case "uchar": case "uint8": return PlyScalar.UInt8;
                case "short": case "int16": return PlyScalar.Int16;
                case "ushort": case "uint16": return PlyScalar.UInt16;
                case "int": case "int32": return PlyScalar.Int32;
                case "uint": case "uint32": return PlyScalar.UInt32;
                case "float": case "float32": return PlyScalar.Float32;
                case "double": case "float64": return PlyScalar.Float64;
                default: throw fail("has a property of unknown type '" + type + "'.");
            }
        }

        /// <summary>An ascii file's next element: the next non-blank line. Binary data has no lines; do not call it there.</summary>
        public void NextLine()
        {
            var line = new StringBuilder();
            while (true)
            {
                var b = NextByte();
                if (b < 0) { if (line.Length == 0) throw fail("ends before all its elements."); break; }
                if (b == '\n') { if (line.ToString().Trim().Length == 0) { line.Clear(); continue; } break; }
                // An element is a few numbers: a longer line is binary or garbage data, refused before it fills memory.
                if (line.Length >= MaxAsciiLine) throw fail("has an ascii line longer than " + MaxAsciiLine + " characters: its data is not ascii PLY.");
                line.Append((char)b);
            }
            tokens = line.ToString().Split(new[] { ' ', '\t', '\r' }, StringSplitOptions.RemoveEmptyEntries);
            next = 0;
        }

        /// <summary>The next value, of the PLY type a header names; an ascii file's value is any number, whatever the type says.</summary>
        public double Read(string type)
        {
            if (ascii)
            {
                if (next >= tokens.Length) throw fail("has a short ascii line.");
                var token = tokens[next++];
                if (!double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out var number))
                    throw fail("has the value '" + (token.Length > 40 ? token.Substring(0, 40) + "…" : token) + "', which is not a number, in its ascii data.");
                return number;
            }
            return Read(Scalar(type));
        }

        /// <summary>The next binary value of <paramref name="type"/>.</summary>
        public double Read(PlyScalar type)
        {
            var size = Size(type);
            for (var i = 0; i < size; i++)
            {
                var b = NextByte();
                if (b < 0) throw fail("ends before all its elements.");
                value[i] = (byte)b;
            }
            if (swap) Array.Reverse(value, 0, size);
            switch (type)
            {
                case PlyScalar.Int8: return (sbyte)value[0];
                case PlyScalar.UInt8: return value[0];
                case PlyScalar.Int16: return BitConverter.ToInt16(value, 0);
                case PlyScalar.UInt16: return BitConverter.ToUInt16(value, 0);
                case PlyScalar.Int32: return BitConverter.ToInt32(value, 0);
                case PlyScalar.UInt32: return BitConverter.ToUInt32(value, 0);
                case PlyScalar.Float32: return BitConverter.ToSingle(value, 0);
                default: return BitConverter.ToDouble(value, 0);
            }
        }

        /// <summary>The bytes of the binary scalar type a header names; an unknown name fails.</summary>
        public int SizeOf(string type) => Size(Scalar(type));

        static int Size(PlyScalar type)
        {
            switch (type)
            {
                case PlyScalar.Int8: case PlyScalar.UInt8: return 1;
                case PlyScalar.Int16: case PlyScalar.UInt16: return 2;
                case PlyScalar.Float64: return 8;
                default: return 4;
            }
        }

        int NextByte()
        {
            if (blockStart == blockEnd)
            {
                blockStart = 0;
                blockEnd = Math.Max(0, stream.Read(block, 0, block.Length));
                if (blockEnd == 0) return -1;
            }
            return block[blockStart++];
        }
    }
}
