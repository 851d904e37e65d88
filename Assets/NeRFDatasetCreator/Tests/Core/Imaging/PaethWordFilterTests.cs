using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// PNG's Paeth filter computed on 64-bit words (eight bytes at once, no branch per byte) by the Huffman encoder,
    /// both when asked for by name and when the adaptive choice picks it: every file is decoded by
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
            foreach (var content in new[] { "noise", "gradient", "render", "stripes", "flat", "zeros" })
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

        [TestCase(PngPixelFormat.Gray8)]
        [TestCase(PngPixelFormat.Rgb8)]
        [TestCase(PngPixelFormat.Rgba8)]
        [TestCase(PngPixelFormat.Gray16)]
        public void AdaptiveChoosesPaethWhereOnlyPaethPredictsMostBytes(PngPixelFormat format)
        {
            // Left half: vertical stripes (each column one random value), which Up and Paeth (c = a, so b) predict
            // exactly and Sub does not. Right half: random values in horizontal pairs of pixels, which Paeth predicts
            // exactly on every second pixel (b = c, so a), Sub as well and Up never. Only Paeth leaves nothing to
            // code on the left and about half on the right, so the adaptive choice must take it on most rows.
            const int width = 96, height = 40;
            int bpp = PngWriter.BytesPerPixel(format);
            var random = new SeededRandom(21);
            var columns = new byte[width / 2 * bpp];
            for (int i = 0; i < columns.Length; i++) columns[i] = (byte)random.NextUInt64();
            var pixels = new byte[width * height * bpp];
            for (int y = 0; y < height; y++)
            {
                for (int i = 0; i < width / 2 * bpp; i++) pixels[y * width * bpp + i] = columns[i];
                for (int x = width / 2; x < width; x += 2)
                for (int k = 0; k < bpp; k++)
                {
                    byte value = (byte)random.NextUInt64();
                    pixels[(y * width + x) * bpp + k] = value;
                    pixels[(y * width + x + 1) * bpp + k] = value;
                }
                // With four bytes a pixel, Up's residuals of a pair would repeat a whole pixel (a nearly free match):
                // a fresh last byte in every second pixel keeps Up from that, and Paeth still predicts the other three.
                if (bpp == 4)
                    for (int x = width / 2 + 1; x < width; x += 2) pixels[(y * width + x) * bpp + 3] = (byte)random.NextUInt64();
            }
            var png = ReferencePngDecoder.Decode(PngWriter.Encode(pixels, width, height, format));
            Assert.That(png.Pixels, Is.EqualTo(pixels));
            int paethRows = 0;
            foreach (int filter in png.RowFilters) if (filter == 4) paethRows++;
            Assert.That(paethRows, Is.GreaterThanOrEqualTo(height * 3 / 4), "rows filtered with Paeth: " + string.Join(",", png.RowFilters));
        }

        [Test]
        public void AdaptiveDecidesEveryOtherRowAndAfterEveryNoneRow()
        {
            // Rows are estimated in pairs: an odd row takes the type of the row above unless that was None, which
            // may be the background above an object; the file must decode either way.
            var pixels = PngWriterTests.RenderLike(120, 90, 4, seed: 17);
            var png = ReferencePngDecoder.Decode(PngWriter.Encode(pixels, 120, 90, PngPixelFormat.Rgba8));
            Assert.That(png.Pixels, Is.EqualTo(pixels));
            Assert.That(new HashSet<int>(png.RowFilters).Count, Is.GreaterThan(2), "the render needs more than one filter besides None");
            for (int y = 1; y < png.Height; y += 2)
                if (png.RowFilters[y - 1] != 0)
                    Assert.That(png.RowFilters[y], Is.EqualTo(png.RowFilters[y - 1]), "row " + y);

            // Empty even rows (None) and horizontal ramps on odd rows: each odd row is estimated afresh, and a ramp
            // is all one Sub residual.
            var ramps = new byte[64 * 12 * 4];
            for (int y = 1; y < 12; y += 2)
                for (int i = 0; i < 64 * 4; i++) ramps[y * 64 * 4 + i] = (byte)(10 + y + 3 * (i / 4));
            var rampPng = ReferencePngDecoder.Decode(PngWriter.Encode(ramps, 64, 12, PngPixelFormat.Rgba8));
            Assert.That(rampPng.Pixels, Is.EqualTo(ramps));
            for (int y = 0; y < 12; y++) Assert.That(rampPng.RowFilters[y], Is.EqualTo(y % 2 == 0 ? 0 : 1), "row " + y);
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
