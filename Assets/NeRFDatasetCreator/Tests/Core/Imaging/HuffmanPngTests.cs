using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The Huffman-only encoder (<see cref="PngCompression.Huffman"/>, the default): every file is decoded by
    /// <see cref="ReferencePngDecoder"/> and must match bit for bit, over shapes chosen to hit each path — one pixel,
    /// odd widths, all zeros (one long run), noise (the stored fallback), gradients, runs longer than a match and
    /// rows longer than a stored block. Sizes are compared with DeflateStream's level 6, the previous default.
    /// </summary>
    public class HuffmanPngTests
    {
        static readonly int[][] Shapes =
        {
            new[] { 1, 1 }, new[] { 2, 1 }, new[] { 1, 7 }, new[] { 3, 3 }, new[] { 7, 5 }, new[] { 33, 17 },
            new[] { 101, 3 }, new[] { 8192, 1 }, new[] { 1, 300 }, new[] { 64, 64 }, new[] { 17000, 2 },
        };

        static readonly string[] Contents = { "zeros", "noise", "gradient", "render", "flat", "stripes" };

        static IEnumerable<TestCaseData> Cases()
        {
            foreach (PngPixelFormat format in Enum.GetValues(typeof(PngPixelFormat)))
            foreach (var content in Contents)
            foreach (var shape in Shapes)
                yield return new TestCaseData(format, content, shape[0], shape[1]);
        }

        [TestCaseSource(nameof(Cases))]
        public void DecodesBitExactly(PngPixelFormat format, string content, int width, int height)
        {
            var pixels = Make(content, width, height, PngWriter.BytesPerPixel(format), seed: width * 7 + height);
            var file = PngWriter.Encode(pixels, width, height, format);
            var png = ReferencePngDecoder.Decode(file);

            Assert.That(png.Width, Is.EqualTo(width));
            Assert.That(png.Height, Is.EqualTo(height));
            Assert.That(png.BitDepth, Is.EqualTo(format == PngPixelFormat.Gray16 ? 16 : 8));
            Assert.That(png.ChunkTypes, Is.EqualTo(new[] { "IHDR", "IDAT", "IEND" }));
            Assert.That(png.Pixels, Is.EqualTo(pixels));
        }

        [TestCaseSource(nameof(FixedFilters))]
        public void EveryFixedFilterDecodesBitExactly(PngFilter filter)
        {
            var pixels = Make("render", 45, 31, 4, seed: 2);
            var png = ReferencePngDecoder.Decode(PngWriter.Encode(pixels, 45, 31, PngPixelFormat.Rgba8, PngCompression.Huffman, filter));
            Assert.That(png.Pixels, Is.EqualTo(pixels));
            Assert.That(png.RowFilters, Has.All.EqualTo((int)filter));
        }

        static IEnumerable<PngFilter> FixedFilters() => new[] { PngFilter.None, PngFilter.Sub, PngFilter.Up, PngFilter.Average, PngFilter.Paeth };

        [Test]
        public void Gray16FromUShortsDecodesBitExactly()
        {
            const int width = 61, height = 29;
            var random = new SeededRandom(4);
            var samples = new ushort[width * height];
            for (int i = 0; i < samples.Length; i++)
                samples[i] = i % 9 == 0 ? (ushort)0 : (ushort)(2000 + (i % width) * 37 + (i / width) * 11 + (int)(random.NextUInt64() % 5));
            var png = ReferencePngDecoder.Decode(PngWriter.EncodeGray16(samples, width, height));
            for (int i = 0; i < samples.Length; i++)
            {
                Assert.That(png.Pixels[2 * i], Is.EqualTo((byte)(samples[i] >> 8)), "high byte of sample " + i);
                Assert.That(png.Pixels[2 * i + 1], Is.EqualTo((byte)samples[i]), "low byte of sample " + i);
            }
        }

        [Test]
        public void IncompressibleDataFallsBackToStoredBlocksOfAtMost65535Bytes()
        {
            // 300×300 noise: Huffman cannot beat 8 bits a byte, so the stream must be stored blocks: the file is the
            // raw bytes plus the filter bytes, 5 bytes per block and the fixed framing, and no more.
            const int width = 300, height = 300;
            var pixels = Make("noise", width, height, 4, seed: 9);
            var file = PngWriter.Encode(pixels, width, height, PngPixelFormat.Rgba8);
            int raw = (width * 4 + 1) * height;
            int blocks = (raw + 65534) / 65535;
            Assert.That(file.Length, Is.EqualTo(8 + 25 + 12 + 2 + raw + 5 * blocks + 4 + 12));
            Assert.That(ReferencePngDecoder.Decode(file).Pixels, Is.EqualTo(pixels));
        }

        [Test]
        public void AllZeroImageIsAFewHundredBytesAtMost()
        {
            // 1000×1000 RGBA zeros: one literal and runs of 258-byte matches, about 2 bits per 258 bytes.
            var file = PngWriter.Encode(new byte[1000 * 1000 * 4], 1000, 1000, PngPixelFormat.Rgba8);
            Assert.That(file.Length, Is.LessThan(4000));
            var png = ReferencePngDecoder.Decode(file);
            Assert.That(png.Pixels, Has.All.EqualTo((byte)0));
            Assert.That(png.RowFilters, Has.All.EqualTo(0), "an all-zero row gets None, so the run goes on across rows");
        }

        [TestCase(PngPixelFormat.Rgba8)]
        [TestCase(PngPixelFormat.Rgb8)]
        [TestCase(PngPixelFormat.Gray8)]
        [TestCase(PngPixelFormat.Gray16)]
        public void SmoothRenderLikeFilesAreNoLargerThanZlibLevel6(PngPixelFormat format)
        {
            // The previous default (DeflateStream's level 6, Sub filter) is the bar on a smooth, slightly noisy disc:
            // no larger by more than 2 %. (On grainy renders and smooth 16-bit depth level 6's LZ77 search wins by
            // 20 % and 2× respectively: README.md, section Performance.)
            var pixels = PngWriterTests.RenderLike(200, 160, PngWriter.BytesPerPixel(format), seed: 12);
            var huffman = PngWriter.Encode(pixels, 200, 160, format);
            var zlib6 = PngWriter.Encode(pixels, 200, 160, format, PngCompression.Optimal, PngFilter.Sub);
            Assert.That(huffman.Length, Is.LessThanOrEqualTo(zlib6.Length * 1.02));
            Assert.That(ReferencePngDecoder.Decode(huffman).Pixels, Is.EqualTo(pixels));
        }

        [Test]
        public void TheZlibHeaderSaysFastest()
        {
            var png = ReferencePngDecoder.Decode(PngWriter.Encode(Make("render", 20, 20, 3, seed: 1), 20, 20, PngPixelFormat.Rgb8));
            Assert.That(png.ZlibCmf, Is.EqualTo(0x78));
            Assert.That(png.ZlibFlg, Is.EqualTo(0x01));
        }

        [Test]
        public void HuffmanCodeLengthsAreCompleteAndWithinTheLimit()
        {
            // Fibonacci counts force the deepest possible optimal tree (depth n − 1); the limit must cut it to 7
            // and the lengths must still form a complete prefix code (Kraft sum exactly 1).
            var counts = new int[19];
            int a = 1, b = 1;
            for (int i = 0; i < counts.Length; i++)
            {
                counts[i] = a;
                int next = a + b;
                a = b;
                b = next;
            }
            var lengths = new byte[19];
            HuffmanCode.BuildLengths(counts, 19, 7, lengths);
            double kraft = 0;
            foreach (var length in lengths)
            {
                Assert.That(length, Is.InRange(1, 7));
                kraft += Math.Pow(2, -length);
            }
            Assert.That(kraft, Is.EqualTo(1.0).Within(1e-12));
        }

        [Test]
        public void CanonicalCodesAreTheRfc1951Example()
        {
            // RFC 1951 §3.2.2: lengths (3, 3, 3, 3, 3, 2, 4, 4) give codes 010 011 100 101 110 00 1110 1111,
            // stored here bit-reversed (sent least significant bit first).
            var lengths = new byte[] { 3, 3, 3, 3, 3, 2, 4, 4 };
            var codes = new int[8];
            HuffmanCode.BuildCodes(lengths, 8, codes);
            Assert.That(codes, Is.EqualTo(new[] { 0b010, 0b110, 0b001, 0b101, 0b011, 0b00, 0b0111, 0b1111 }));
        }

        /// <summary>Deterministic test images of the named kind, tightly packed, bytesPerPixel bytes per pixel.</summary>
        internal static byte[] Make(string content, int width, int height, int bytesPerPixel, int seed)
        {
            var pixels = new byte[width * height * bytesPerPixel];
            var random = new SeededRandom(seed);
            for (int y = 0; y < height; y++)
            for (int x = 0; x < width; x++)
            for (int c = 0; c < bytesPerPixel; c++)
            {
                int i = (y * width + x) * bytesPerPixel + c;
                switch (content)
                {
                    case "zeros": break;
                    case "noise": pixels[i] = (byte)random.NextUInt64(); break;
                    case "gradient": pixels[i] = (byte)(x * 3 + y * 5 + c * 40); break;
                    case "flat": pixels[i] = (byte)(90 + c); break;
                    case "stripes": pixels[i] = (byte)((x / 300 + y) % 2 == 0 ? 0 : 200 + c); break;
                    default: break;
                }
            }
            if (content == "render") return PngWriterTests.RenderLike(width, height, bytesPerPixel, seed);
            return pixels;
        }
    }
}
