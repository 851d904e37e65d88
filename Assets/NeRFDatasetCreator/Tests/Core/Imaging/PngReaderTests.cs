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
        public void AHeaderClaimingMorePixelsThanTheDataCanHoldIsRefusedBeforeDecoding()
        {
            // A real 4×4 grey PNG whose IHDR is rewritten to 20000×20000 (CRC recomputed): 400 MB of rows from a few
            // dozen bytes of deflate data, beyond deflate's 1032:1, so it is refused without allocating them.
            var file = PngWriter.Encode(new byte[16], 4, 4, PngPixelFormat.Gray8);
            foreach (var offset in new[] { 16, 20 }) { file[offset] = 0; file[offset + 1] = 0; file[offset + 2] = 0x4E; file[offset + 3] = 0x20; }
            var crc = Crc32.Compute(file, 12, 17);
            file[29] = (byte)(crc >> 24); file[30] = (byte)(crc >> 16); file[31] = (byte)(crc >> 8); file[32] = (byte)crc;
            var e = Assert.Throws<InvalidDataException>(() => PngReader.Decode(file, "huge.png"));
            Assert.That(e.Message, Does.StartWith("huge.png claims 20000×20000 pixels, more than its"));
        }

        [Test]
        public void NotAPngIsRefusedWithItsName()
        {
            var e = Assert.Throws<InvalidDataException>(() => PngReader.Decode(new byte[] { 1, 2, 3, 4, 5, 6, 7, 8, 9 }, "broken.png"));
            Assert.That(e.Message, Does.StartWith("broken.png is not a PNG file"));
        }
    }
}
