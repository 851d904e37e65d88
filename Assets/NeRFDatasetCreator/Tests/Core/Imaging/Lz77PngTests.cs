using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The greedy LZ77 encoder (<see cref="PngCompression.Lz77"/>): every file is decoded by
    /// <see cref="ReferencePngDecoder"/> and must match bit for bit — the Huffman tests' shapes and contents, and
    /// one-row gray images whose zlib payload (a 0 type byte, then the pixels) is laid out to hit each edge of
    /// RFC 1951: a match exactly 32 768 bytes back and one a byte too far, 258-byte matches, overlapping matches,
    /// many blocks mixing stored and Huffman-coded ones, streams shorter than a match.
    /// </summary>
    public class Lz77PngTests
    {
        static readonly int[][] Shapes =
        {
            new[] { 1, 1 }, new[] { 2, 1 }, new[] { 3, 1 }, new[] { 1, 7 }, new[] { 7, 5 }, new[] { 33, 17 },
            new[] { 101, 3 }, new[] { 8192, 1 }, new[] { 1, 300 }, new[] { 64, 64 }, new[] { 17000, 2 }, new[] { 300, 300 },
        };

        static IEnumerable<TestCaseData> Cases()
        {
            foreach (PngPixelFormat format in Enum.GetValues(typeof(PngPixelFormat)))
            foreach (var content in new[] { "zeros", "noise", "gradient", "render", "flat", "stripes" })
            foreach (var shape in Shapes)
                yield return new TestCaseData(format, content, shape[0], shape[1]);
        }

        [TestCaseSource(nameof(Cases))]
        public void DecodesBitExactly(PngPixelFormat format, string content, int width, int height)
        {
            var pixels = HuffmanPngTests.Make(content, width, height, PngWriter.BytesPerPixel(format), seed: width * 5 + height);
            var png = ReferencePngDecoder.Decode(PngWriter.Encode(pixels, width, height, format, PngCompression.Lz77));
            Assert.That(png.Width, Is.EqualTo(width));
            Assert.That(png.Height, Is.EqualTo(height));
            Assert.That(png.Pixels, Is.EqualTo(pixels));
        }

        [TestCase(PngFilter.None)]
        [TestCase(PngFilter.Up)]
        [TestCase(PngFilter.Paeth)]
        public void Gray16DepthDecodesBitExactly(PngFilter filter)
        {
            const int width = 97, height = 61;
            var samples = new ushort[width * height];
            for (int i = 0; i < samples.Length; i++)
                samples[i] = i % 13 == 0 ? (ushort)0 : (ushort)(3000 + (i % width) * 21 + (i / width) * 7);
            var png = ReferencePngDecoder.Decode(PngWriter.EncodeGray16(samples, width, height, PngCompression.Lz77, filter));
            for (int i = 0; i < samples.Length; i++)
                Assert.That(png.Pixels[2 * i] << 8 | png.Pixels[2 * i + 1], Is.EqualTo(samples[i]), "sample " + i);
        }

        [Test]
        public void AMatchReachesExactly32768BytesBackAndNoFurther()
        {
            // A 300-byte block of noise repeated 32 768 bytes later is sent as matches (the file is over 200 bytes smaller
            // than with the block unrepeated); repeated 32 769 bytes later it is out of reach and sent as literals.
            byte[] inReach = Noise(70000, 1), outOfReach = Noise(70000, 1), unrepeated = Noise(70000, 1);
            Array.Copy(inReach, 1000, inReach, 1000 + 32768, 300);
            Array.Copy(outOfReach, 1000, outOfReach, 1000 + 32769, 300);
            int inSize = EncodeRow(inReach).Length, outSize = EncodeRow(outOfReach).Length, noneSize = EncodeRow(unrepeated).Length;
            Assert.That(noneSize - inSize, Is.GreaterThan(200));
            Assert.That(outSize, Is.EqualTo(noneSize).Within(2));
        }

        [Test]
        public void RunsBecome258ByteMatchesAcrossBlocks()
        {
            // 200 000 zeros: one literal, then overlapping distance-1 matches of 258 bytes, about 775 of them.
            var file = EncodeRow(new byte[200000]);
            Assert.That(file.Length, Is.LessThan(400));
        }

        [Test]
        public void OverlappingMatchesRepeatAShortPattern()
        {
            // "abc" 4000 times: matches at distance 3 longer than their distance (the decoder copies byte by byte).
            var pixels = new byte[12000];
            for (int i = 0; i < pixels.Length; i++) pixels[i] = (byte)("abc"[i % 3]);
            var file = EncodeRow(pixels);
            Assert.That(file.Length, Is.LessThan(300));
        }

        [Test]
        public void StoredAndHuffmanBlocksMix()
        {
            // Noise (stored blocks: Huffman cannot beat 8 bits a byte), a smooth ramp, noise again: more than
            // BlockSymbols symbols in each part, so block boundaries fall inside runs and between kinds of block.
            var pixels = Noise(250000, 7);
            for (int i = 80000; i < 170000; i++) pixels[i] = (byte)((i / 97) & 0x3F);
            EncodeRow(pixels);
        }

        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        [TestCase(5)]
        public void StreamsShorterThanAMatchAreLiterals(int width)
        {
            var pixels = new byte[width];
            for (int i = 0; i < width; i++) pixels[i] = (byte)(200 + i);
            EncodeRow(pixels);
        }

        [Test]
        public void TheZlibHeaderSaysFast()
        {
            var file = PngWriter.Encode(new byte[16], 4, 4, PngPixelFormat.Gray8, PngCompression.Lz77);
            var png = ReferencePngDecoder.Decode(file);
            Assert.That(png.ZlibCmf, Is.EqualTo(0x78));
            Assert.That(png.ZlibFlg >> 6, Is.EqualTo(1), "FLEVEL 1: fast");
        }

        /// <summary>One 8-bit gray row, filter None: the zlib payload is a 0 byte and the pixels. Checks the round trip.</summary>
        static byte[] EncodeRow(byte[] pixels)
        {
            var file = PngWriter.Encode(pixels, pixels.Length, 1, PngPixelFormat.Gray8, PngCompression.Lz77, PngFilter.None);
            Assert.That(ReferencePngDecoder.Decode(file).Pixels, Is.EqualTo(pixels));
            return file;
        }

        static byte[] Noise(int length, int seed)
        {
            var random = new SeededRandom(seed);
            var bytes = new byte[length];
            for (int i = 0; i < length; i++) bytes[i] = (byte)random.NextUInt64();
            return bytes;
        }
    }
}
