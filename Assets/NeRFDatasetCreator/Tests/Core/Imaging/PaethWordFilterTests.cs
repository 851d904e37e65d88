using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// PNG's Paeth filter computed on 64-bit words (eight bytes at once, no branch) by the Huffman encoder, both when
    /// asked for by name and when the adaptive choice picks it: every file is decoded by
    /// <see cref="ReferencePngDecoder"/>, whose own byte-wise Paeth predictor (PNG spec §9.4) unfilters it, and must
    /// give the input back bit for bit — for every (left, above, above-left) byte triple, every pixel size, rows whose
    /// length is not a multiple of 8 bytes, a single pixel and a first row (where the row above is zeros).
    /// </summary>
    public class PaethWordFilterTests
    {
        [Test]
        public void EveryTripleOfLeftAboveAndAboveLeftBytesDecodesExactly()
        {
            // Gray 8, so each residual's neighbours are the bytes just left, above and above-left. Each row is
            // u(i) + v(y) (mod 256): u is a de Bruijn sequence (every ordered pair of bytes is (u(i − 1), u(i)) for some
            // i), and v(y) = y(y + 1)/2 steps by y. At (y, i) with c = u(i − 1) + v(y − 1) the byte above is c + Δu and
            // the byte to the left c − y: over 257 rows every (a − c, b − c, c) occurs, so every (a, b, c) does.
            var u = DeBruijnPairs();
            int width = u.Length, height = 257;
            var pixels = new byte[width * height];
            for (int y = 0; y < height; y++)
            {
                int v = y * (y + 1) / 2;
                for (int i = 0; i < width; i++) pixels[y * width + i] = (byte)(u[i] + v);
            }
            var png = ReferencePngDecoder.Decode(PngWriter.Encode(pixels, width, height, PngPixelFormat.Gray8, PngCompression.Huffman, PngFilter.Paeth));
            Assert.That(png.RowFilters, Has.All.EqualTo(4));
            AssertSameBytes(png.Pixels, pixels);
        }

        /// <summary>256² + 1 bytes in which every ordered pair of byte values appears as neighbours (Lyndon words of length 1 and 2 in order).</summary>
        static byte[] DeBruijnPairs()
        {
            var sequence = new List<byte>(65537);
            for (int first = 0; first < 256; first++)
            {
                sequence.Add((byte)first);
                for (int second = first + 1; second < 256; second++)
                {
                    sequence.Add((byte)first);
                    sequence.Add((byte)second);
                }
            }
            sequence.Add(0); // the cycle closed: (255, 0) and, with the start, (0, 0)
            var pairs = new HashSet<int>();
            for (int i = 1; i < sequence.Count; i++) pairs.Add(sequence[i - 1] << 8 | sequence[i]);
            Assert.That(pairs.Count, Is.EqualTo(65536), "the test's own sequence must hold every pair");
            return sequence.ToArray();
        }

        static readonly int[][] Shapes =
        {
            new[] { 1, 1 }, new[] { 2, 1 }, new[] { 1, 7 }, new[] { 3, 3 }, new[] { 7, 5 }, new[] { 9, 4 },
            new[] { 33, 17 }, new[] { 101, 3 }, new[] { 1, 300 }, new[] { 64, 64 }, new[] { 257, 9 },
        };

        static IEnumerable<TestCaseData> Cases()
        {
            foreach (PngPixelFormat format in Enum.GetValues(typeof(PngPixelFormat)))
            foreach (var content in new[] { "noise", "gradient", "render", "stripes" })
            foreach (var shape in Shapes)
                yield return new TestCaseData(format, content, shape[0], shape[1]);
        }

        [TestCaseSource(nameof(Cases))]
        public void PaethByNameDecodesBitExactly(PngPixelFormat format, string content, int width, int height)
        {
            var pixels = HuffmanPngTests.Make(content, width, height, PngWriter.BytesPerPixel(format), seed: width * 5 + height);
            var png = ReferencePngDecoder.Decode(PngWriter.Encode(pixels, width, height, format, PngCompression.Huffman, PngFilter.Paeth));
            Assert.That(png.RowFilters, Has.All.EqualTo(4));
            Assert.That(png.Pixels, Is.EqualTo(pixels));
        }

        [Test]
        public void Gray16FromUShortsWithPaethDecodesBitExactly()
        {
            // Samples whose high and low bytes both vary, read as little-endian ushorts and swapped in words.
            const int width = 43, height = 19;
            var random = new SeededRandom(8);
            var samples = new ushort[width * height];
            for (int i = 0; i < samples.Length; i++) samples[i] = (ushort)(i * 613 + (int)(random.NextUInt64() % 300));
            var png = ReferencePngDecoder.Decode(PngWriter.EncodeGray16(samples, width, height, PngCompression.Huffman, PngFilter.Paeth));
            var expected = new byte[samples.Length * 2];
            for (int i = 0; i < samples.Length; i++)
            {
                expected[2 * i] = (byte)(samples[i] >> 8);
                expected[2 * i + 1] = (byte)samples[i];
            }
            Assert.That(png.Pixels, Is.EqualTo(expected));
        }

        static void AssertSameBytes(byte[] actual, byte[] expected)
        {
            Assert.That(actual.Length, Is.EqualTo(expected.Length));
            for (int i = 0; i < expected.Length; i++)
                if (actual[i] != expected[i])
                    Assert.Fail($"byte {i} is {actual[i]}, expected {expected[i]}");
        }
    }
}
