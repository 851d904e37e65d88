using System.IO;
using System.IO.Compression;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Writes minimal valid PNGs (all-zero pixels) from the PNG spec: signature, IHDR, one zlib IDAT, IEND, each
    /// chunk with its CRC-32. Only the converters' header reading needs them; no pixel is ever looked at.
    /// </summary>
    static class TestPng
    {
        public const int ColorTypeGrey = 0;
        public const int ColorTypeRgba = 6;

        public static byte[] Bytes(int width, int height, int bitDepth, int colorType)
        {
            var channels = colorType == ColorTypeRgba ? 4 : 1;
            var rowBytes = 1 + width * channels * bitDepth / 8; // filter byte + samples
            var raw = new byte[rowBytes * height];

            var output = new MemoryStream();
            output.Write(new byte[] { 137, 80, 78, 71, 13, 10, 26, 10 }, 0, 8);
            var ihdr = new byte[13];
            BigEndian(ihdr, 0, (uint)width);
            BigEndian(ihdr, 4, (uint)height);
            ihdr[8] = (byte)bitDepth;
            ihdr[9] = (byte)colorType;
            Chunk(output, "IHDR", ihdr);
            Chunk(output, "IDAT", Zlib(raw));
            Chunk(output, "IEND", new byte[0]);
            return output.ToArray();
        }

        public static void Write(string path, int width, int height, int bitDepth = 8, int colorType = ColorTypeRgba)
        {
            Directory.CreateDirectory(Path.GetDirectoryName(path));
            File.WriteAllBytes(path, Bytes(width, height, bitDepth, colorType));
        }

        static byte[] Zlib(byte[] data)
        {
            var compressed = new MemoryStream();
            compressed.WriteByte(0x78);
            compressed.WriteByte(0x9C);
            using (var deflate = new DeflateStream(compressed, CompressionLevel.Fastest, true))
                deflate.Write(data, 0, data.Length);
            uint a = 1, b = 0;
            foreach (var x in data)
            {
                a = (a + x) % 65521;
                b = (b + a) % 65521;
            }
            var adler = new byte[4];
            BigEndian(adler, 0, (b << 16) | a);
            compressed.Write(adler, 0, 4);
            return compressed.ToArray();
        }

        static void Chunk(Stream output, string type, byte[] data)
        {
            var header = new byte[8];
            BigEndian(header, 0, (uint)data.Length);
            for (var i = 0; i < 4; i++) header[4 + i] = (byte)type[i];
            output.Write(header, 0, 8);
            output.Write(data, 0, data.Length);
            var crc = 0xFFFFFFFFu;
            for (var i = 4; i < 8; i++) crc = Crc(crc, header[i]);
            foreach (var x in data) crc = Crc(crc, x);
            var tail = new byte[4];
            BigEndian(tail, 0, crc ^ 0xFFFFFFFFu);
            output.Write(tail, 0, 4);
        }

        static uint Crc(uint crc, byte value)
        {
            crc ^= value;
            for (var k = 0; k < 8; k++) crc = (crc & 1) != 0 ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
            return crc;
        }

        static void BigEndian(byte[] buffer, int offset, uint value)
        {
            buffer[offset] = (byte)(value >> 24);
            buffer[offset + 1] = (byte)(value >> 16);
            buffer[offset + 2] = (byte)(value >> 8);
            buffer[offset + 3] = (byte)value;
        }
    }
}
