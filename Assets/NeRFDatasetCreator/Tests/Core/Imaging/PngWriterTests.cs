using System;
using System.Collections.Generic;
using System.Threading;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Every writer variant is decoded by <see cref="ReferencePngDecoder"/> and must match bit for bit.</summary>
    public class PngWriterTests
    {
        static readonly int[][] Sizes =
        {
            new[] { 1, 1 }, new[] { 7, 5 }, new[] { 33, 17 }, new[] { 8192, 1 }, new[] { 1, 9 }, new[] { 64, 64 },
        };

        static IEnumerable<TestCaseData> Variants()
        {
            foreach (PngPixelFormat format in Enum.GetValues(typeof(PngPixelFormat)))
            foreach (PngFilter filter in Enum.GetValues(typeof(PngFilter)))
            foreach (var size in Sizes)
                yield return new TestCaseData(format, filter, size[0], size[1]);
        }

        [TestCaseSource(nameof(Variants))]
        public void DecodesBitExactly(PngPixelFormat format, PngFilter filter, int width, int height)
        {
            var pixels = RenderLike(width, height, PngWriter.BytesPerPixel(format), seed: width * 31 + height);
            var png = ReferencePngDecoder.Decode(PngWriter.Encode(pixels, width, height, format, PngCompression.Optimal, filter));

            Assert.That(png.Width, Is.EqualTo(width));
            Assert.That(png.Height, Is.EqualTo(height));
            Assert.That(png.BitDepth, Is.EqualTo(format == PngPixelFormat.Gray16 ? 16 : 8));
            Assert.That(png.ColorType, Is.EqualTo(format == PngPixelFormat.Rgb8 ? 2 : format == PngPixelFormat.Rgba8 ? 6 : 0));
            Assert.That(png.ChunkTypes, Is.EqualTo(new[] { "IHDR", "IDAT", "IEND" }));
            Assert.That(png.Pixels, Is.EqualTo(pixels));
            if (filter != PngFilter.Adaptive)
                Assert.That(png.RowFilters, Has.All.EqualTo((int)filter));
        }

        [TestCase(PngCompression.Fastest, 0x01)]
        [TestCase(PngCompression.Optimal, 0x9C)]
        [TestCase(PngCompression.None, 0x01)]
        public void ZlibHeaderNamesTheLevelAndEveryCompressionDecodes(PngCompression compression, int expectedFlags)
        {
            var pixels = RenderLike(50, 40, 4, seed: 3);
            var png = ReferencePngDecoder.Decode(PngWriter.Encode(pixels, 50, 40, PngPixelFormat.Rgba8, compression));
            Assert.That(png.ZlibCmf, Is.EqualTo(0x78));
            Assert.That(png.ZlibFlg, Is.EqualTo(expectedFlags));
            Assert.That(png.Pixels, Is.EqualTo(pixels));
        }

        [Test]
        public void Gray16SamplesAreStoredBigEndian()
        {
            // 0x1234 must appear as 12 34; 65535 and 0 at the ends of the range; 300 crosses a byte boundary.
            var samples = new ushort[] { 0x1234, 65535, 0, 300, 1 };
            var png = ReferencePngDecoder.Decode(PngWriter.EncodeGray16(samples, 5, 1));
            Assert.That(png.BitDepth, Is.EqualTo(16));
            Assert.That(png.Pixels, Is.EqualTo(new byte[] { 0x12, 0x34, 0xFF, 0xFF, 0, 0, 0x01, 0x2C, 0, 1 }));
        }

        [TestCaseSource(nameof(Filters))]
        public void Gray16FromUShortsDecodesBitExactlyWithEveryFilter(PngFilter filter)
        {
            const int width = 37, height = 23;
            var random = new SeededRandom(11);
            var samples = new ushort[width * height];
            for (int i = 0; i < samples.Length; i++) samples[i] = i % 5 == 0 ? (ushort)0 : (ushort)(1500 + (i % width) * 40 + (int)(random.NextUInt64() % 7));
            var png = ReferencePngDecoder.Decode(PngWriter.EncodeGray16(samples, width, height, PngCompression.Fastest, filter));
            var expected = new byte[samples.Length * 2];
            for (int i = 0; i < samples.Length; i++)
            {
                expected[2 * i] = (byte)(samples[i] >> 8);
                expected[2 * i + 1] = (byte)samples[i];
            }
            Assert.That(png.Pixels, Is.EqualTo(expected));
        }

        static IEnumerable<PngFilter> Filters() => (PngFilter[])Enum.GetValues(typeof(PngFilter));

        [Test]
        public void AdaptiveUsesMoreThanOneFilterOnARenderLikeImage()
        {
            // A transparent border (None/Sub/Up all give zeros) around a shaded disc (where Paeth/Sub win): the
            // heuristic must actually choose per row, not return one type everywhere.
            var pixels = RenderLike(96, 96, 4, seed: 5);
            var png = ReferencePngDecoder.Decode(PngWriter.Encode(pixels, 96, 96, PngPixelFormat.Rgba8, PngCompression.Fastest, PngFilter.Adaptive));
            var used = new HashSet<int>(png.RowFilters);
            Assert.That(used.Count, Is.GreaterThan(1));
        }

        [Test]
        public void ConcurrentEncodesGiveTheSameBytesAsSequentialOnes()
        {
            const int jobs = 8;
            var inputs = new byte[jobs][];
            var sequential = new byte[jobs][];
            for (int j = 0; j < jobs; j++)
            {
                // Different sizes per job so a shared scratch buffer would corrupt some output.
                inputs[j] = RenderLike(40 + j * 13, 30 + j * 7, 4, seed: j);
                sequential[j] = PngWriter.Encode(inputs[j], 40 + j * 13, 30 + j * 7, PngPixelFormat.Rgba8);
            }
            var parallel = new byte[jobs][];
            var threads = new Thread[jobs];
            for (int j = 0; j < jobs; j++)
            {
                int job = j;
                threads[j] = new Thread(() =>
                {
                    for (int repeat = 0; repeat < 20; repeat++)
                        parallel[job] = PngWriter.Encode(inputs[job], 40 + job * 13, 30 + job * 7, PngPixelFormat.Rgba8);
                });
                threads[j].Start();
            }
            foreach (var t in threads) t.Join();
            for (int j = 0; j < jobs; j++) Assert.That(parallel[j], Is.EqualTo(sequential[j]), "job " + j);
        }

        [Test]
        public void RejectsAMismatchedBufferNamingTheField()
        {
            var e = Assert.Throws<InvalidParameterException>(() => PngWriter.Encode(new byte[10], 2, 2, PngPixelFormat.Rgb8));
            Assert.That(e.Message, Does.Contain("pixels").And.Contain("12"));
            Assert.Throws<InvalidParameterException>(() => PngWriter.Encode(new byte[0], 0, 1, PngPixelFormat.Gray8));
            Assert.Throws<InvalidParameterException>(() => PngWriter.EncodeGray16(null, 1, 1));
        }

        /// <summary>
        /// Bytes that look like a render: a zero (transparent) border and a smoothly shaded disc with a little noise,
        /// so every filter type has something to do. Deterministic per seed.
        /// </summary>
        internal static byte[] RenderLike(int width, int height, int bytesPerPixel, int seed)
        {
            var random = new SeededRandom(seed);
            var pixels = new byte[width * height * bytesPerPixel];
            double cx = width / 2.0, cy = height / 2.0, radius = Math.Max(1, Math.Min(width, height) * 0.4);
            for (int y = 0; y < height; y++)
            for (int x = 0; x < width; x++)
            {
                double dx = (x + 0.5 - cx) / radius, dy = (y + 0.5 - cy) / radius;
                bool inside = dx * dx + dy * dy < 1 || width * height < 4;
                for (int c = 0; c < bytesPerPixel; c++)
                {
                    int v = inside ? (int)(128 + 100 * dx * (c + 1) / bytesPerPixel - 60 * dy) + (int)(random.NextUInt64() % 5) : 0;
                    pixels[(y * width + x) * bytesPerPixel + c] = (byte)Math.Max(0, Math.Min(255, v));
                }
            }
            return pixels;
        }
    }
}
