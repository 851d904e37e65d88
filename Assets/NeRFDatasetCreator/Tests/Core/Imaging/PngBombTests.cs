using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 32 (bounded memory on hostile files): a small PNG whose zeros inflate to an image larger than any capture
    /// (within deflate's 1032:1, so the ratio test passes it) is refused by its header before its buffer is allocated.
    /// </summary>
    public class PngBombTests
    {
        [Test]
        public void APngLargerThanTheLargestCaptureIsRefusedBeforeDecoding()
        {
            // 8200 × 8200 grey zeros: 67 MB of pixels in about 65 kB of PNG.
            var bomb = TestPng.Encode(8200, 8200, 8, PngInfo.ColorTypeGray);
            Assert.That(bomb.Length, Is.LessThan(1 << 20));
            Assert.That(() => PngReader.Decode(bomb, "r_0.png"), Throws.TypeOf<InvalidDataException>().With.Message.EqualTo(
                "r_0.png claims 8200×8200 pixels, more than the 8192×8192 this tool decodes (the largest capture it makes)."));
            // A long thin image of fewer pixels is still decoded: the limit is the area, not a side.
            var strip = PngReader.Decode(TestPng.Encode(20000, 8, 8, PngInfo.ColorTypeGray), "strip.png");
            Assert.That((strip.Width, strip.Height), Is.EqualTo((20000, 8)));
        }
    }
}
