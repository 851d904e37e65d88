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
