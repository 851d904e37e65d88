using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class NormalFloatsTests
    {
        // A 1×2 readback: row 0 (the bottom of the picture) sees a surface facing −X, row 1 sees nothing.
        static RawFrame Frame() => new RawFrame(1, 2, 1) { Normals = new float[] { -1, 0, 0, 1, 0, 0, 0, 0 } };

        [Test]
        public void TextureOrderKeepsTheBottomRowFirstWithCoverageInAlpha()
        {
            var floats = new float[8];
            NormalEncoding.ToFloats(Frame(), floats, RowDirection.BottomRowFirst);
            Assert.That(floats, Is.EqualTo(new float[] { -1, 0, 0, 1, 0, 0, 0, 0 }), "negative components survive");
        }

        [Test]
        public void FileOrderPutsTheTopRowFirst()
        {
            var floats = new float[8];
            NormalEncoding.ToFloats(Frame(), floats, RowDirection.TopRowFirst);
            Assert.That(floats, Is.EqualTo(new float[] { 0, 0, 0, 0, -1, 0, 0, 1 }));
        }

        [Test]
        public void FloatsAndBytesSampleTheSamePixel()
        {
            // k = 2: only the upper-right sample of the block hit; both encodings must take it.
            var frame = new RawFrame(2, 2, 2) { Normals = new float[16] };
            frame.Normals[3 * 4 + 1] = 1; // sample (1, 1), upper right, facing +Y
            var floats = new float[4];
            var bytes = new byte[3];
            NormalEncoding.ToFloats(frame, floats, RowDirection.TopRowFirst);
            NormalEncoding.Encode(frame, bytes);
            Assert.That(floats, Is.EqualTo(new float[] { 0, 1, 0, 1 }));
            Assert.That(bytes, Is.EqualTo(new byte[] { 128, 255, 128 }));
        }
    }
}
