using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class PngInfoTests
    {
        static PngInfo Read(byte[] bytes) => PngInfo.Read(new MemoryStream(bytes));

        [TestCase(800, 800, 8, 6, 4)]
        [TestCase(64, 32, 16, 0, 1)]
        [TestCase(3, 5, 8, 2, 3)]
        [TestCase(7, 9, 8, 0, 1)]
        public void ReadsTheHeader(int width, int height, int bitDepth, int colorType, int channels)
        {
            var info = Read(TestPng.Encode(width, height, bitDepth, colorType));
            Assert.That(info.Width, Is.EqualTo(width));
            Assert.That(info.Height, Is.EqualTo(height));
            Assert.That(info.BitDepth, Is.EqualTo(bitDepth));
            Assert.That(info.ColorType, Is.EqualTo(colorType));
            Assert.That(info.Channels, Is.EqualTo(channels));
        }

        [Test]
        public void TheSizeIsTheBigEndianWordsAtOffsets16And20()
        {
            // PNG spec: 8-byte signature, then IHDR's length (4) and type (4); width at byte 16, height at 20.
            var bytes = TestPng.Encode(1, 1, 8, 6);
            bytes[16] = 0; bytes[17] = 0; bytes[18] = 0x03; bytes[19] = 0x20; // 800
            bytes[20] = 0; bytes[21] = 0; bytes[22] = 0x02; bytes[23] = 0x58; // 600
            var info = Read(bytes);
            Assert.That(info.Width, Is.EqualTo(800));
            Assert.That(info.Height, Is.EqualTo(600));
            Assert.That(info.Describe(), Is.EqualTo("8-bit RGBA"));
        }

        [Test]
        public void TruncatedFilesAreRejectedWhereverTheyEnd()
        {
            var bytes = TestPng.Encode(16, 16, 8, 6);
            foreach (var length in new[] { 0, 5, 8, 12, 20, 33, 40, bytes.Length - 12, bytes.Length - 1 })
            {
                var cut = new byte[length];
                System.Array.Copy(bytes, cut, length);
                Assert.Throws<InvalidDataException>(() => Read(cut), "length " + length);
            }
            Assert.That(Read(bytes).Width, Is.EqualTo(16), "the whole file is fine");
        }

        [Test]
        public void TruncationMessageSaysSo()
        {
            var bytes = TestPng.Encode(16, 16, 8, 6);
            var cut = new byte[bytes.Length - 20];
            System.Array.Copy(bytes, cut, cut.Length);
            var e = Assert.Throws<InvalidDataException>(() => Read(cut));
            Assert.That(e.Message, Does.Contain("truncated"));
        }

        [Test]
        public void NonPngIsRejected()
        {
            var e = Assert.Throws<InvalidDataException>(() => Read(System.Text.Encoding.ASCII.GetBytes("GIF89a........................")));
            Assert.That(e.Message, Does.Contain("signature"));
        }
    }
}
