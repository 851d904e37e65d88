using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A PNG reader written from the PNG specification (3rd ed.) and RFC 1950, sharing no code with the writer:
    /// its own bit-by-bit CRC-32, its own per-byte Adler-32, its own unfiltering of all five filter types. Only the
    /// DEFLATE decompression itself is System.IO.Compression's. Every structural error throws.
    /// </summary>
    internal sealed class ReferencePngDecoder
    {
        public int Width;
        public int Height;
        public int BitDepth;
        public int ColorType;
        public byte ZlibCmf;
        public byte ZlibFlg;

        /// <summary>Unfiltered image bytes, rows top first, 16-bit samples big-endian as stored.</summary>
        public byte[] Pixels;

        /// <summary>The filter type byte of each row.</summary>
        public int[] RowFilters;

        public readonly List<string> ChunkTypes = new List<string>();

        static readonly byte[] Signature = { 0x89, (byte)'P', (byte)'N', (byte)'G', 0x0D, 0x0A, 0x1A, 0x0A };

        public static ReferencePngDecoder Decode(byte[] file)
        {
            var png = new ReferencePngDecoder();
            for (int i = 0; i < 8; i++)
                if (file[i] != Signature[i]) throw new FormatException("bad PNG signature at byte " + i);

            var idat = new MemoryStream();
            int pos = 8;
            bool ended = false;
            while (!ended)
            {
                uint length = ReadBigEndian(file, pos);
                string type = "" + (char)file[pos + 4] + (char)file[pos + 5] + (char)file[pos + 6] + (char)file[pos + 7];
                int dataStart = pos + 8;
                if (length > int.MaxValue || dataStart + (long)length + 4 > file.Length) throw new FormatException("chunk " + type + " runs past the end");
                uint storedCrc = ReadBigEndian(file, dataStart + (int)length);
                uint crc = BitwiseCrc32(file, pos + 4, 4 + (int)length);
                if (crc != storedCrc) throw new FormatException($"CRC mismatch in {type}: stored {storedCrc:X8}, computed {crc:X8}");
                png.ChunkTypes.Add(type);

                if (png.ChunkTypes.Count == 1 && type != "IHDR") throw new FormatException("first chunk is " + type);
                switch (type)
                {
                    case "IHDR":
                        if (length != 13) throw new FormatException("IHDR length " + length);
                        png.Width = (int)ReadBigEndian(file, dataStart);
                        png.Height = (int)ReadBigEndian(file, dataStart + 4);
                        png.BitDepth = file[dataStart + 8];
                        png.ColorType = file[dataStart + 9];
                        if (file[dataStart + 10] != 0 || file[dataStart + 11] != 0 || file[dataStart + 12] != 0)
                            throw new FormatException("unsupported compression, filter or interlace method");
                        if (png.Width <= 0 || png.Height <= 0) throw new FormatException("zero size");
                        break;
                    case "IDAT":
                        idat.Write(file, dataStart, (int)length);
                        break;
                    case "IEND":
                        if (length != 0) throw new FormatException("IEND with data");
                        ended = true;
                        break;
                    default:
                        // Critical chunks (upper-case first letter) we do not know would make the file unreadable.
                        if (char.IsUpper(type[0])) throw new FormatException("unknown critical chunk " + type);
                        break;
                }
                pos = dataStart + (int)length + 4;
            }
            if (pos != file.Length) throw new FormatException("bytes after IEND");

            byte[] zlib = idat.ToArray();
            png.ZlibCmf = zlib[0];
            png.ZlibFlg = zlib[1];
            if ((zlib[0] & 0x0F) != 8) throw new FormatException("zlib CM is not deflate");
            if ((zlib[0] >> 4) > 7) throw new FormatException("zlib window larger than 32 KiB");
            if ((zlib[0] * 256 + zlib[1]) % 31 != 0) throw new FormatException("zlib FCHECK wrong");
            if ((zlib[1] & 0x20) != 0) throw new FormatException("zlib preset dictionary not allowed in PNG");

            byte[] raw;
            using (var input = new MemoryStream(zlib, 2, zlib.Length - 6))
            using (var inflate = new DeflateStream(input, CompressionMode.Decompress))
            using (var result = new MemoryStream())
            {
                inflate.CopyTo(result);
                raw = result.ToArray();
            }
            uint storedAdler = ReadBigEndian(zlib, zlib.Length - 4);
            uint adler = SimpleAdler32(raw);
            if (adler != storedAdler) throw new FormatException($"Adler-32 mismatch: stored {storedAdler:X8}, computed {adler:X8}");

            int channels = png.ColorType == 0 ? 1 : png.ColorType == 2 ? 3 : png.ColorType == 6 ? 4 : png.ColorType == 4 ? 2 : -1;
            if (channels < 0) throw new FormatException("colour type " + png.ColorType + " not handled by this reader");
            if (png.BitDepth != 8 && png.BitDepth != 16) throw new FormatException("bit depth " + png.BitDepth + " not handled by this reader");
            int bytesPerPixel = channels * png.BitDepth / 8;
            int stride = png.Width * bytesPerPixel;
            if (raw.Length != png.Height * (stride + 1)) throw new FormatException($"inflated {raw.Length} bytes, expected {png.Height * (stride + 1)}");

            png.Pixels = new byte[png.Height * stride];
            png.RowFilters = new int[png.Height];
            for (int y = 0; y < png.Height; y++)
            {
                int filter = raw[y * (stride + 1)];
                png.RowFilters[y] = filter;
                for (int x = 0; x < stride; x++)
                {
                    int filtered = raw[y * (stride + 1) + 1 + x];
                    int a = x >= bytesPerPixel ? png.Pixels[y * stride + x - bytesPerPixel] : 0;
                    int b = y > 0 ? png.Pixels[(y - 1) * stride + x] : 0;
                    int c = x >= bytesPerPixel && y > 0 ? png.Pixels[(y - 1) * stride + x - bytesPerPixel] : 0;
                    int predictor;
                    switch (filter)
                    {
                        case 0: predictor = 0; break;
                        case 1: predictor = a; break;
                        case 2: predictor = b; break;
                        case 3: predictor = (a + b) / 2; break;
                        case 4: predictor = PaethPredictor(a, b, c); break;
                        default: throw new FormatException("filter type " + filter + " on row " + y);
                    }
                    png.Pixels[y * stride + x] = (byte)((filtered + predictor) % 256);
                }
            }
            return png;
        }

        /// <summary>PNG spec §9.4, written as the specification's pseudocode.</summary>
        static int PaethPredictor(int a, int b, int c)
        {
            int p = a + b - c;
            int pa = Math.Abs(p - a);
            int pb = Math.Abs(p - b);
            int pc = Math.Abs(p - c);
            if (pa <= pb && pa <= pc) return a;
            if (pb <= pc) return b;
            return c;
        }

        /// <summary>CRC-32 one bit at a time (PNG spec Annex D without the table).</summary>
        public static uint BitwiseCrc32(byte[] data, int offset, int count)
        {
            uint crc = 0xFFFFFFFF;
            for (int i = offset; i < offset + count; i++)
            {
                crc ^= data[i];
                for (int bit = 0; bit < 8; bit++)
                {
                    bool low = (crc & 1) != 0;
                    crc >>= 1;
                    if (low) crc ^= 0xEDB88320;
                }
            }
            return ~crc;
        }

        /// <summary>Adler-32 by its definition (RFC 1950 §8), modulo after every byte.</summary>
        public static uint SimpleAdler32(byte[] data)
        {
            uint a = 1, b = 0;
            foreach (byte d in data)
            {
                a = (a + d) % 65521;
                b = (b + a) % 65521;
            }
            return (b << 16) | a;
        }

        static uint ReadBigEndian(byte[] b, int at) =>
            ((uint)b[at] << 24) | ((uint)b[at + 1] << 16) | ((uint)b[at + 2] << 8) | b[at + 3];
    }
}
