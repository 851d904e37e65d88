using System;
using System.IO;
using System.IO.Compression;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A minimal valid PNG writer for test images (all pixels zero, filter 0, zlib via DeflateStream), built from
    /// the PNG spec (signature, IHDR, IDAT, IEND, CRC-32 over type and data, zlib header and Adler-32). It lives
    /// in the tests only: Core's real encoder belongs to Core/Imaging.
    /// </summary>
    static class TestPng
    {
        public static byte[] Encode(int width, int height, int bitDepth, int colorType)
        {
            var channels = colorType == 0 ? 1 : colorType == 2 ? 3 : colorType == 4 ? 2 : colorType == 6 ? 4 : 1;
            var rowBytes = 1 + (width * channels * bitDepth + 7) / 8;
            var raw = new byte[rowBytes * height]; // every row: filter type 0, then zero samples

            var png = new MemoryStream();
            png.Write(new byte[] { 137, 80, 78, 71, 13, 10, 26, 10 }, 0, 8);
            var ihdr = new byte[13];
            BigEndian(ihdr, 0, (uint)width);
            BigEndian(ihdr, 4, (uint)height);
            ihdr[8] = (byte)bitDepth;
            ihdr[9] = (byte)colorType;
            Chunk(png, "IHDR", ihdr);
            Chunk(png, "IDAT", Zlib(raw));
            Chunk(png, "IEND", new byte[0]);
            return png.ToArray();
        }

        public static void Write(string path, int width, int height, int bitDepth = 8, int colorType = 6)
        {
            Directory.CreateDirectory(Path.GetDirectoryName(path));
            File.WriteAllBytes(path, Encode(width, height, bitDepth, colorType));
        }

        static byte[] Zlib(byte[] data)
        {
            var output = new MemoryStream();
            output.WriteByte(0x78);
            output.WriteByte(0x9C);
            using (var deflate = new DeflateStream(output, CompressionLevel.Fastest, true))
                deflate.Write(data, 0, data.Length);
            uint a = 1, b = 0;
            foreach (var d in data)
            {
                a = (a + d) % 65521;
                b = (b + a) % 65521;
            }
            var adler = new byte[4];
            BigEndian(adler, 0, (b << 16) | a);
            output.Write(adler, 0, 4);
            return output.ToArray();
        }

        static void Chunk(Stream s, string type, byte[] data)
        {
            var header = new byte[8];
            BigEndian(header, 0, (uint)data.Length);
            for (var i = 0; i < 4; i++) header[4 + i] = (byte)type[i];
            s.Write(header, 0, 8);
            s.Write(data, 0, data.Length);
            var crc = Crc32(header, 4, 4, 0xFFFFFFFFu);
            crc = Crc32(data, 0, data.Length, crc) ^ 0xFFFFFFFFu;
            var tail = new byte[4];
            BigEndian(tail, 0, crc);
            s.Write(tail, 0, 4);
        }

        static uint Crc32(byte[] data, int offset, int count, uint crc)
        {
            for (var i = offset; i < offset + count; i++)
            {
                crc ^= data[i];
                for (var k = 0; k < 8; k++) crc = (crc & 1) != 0 ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
            }
            return crc;
        }

        static void BigEndian(byte[] b, int offset, uint v)
        {
            b[offset] = (byte)(v >> 24);
            b[offset + 1] = (byte)(v >> 16);
            b[offset + 2] = (byte)(v >> 8);
            b[offset + 3] = (byte)v;
        }
    }
}
