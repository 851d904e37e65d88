using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Proves the reference decoder itself against hand-derived data before it is trusted to judge the writer.</summary>
    public class ReferencePngDecoderTests
    {
        [Test]
        public void BitwiseCrcMatchesTheStandardCheckValue()
        {
            // The CRC-32 check value of the ASCII string "123456789" (ISO 3309 / PNG's CRC).
            var data = System.Text.Encoding.ASCII.GetBytes("123456789");
            Assert.That(ReferencePngDecoder.BitwiseCrc32(data, 0, data.Length), Is.EqualTo(0xCBF43926u));
        }

        [Test]
        public void SimpleAdlerMatchesTheKnownValue()
        {
            // The worked example of Adler-32: "Wikipedia" → 0x11E60398.
            Assert.That(ReferencePngDecoder.SimpleAdler32(System.Text.Encoding.ASCII.GetBytes("Wikipedia")), Is.EqualTo(0x11E60398u));
        }

        // A 3×5 gray image whose rows use filter types 0…4, filtered by hand (PNG spec §9.2):
        //   row 0 None    10 20 30                      → 10 20 30
        //   row 1 Sub     15 25 40  (a = left)          → 15 10 15
        //   row 2 Up      20 20 50  (b = 15 25 40)      → 5 −5 10          = 5 251 10
        //   row 3 Average 30 40 35  floor((a+b)/2) = 10 25 45 → 20 15 −10 = 20 15 246
        //   row 4 Paeth   32 44 30  predictors b=30, b=40, c=40 → 2 4 −10  = 2 4 246
        static readonly byte[] HandFiltered =
        {
            0, 10, 20, 30,
            1, 15, 10, 15,
            2, 5, 251, 10,
            3, 20, 15, 246,
            4, 2, 4, 246,
        };

        static readonly byte[] HandPixels = { 10, 20, 30, 15, 25, 40, 20, 20, 50, 30, 40, 35, 32, 44, 30 };

        [Test]
        public void UnfiltersAllFiveTypesOfAHandBuiltFile()
        {
            var png = ReferencePngDecoder.Decode(HandBuiltPng(HandFiltered, 3, 5));
            Assert.That(png.Width, Is.EqualTo(3));
            Assert.That(png.Height, Is.EqualTo(5));
            Assert.That(png.RowFilters, Is.EqualTo(new[] { 0, 1, 2, 3, 4 }));
            Assert.That(png.Pixels, Is.EqualTo(HandPixels));
        }

        [Test]
        public void RejectsACorruptedCrc()
        {
            var file = HandBuiltPng(HandFiltered, 3, 5);
            file[8 + 8 + 13] ^= 1; // first byte of IHDR's CRC
            Assert.Throws<FormatException>(() => ReferencePngDecoder.Decode(file));
        }

        [Test]
        public void RejectsAWrongAdler()
        {
            var file = HandBuiltPng(HandFiltered, 3, 5, corruptAdler: true);
            Assert.Throws<FormatException>(() => ReferencePngDecoder.Decode(file));
        }

        /// <summary>
        /// A gray 8-bit PNG assembled byte by byte: zlib header 78 01, one stored DEFLATE block (RFC 1951 §3.2.4:
        /// BFINAL=1, BTYPE=00, LEN, NLEN little-endian, raw bytes), Adler-32, chunk CRCs.
        /// </summary>
        internal static byte[] HandBuiltPng(byte[] filteredRows, int width, int height, bool corruptAdler = false)
        {
            var zlib = new List<byte> { 0x78, 0x01, 0x01 };
            int n = filteredRows.Length;
            zlib.AddRange(new[] { (byte)n, (byte)(n >> 8), (byte)~n, (byte)(~n >> 8) });
            zlib.AddRange(filteredRows);
            uint adler = ReferencePngDecoder.SimpleAdler32(filteredRows) ^ (corruptAdler ? 1u : 0u);
            zlib.AddRange(BigEndian(adler));

            var file = new List<byte> { 0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A };
            var ihdr = new List<byte>();
            ihdr.AddRange(BigEndian((uint)width));
            ihdr.AddRange(BigEndian((uint)height));
            ihdr.AddRange(new byte[] { 8, 0, 0, 0, 0 });
            AddChunk(file, "IHDR", ihdr.ToArray());
            AddChunk(file, "IDAT", zlib.ToArray());
            AddChunk(file, "IEND", new byte[0]);
            return file.ToArray();
        }

        static void AddChunk(List<byte> file, string type, byte[] data)
        {
            var typed = new List<byte>();
            foreach (char ch in type) typed.Add((byte)ch);
            typed.AddRange(data);
            var bytes = typed.ToArray();
            file.AddRange(BigEndian((uint)data.Length));
            file.AddRange(bytes);
            file.AddRange(BigEndian(ReferencePngDecoder.BitwiseCrc32(bytes, 0, bytes.Length)));
        }

        static byte[] BigEndian(uint v) => new[] { (byte)(v >> 24), (byte)(v >> 16), (byte)(v >> 8), (byte)v };
    }
}
