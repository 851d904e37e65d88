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
