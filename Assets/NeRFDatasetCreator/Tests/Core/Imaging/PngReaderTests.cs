using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Core's PNG reader returns what the independent reference decoder (written from the specification) reads, for every format the plugin writes and every row filter.</summary>
    public class PngReaderTests
    {
        static byte[] Pattern(int count)
        {
            var bytes = new byte[count];
            for (var i = 0; i < count; i++) bytes[i] = (byte)(i * 37 + (i >> 3) * 11);
            return bytes;
        }

        [Test]
        public void EightBitFormatsMatchTheReferenceDecoder(
            [Values(PngPixelFormat.Gray8, PngPixelFormat.Rgb8, PngPixelFormat.Rgba8)] PngPixelFormat format,
            [Values(PngFilter.None, PngFilter.Sub, PngFilter.Up, PngFilter.Average, PngFilter.Paeth, PngFilter.Adaptive)] PngFilter filter)
        {
            const int w = 9, h = 6;
            var pixels = Pattern(w * h * PngWriter.BytesPerPixel(format));
            var file = PngWriter.Encode(pixels, w, h, format, PngCompression.Optimal, filter);
            var image = PngReader.Decode(file, "x.png");
            var reference = ReferencePngDecoder.Decode(file);
            Assert.That(image.Samples, Is.EqualTo(reference.Pixels));
            Assert.That(image.Samples, Is.EqualTo(pixels));
            Assert.That(image.ColorType, Is.EqualTo(reference.ColorType));
            Assert.That(image.Channels, Is.EqualTo(PngWriter.BytesPerPixel(format)));
            Assert.That((image.Width, image.Height, image.BitDepth), Is.EqualTo((w, h, 8)));
        }

        [Test]
        public void SixteenBitGreyIsReadBigEndianAsStored()
        {
            var samples = new ushort[] { 0x0102, 0xFFFE, 0, 4099 };
            var image = PngReader.Decode(PngWriter.EncodeGray16(samples, 2, 2), "d.png");
            Assert.That(image.BitDepth, Is.EqualTo(16));
            Assert.That(image.Samples, Is.EqualTo(new byte[] { 1, 2, 0xFF, 0xFE, 0, 0, 0x10, 0x03 }));
        }

        [Test]
        public void NotAPngIsRefusedWithItsName()
        {
            var e = Assert.Throws<InvalidDataException>(() => PngReader.Decode(new byte[] { 1, 2, 3, 4, 5, 6, 7, 8, 9 }, "broken.png"));
            Assert.That(e.Message, Does.StartWith("broken.png is not a PNG file"));
        }
    }
}
