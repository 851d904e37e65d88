using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class MaskEncodingTests
    {
        [Test]
        public void MaskIsTheMeanCoverageOfEachBlock()
        {
            // k = 2, four output pixels with 1, 2, 3 and 4 covered samples: 255·n/4 rounded = 64, 128, 191, 255.
            var frame = FrameBuilder.Frame(4, 1, 2).WithSrgb();
            for (int n = 1; n <= 4; n++)
                for (int i = 0; i < n; i++) frame.Cover(2 * (n - 1) + i % 2, i / 2, 1, 2, 3);
            var gray = new byte[4];
            MaskEncoding.Encode(frame, gray);
            Assert.That(gray, Is.EqualTo(new byte[] { 64, 128, 191, 255 }));
        }

        [TestCase(1, 2)]
        [TestCase(4, 2)]
        [TestCase(1, 3)]
        [TestCase(4, 1)]
        public void EverySupersamplingGivesTheRoundedMeanOfItsBlock(int bytesPerPixel, int k)
        {
            // Random coverage, against the definition written out here: round(sum / k²), halves up, top row first.
            const int ow = 7, oh = 5;
            var random = new SeededRandom(31 + k);
            var frame = new RawFrame(ow * k, oh * k, k) { Mask = new byte[ow * k * oh * k * bytesPerPixel], MaskBytesPerPixel = bytesPerPixel };
            for (var i = 0; i < frame.Mask.Length; i++) frame.Mask[i] = (byte)(random.NextUInt64() % 4 == 0 ? 255 : random.NextUInt64() % 256);
            var gray = new byte[ow * oh];
            MaskEncoding.Encode(frame, gray);
            for (var oy = 0; oy < oh; oy++)
                for (var ox = 0; ox < ow; ox++)
                {
                    var sum = 0;
                    var sourceRow = (oh - 1 - oy) * k; // source rows are bottom-up
                    for (var dy = 0; dy < k; dy++)
                        for (var dx = 0; dx < k; dx++)
                            sum += frame.Mask[((sourceRow + dy) * ow * k + ox * k + dx) * bytesPerPixel];
                    var expected = (int)System.Math.Floor((double)sum / (k * k) + 0.5);
                    Assert.That(gray[oy * ow + ox], Is.EqualTo(expected), "pixel " + ox + "," + oy);
                }
        }

        /// <summary>
        /// At k = 2 a one-byte mask whose width is a multiple of 8 is read 8 samples (four blocks) per row at a time,
        /// with whole words of 0 or 255 written four pixels at once. Words that are all 0 or all 255 but for one byte
        /// (every position, in the upper or the lower row, set to 0, 1, 254 or 255), random words, and widths that are
        /// (32, 64) and are not (30, 36) multiples of 8: the rounded mean of every block.
        /// </summary>
        [TestCase(16)]
        [TestCase(32)]
        [TestCase(15)]
        [TestCase(18)]
        public void TwoByTwoWordsGiveTheRoundedMeanOfEveryBlock(int ow)
        {
            const int k = 2, oh = 140;
            int width = ow * k;
            var random = new SeededRandom(57 + ow);
            var frame = new RawFrame(width, oh * k, k) { Mask = new byte[width * oh * k], MaskBytesPerPixel = 1 };
            byte[] odd = { 0, 1, 254, 255 };
            int pair = 0;
            for (int row = 0; row < oh * k; row += 2)
                for (int x = 0; x + 8 <= width; x += 8, pair++)
                {
                    // In turn: 0s, 255s, 0s and 255s with one odd byte, random bytes; the odd byte walks through the
                    // 16 positions of the two words and the four odd values.
                    int kind = pair % 6;
                    byte fill = (byte)(kind % 2 == 0 ? 0 : 255);
                    for (int dy = 0; dy < 2; dy++)
                        for (int i = 0; i < 8; i++)
                            frame.Mask[(row + dy) * width + x + i] = kind >= 4 ? (byte)random.NextUInt64() : fill;
                    int position = pair / 24 % 16;
                    if (kind == 2 || kind == 3)
                        frame.Mask[(row + position / 8) * width + x + position % 8] = odd[pair / 6 % 4];
                }
            Assert.That(pair, Is.GreaterThanOrEqualTo(6 * 4 * 16), "every odd byte position and value");
            var gray = new byte[ow * oh];
            MaskEncoding.Encode(frame, gray);
            for (var oy = 0; oy < oh; oy++)
                for (var ox = 0; ox < ow; ox++)
                {
                    var sourceRow = (oh - 1 - oy) * k; // source rows are bottom-up
                    var sum = 0;
                    for (var dy = 0; dy < k; dy++)
                        for (var dx = 0; dx < k; dx++)
                            sum += frame.Mask[(sourceRow + dy) * width + ox * k + dx];
                    Assert.That(gray[oy * ow + ox], Is.EqualTo((int)System.Math.Floor(sum / 4.0 + 0.5)), "pixel " + ox + "," + oy);
                }
        }

        [Test]
        public void SingleChannelMaskIsRead()
        {
            var frame = new RawFrame(2, 2, 1) { Mask = new byte[] { 0, 255, 10, 20 }, MaskBytesPerPixel = 1 };
            var gray = new byte[4];
            MaskEncoding.Encode(frame, gray);
            // Bottom-up rows (0 255) and (10 20) come out top first.
            Assert.That(gray, Is.EqualTo(new byte[] { 10, 20, 0, 255 }));
        }
    }
}
