using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class NormalEncodingTests
    {
        static byte[] EncodeOne(float x, float y, float z)
        {
            var frame = new RawFrame(1, 1, 1) { Normals = new[] { x, y, z, 1f } };
            var rgb = new byte[3];
            NormalEncoding.Encode(frame, rgb);
            return rgb;
        }

        // round((n·0.5 + 0.5)·255), halves up: −1 → 0, 0 → 127.5 → 128, +1 → 255.
        [TestCase(1f, 0f, 0f, 255, 128, 128)]
        [TestCase(-1f, 0f, 0f, 0, 128, 128)]
        [TestCase(0f, 1f, 0f, 128, 255, 128)]
        [TestCase(0f, -1f, 0f, 128, 0, 128)]
        [TestCase(0f, 0f, 1f, 128, 128, 255)]
        [TestCase(0f, 0f, -1f, 128, 128, 0)]
        public void AxisVectorsMapToTheExpectedRgb(float x, float y, float z, int r, int g, int b)
        {
            Assert.That(EncodeOne(x, y, z), Is.EqualTo(new[] { (byte)r, (byte)g, (byte)b }));
        }

        [Test]
        public void NegativeComponentsSurvive()
        {
            // (−0.6, 0, 0.8): 0.2·255 = 51, 127.5 → 128, 0.9·255 = 229.5 → 230. The original plugin clipped −0.6 to 0 (→128).
            Assert.That(EncodeOne(-0.6f, 0f, 0.8f), Is.EqualTo(new byte[] { 51, 128, 230 }));
        }

        [Test]
        public void BackgroundIsBlackAndEdgesArePointSampled()
        {
            // k = 2, two output pixels: the first block has a background sample first in order (lower-left) and
            // +Z elsewhere → +Z, not a shortened average; the second block is all background → (0,0,0).
            var frame = FrameBuilder.Frame(2, 1, 2);
            frame.Normals = new float[frame.Width * frame.Height * 3];
            frame.NormalFloatsPerPixel = 3;
            foreach (var (x, y) in new[] { (1, 1), (0, 0), (1, 0) })
                frame.Normals[3 * FrameBuilder.Index(frame, x, y) + 2] = 1f;
            var rgb = new byte[6];
            NormalEncoding.Encode(frame, rgb);
            Assert.That(rgb, Is.EqualTo(new byte[] { 128, 128, 255, 0, 0, 0 }));
        }
    }
}
