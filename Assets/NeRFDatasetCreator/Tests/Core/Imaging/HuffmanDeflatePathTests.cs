using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The paths inside <see cref="PngCompression.Huffman"/>'s encoder that whole-image tests reach only by chance:
    /// runs of bytes equal to the byte a pixel earlier at every length around the 4-byte threshold and every offset
    /// in a 64-bit word, runs going on through a row's type byte, runs cut at the 258-byte match limit, the sampled
    /// counting of large images (a byte the sample never saw must still have a code), literal codes cut to the
    /// 15-bit limit, and noise large enough to be sampled. Every file is decoded by <see cref="ReferencePngDecoder"/>
    /// (its own CRC and Adler-32; System.IO.Compression inflates) and must give the input back bit for bit; the
    /// block header is read back here with a bit reader written from RFC 1951 §3.2.7.
    /// </summary>
    public class HuffmanDeflatePathTests
    {
        static byte[] RoundTrip(byte[] pixels, int width, int height, PngPixelFormat format, PngFilter filter = PngFilter.Adaptive)
        {
            var file = PngWriter.Encode(pixels, width, height, format, PngCompression.Huffman, filter);
            var png = ReferencePngDecoder.Decode(file);
            Assert.That(png.Pixels, Is.EqualTo(pixels));
            return file;
        }

        /// <summary>Bytes that never equal the byte <paramref name="bytesPerPixel"/> earlier (so no run by chance).</summary>
        static byte[] NoRuns(int count, int bytesPerPixel, int seed)
        {
            var random = new SeededRandom(seed);
            var bytes = new byte[count];
            for (int i = 0; i < count; i++)
            {
                byte value;
                do value = (byte)random.NextUInt64(); while (i >= bytesPerPixel && value == bytes[i - bytesPerPixel]);
                bytes[i] = value;
            }
            return bytes;
        }

        static IEnumerable<TestCaseData> RunCases()
        {
            foreach (int bytesPerPixel in new[] { 1, 2, 3, 4 })
            foreach (int length in new[] { 1, 2, 3, 4, 5, 7, 8, 9, 15, 16, 17 })
                yield return new TestCaseData(bytesPerPixel, length);
        }

        [TestCaseSource(nameof(RunCases))]
        public void RunsOfEveryLengthAtEveryOffsetOfAWord(int bytesPerPixel, int length)
        {
            // One row per start offset 0…23 (three words): the row's bytes never repeat the byte a pixel earlier,
            // except `length` bytes from the offset, which do. Filter None, so the payload is exactly these bytes.
            var format = FormatOf(bytesPerPixel);
            int width = 64 / bytesPerPixel + 4, rowBytes = width * bytesPerPixel, height = 24;
            var pixels = NoRuns(rowBytes * height, bytesPerPixel, seed: 100 * bytesPerPixel + length);
            for (int y = 0; y < height; y++)
            {
                // Stream offset of row byte k is y·(rowBytes + 1) + 1 + k; start the run so that it begins y bytes
                // into a 64-bit word of the payload.
                int rowStart = y * (rowBytes + 1) + 1;
                int first = ((y - rowStart) % 8 + 8) % 8 + bytesPerPixel;
                if (first + length > rowBytes) continue;
                for (int k = first; k < first + length; k++) pixels[y * rowBytes + k] = pixels[y * rowBytes + k - bytesPerPixel];
            }
            RoundTrip(pixels, width, height, format, PngFilter.None);
        }

        [Test]
        public void ARunGoesOnThroughTheTypeBytesOfAllZeroRows()
        {
            // Rows of zeros with filter None (type byte 0): one run over the whole payload, a few hundred bytes.
            var pixels = new byte[300 * 200 * 3];
            for (int i = 0; i < 300 * 3; i++) pixels[100 * 300 * 3 + i] = (byte)(i * 7); // one busy row in the middle
            var file = RoundTrip(pixels, 300, 200, PngPixelFormat.Rgb8, PngFilter.None);
            Assert.That(file.Length, Is.LessThan(300 * 3 + 1000), "the zero rows cost a few bits per 258 bytes");
        }

        [TestCase(3)]
        [TestCase(4)]
        [TestCase(257)]
        [TestCase(258)]
        [TestCase(259)]
        [TestCase(260)]
        [TestCase(261)]
        [TestCase(262)]
        [TestCase(516)]
        [TestCase(517)]
        [TestCase(518)]
        [TestCase(519)]
        [TestCase(774)]
        public void RunsAroundTheMaximumMatchLengthAreCutIntoValidMatches(int repeats)
        {
            // A one-row gray image of a constant non-zero value: its first byte follows the type byte 0, the next
            // `repeats` bytes each equal the one before. A second row of noise follows.
            int width = repeats + 1;
            var pixels = new byte[width * 2];
            for (int x = 0; x < width; x++) pixels[x] = 77;
            Array.Copy(NoRuns(width, 1, seed: repeats), 0, pixels, width, width);
            RoundTrip(pixels, width, 2, PngPixelFormat.Gray8, PngFilter.None);
        }

        [Test]
        public void ALargeImageCodesBytesItsSampleNeverSaw()
        {
            // 640×400 gray (256 000 bytes): the codes come from a sample. Bytes 0…99 fill the image; every other
            // value appears once, each in a payload word the sample skips (it counts 64 words in every 512).
            const int width = 640, height = 400;
            var random = new SeededRandom(5);
            var pixels = new byte[width * height];
            for (int i = 0; i < pixels.Length; i++) pixels[i] = (byte)(random.NextUInt64() % 100);
            int rare = 100;
            for (int word = 100; rare < 256; word += word % 512 == 300 ? 312 : 100) // words 100, 200, 300 of each 512
            {
                // Payload byte s is row s / (width + 1), column s % (width + 1) − 1 (−1: the row's type byte).
                int s = word * 8 + 3;
                if (s % (width + 1) == 0) s++;
                pixels[s / (width + 1) * width + s % (width + 1) - 1] = (byte)rare++;
            }
            var file = RoundTrip(pixels, width, height, PngPixelFormat.Gray8, PngFilter.None);
            Assert.That(file.Length, Is.LessThan(width * height * 7 / 8), "Huffman-coded, not stored");
            RoundTrip(pixels, width, height, PngPixelFormat.Gray8);
        }

        [Test]
        public void LiteralCodesAreCutToFifteenBits()
        {
            // Byte value i appears Fibonacci(i) times (i = 0…21): an optimal code would be 21 bits deep. Placed so
            // at random, filter None, small enough to be counted whole.
            var counts = new int[22];
            counts[0] = counts[1] = 1;
            for (int i = 2; i < counts.Length; i++) counts[i] = counts[i - 1] + counts[i - 2];
            var values = new List<byte>();
            for (int v = 0; v < counts.Length; v++)
                for (int c = 0; c < counts[v]; c++) values.Add((byte)v);
            // Shuffled: the few runs this leaves change the counts a little, not the depth the limit must cut.
            var bytes = new byte[values.Count];
            var random = new SeededRandom(8);
            for (int i = bytes.Length - 1; i > 0; i--)
            {
                int j = (int)(random.NextUInt64() % (ulong)(i + 1));
                var swap = values[i];
                values[i] = values[j];
                values[j] = swap;
            }
            for (int i = 0; i < bytes.Length; i++) bytes[i] = values[i];
            int width = bytes.Length, height = 1; // 46 367 bytes: below the sampling size
            var file = RoundTrip(bytes, width, height, PngPixelFormat.Gray8, PngFilter.None);

            var lengths = LiteralLengthCodeLengths(file);
            int longest = 0;
            double kraft = 0;
            foreach (var length in lengths)
            {
                longest = Math.Max(longest, length);
                if (length > 0) kraft += Math.Pow(2, -length);
            }
            Assert.That(longest, Is.EqualTo(15), "the deepest literal sits at the 15-bit limit");
            Assert.That(kraft, Is.EqualTo(1.0).Within(1e-12), "the cut code is still complete");
        }

        [Test]
        public void LargeNoiseFallsBackToStoredBlocks()
        {
            // 400×400 RGBA noise (640 KB, sampled): stored blocks, exactly the payload plus 5 bytes a block.
            const int width = 400, height = 400;
            var pixels = HuffmanPngTests.Make("noise", width, height, 4, seed: 21);
            var file = RoundTrip(pixels, width, height, PngPixelFormat.Rgba8);
            int raw = (width * 4 + 1) * height;
            Assert.That(file.Length, Is.EqualTo(8 + 25 + 12 + 2 + raw + 5 * ((raw + 65534) / 65535) + 4 + 12));
        }

        [TestCase(PngPixelFormat.Gray8)]
        [TestCase(PngPixelFormat.Rgb8)]
        [TestCase(PngPixelFormat.Rgba8)]
        [TestCase(PngPixelFormat.Gray16)]
        public void ALargeRenderDecodesLikeTheReferenceEncodersFile(PngPixelFormat format)
        {
            // 500×400: sampled counting, pair codes, runs through backgrounds. The reference encoder
            // (DeflateStream, level 6) and ours must decode to the same pixels: the input.
            var pixels = PngWriterTests.RenderLike(500, 400, PngWriter.BytesPerPixel(format), seed: 17);
            var ours = RoundTrip(pixels, 500, 400, format);
            var reference = ReferencePngDecoder.Decode(PngWriter.Encode(pixels, 500, 400, format, PngCompression.Optimal, PngFilter.Sub));
            Assert.That(ReferencePngDecoder.Decode(ours).Pixels, Is.EqualTo(reference.Pixels));
        }

        static PngPixelFormat FormatOf(int bytesPerPixel) =>
            bytesPerPixel == 1 ? PngPixelFormat.Gray8 : bytesPerPixel == 2 ? PngPixelFormat.Gray16 : bytesPerPixel == 3 ? PngPixelFormat.Rgb8 : PngPixelFormat.Rgba8;

        /// <summary>
        /// The literal/length code lengths of the file's first DEFLATE block, read from the IDAT with a bit reader
        /// written from RFC 1951 §3.2.7 (the file has one IDAT, after the 8-byte signature and the 25-byte IHDR).
        /// </summary>
        static int[] LiteralLengthCodeLengths(byte[] file)
        {
            int at = 8 + 25 + 8 + 2; // IDAT's data, past the zlib header
            long bit = 0;
            int Read(int n)
            {
                int value = 0;
                for (int i = 0; i < n; i++, bit++) value |= ((file[at + (int)(bit >> 3)] >> (int)(bit & 7)) & 1) << i;
                return value;
            }
            Read(1); // BFINAL
            Assert.That(Read(2), Is.EqualTo(2), "a dynamic-Huffman block");
            int literals = Read(5) + 257, distances = Read(5) + 1, codeLengthCodes = Read(4) + 4;
            int[] order = { 16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15 };
            var clLengths = new int[19];
            for (int i = 0; i < codeLengthCodes; i++) clLengths[order[i]] = Read(3);
            // Canonical codes of the code-length code, decoded bit by bit (most significant bit of a code first).
            var codes = new Dictionary<(int, int), int>();
            var perLength = new int[8];
            foreach (var l in clLengths) if (l > 0) perLength[l]++;
            var next = new int[8];
            for (int l = 1, code = 0; l < 8; l++)
            {
                code = (code + perLength[l - 1]) << 1;
                next[l] = code;
            }
            for (int s = 0; s < 19; s++) if (clLengths[s] > 0) codes[(clLengths[s], next[clLengths[s]]++)] = s;
            var all = new List<int>();
            while (all.Count < literals + distances)
            {
                int code = 0, length = 0, symbol;
                do
                {
                    code = (code << 1) | Read(1);
                    length++;
                    Assert.That(length, Is.LessThanOrEqualTo(7), "a code-length code of at most 7 bits");
                } while (!codes.TryGetValue((length, code), out symbol));
                if (symbol < 16) all.Add(symbol);
                else if (symbol == 16) { int r = 3 + Read(2), last = all[all.Count - 1]; for (int i = 0; i < r; i++) all.Add(last); }
                else if (symbol == 17) { int r = 3 + Read(3); for (int i = 0; i < r; i++) all.Add(0); }
                else { int r = 11 + Read(7); for (int i = 0; i < r; i++) all.Add(0); }
            }
            return all.GetRange(0, literals).ToArray();
        }
    }
}
