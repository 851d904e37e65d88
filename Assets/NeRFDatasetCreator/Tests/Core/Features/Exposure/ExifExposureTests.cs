using System;
using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ExifExposureTests
    {
        /// <summary>
        /// Reads the block the way piexif does for gsplat (IFD0 → ExifIFD pointer 34665 → ExposureTime 33434, FNumber 33437,
        /// PhotographicSensitivity 34855) and applies gsplat's formula log2(t / N² · ISO) (examples/exif.py:94–121).
        /// </summary>
        static double GsplatEv(byte[] tiff)
        {
            Assert.That(tiff[0] == 'I' && tiff[1] == 'I' && U16(tiff, 2) == 42, "little-endian TIFF header");
            var ifd0 = (int)U32(tiff, 4);
            int exif = -1;
            for (var i = 0; i < U16(tiff, ifd0); i++)
                if (U16(tiff, ifd0 + 2 + 12 * i) == 34665) exif = (int)U32(tiff, ifd0 + 2 + 12 * i + 8);
            Assert.That(exif, Is.GreaterThan(0), "Exif IFD pointer");
            double t = double.NaN, n = double.NaN, iso = double.NaN;
            var lastTag = 0;
            for (var i = 0; i < U16(tiff, exif); i++)
            {
                var at = exif + 2 + 12 * i;
                int tag = U16(tiff, at), type = U16(tiff, at + 2);
                Assert.That(tag, Is.GreaterThan(lastTag), "tags ascending");
                lastTag = tag;
                if (tag == 33434 || tag == 33437)
                {
                    Assert.That(type, Is.EqualTo(5), "RATIONAL");
                    var off = (int)U32(tiff, at + 8);
                    var value = U32(tiff, off) / (double)U32(tiff, off + 4);
                    if (tag == 33434) t = value; else n = value;
                }
                if (tag == 34855)
                {
                    Assert.That(type, Is.EqualTo(3), "SHORT");
                    iso = U16(tiff, at + 8);
                }
            }
            return Math.Log(t / (n * n) * iso, 2);
        }

        static int U16(byte[] b, int at) => b[at] | (b[at + 1] << 8);
        static uint U32(byte[] b, int at) => (uint)(b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) | (b[at + 3] << 24));

        [Test]
        public void GsplatsFormulaGivesBackTheEv()
        {
            foreach (var ev in new[] { -10, -3.3, -1, -0.123456, 0, 0.5, 1, 2.75, 10 })
                Assert.That(GsplatEv(ExifExposure.Block(ev)), Is.EqualTo(ev).Within(2e-5), ev.ToString());
            // EV 0 is 1/100 s at f/4, ISO 1600.
            var (num, den) = ExifExposure.Rational(ExifExposure.ExposureTime(0));
            Assert.That(num / (double)den, Is.EqualTo(0.01).Within(1e-9));
        }

        [Test]
        public void PngWithTheChunkDecodesToTheSamePixelsAndHoldsItBeforeIdat()
        {
            var pixels = new byte[4 * 3 * 2];
            for (var i = 0; i < pixels.Length; i++) pixels[i] = (byte)(i * 11);
            var png = PngWriter.Encode(pixels, 3, 2, PngPixelFormat.Rgba8);
            var block = ExifExposure.Block(0.5);
            var with = PngChunks.InsertExif(png, block);
            var path = Path.Combine(Path.GetTempPath(), "exif-" + Guid.NewGuid().ToString("N") + ".png");
            try
            {
                File.WriteAllBytes(path, with);
                Assert.That(PngReader.Read(path).Samples, Is.EqualTo(pixels));
            }
            finally { File.Delete(path); }
            // Chunk walk: IHDR, eXIf (CRC over type + data), then IDAT.
            var at = 8 + 25;
            var length = (with[at] << 24) | (with[at + 1] << 16) | (with[at + 2] << 8) | with[at + 3];
            Assert.That(System.Text.Encoding.ASCII.GetString(with, at + 4, 4), Is.EqualTo("eXIf"));
            Assert.That(length, Is.EqualTo(block.Length));
            var crc = (uint)((with[at + 8 + length] << 24) | (with[at + 9 + length] << 16) | (with[at + 10 + length] << 8) | with[at + 11 + length]);
            Assert.That(crc, Is.EqualTo(Crc32.Compute(with, at + 4, 4 + length)));
            Assert.That(System.Text.Encoding.ASCII.GetString(with, at + 12 + length + 4, 4), Is.EqualTo("IDAT"));
            var copy = new byte[length];
            Array.Copy(with, at + 8, copy, 0, length);
            Assert.That(GsplatEv(copy), Is.EqualTo(0.5).Within(2e-5));
        }
    }
}
