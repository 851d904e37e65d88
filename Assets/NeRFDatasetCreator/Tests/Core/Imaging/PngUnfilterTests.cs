using System;
using System.IO;
using System.IO.Compression;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Core's PNG reader undoes every row filter on every pixel layout it reads (1 to 8 bytes a pixel: grey, grey + alpha,
    /// RGB, RGBA at 8 and 16 bits), on files filtered here from the specification (§9.2–9.4) — one filter for every row,
    /// and all five in turn — with noise that reaches every Paeth branch, and an IDAT split into many small chunks.
    /// </summary>
    public class PngUnfilterTests
    {
        [Test]
        public void EveryFilterOnEveryLayoutDecodesToThePixels(
            [Values(0, 4, 2, 6)] int colorType,
            [Values(8, 16)] int bitDepth,
            [Values(0, 1, 2, 3, 4, -1)] int filter) // −1: row y uses filter y mod 5
        {
            const int w = 13, h = 11;
            var channels = colorType == 0 ? 1 : colorType == 4 ? 2 : colorType == 2 ? 3 : 4;
            var bpp = channels * bitDepth / 8;
            var pixels = new byte[w * h * bpp];
            var random = new Random(colorType * 100 + bitDepth * 10 + filter);
            for (var i = 0; i < pixels.Length; i++)
                pixels[i] = (byte)(i % 7 == 0 ? random.Next(256) : (i * 29 + (i / (w * bpp)) * 3) & 255); // noise and ramps
            var file = Encode(pixels, w, h, bitDepth, colorType, filter, idatChunk: 7);

            var image = PngReader.Decode(file, "f.png");
            Assert.That(image.Samples, Is.EqualTo(pixels));
            Assert.That(ReferencePngDecoder.Decode(file).Pixels, Is.EqualTo(pixels), "the reference decoder agrees on the test's file");
            Assert.That((image.Width, image.Height, image.BitDepth, image.ColorType), Is.EqualTo((w, h, bitDepth, colorType)));
        }

        [Test]
        public void OneIdatChunkAndAWideImageDecodeThroughSeveralBands()
        {
            // 1500 rows of 200 RGBA pixels: more than one band of inflated rows (256 KiB each).
            const int w = 200, h = 1500;
            var pixels = new byte[w * h * 4];
            for (var i = 0; i < pixels.Length; i++) pixels[i] = (byte)(i * 7 + i / 801);
            var file = Encode(pixels, w, h, 8, 6, -1, idatChunk: int.MaxValue);
            Assert.That(PngReader.Decode(file, "wide.png").Samples, Is.EqualTo(pixels));
        }

        [Test]
        public void AnUnknownFilterIsRefusedWithTheRow()
        {
            var file = Encode(new byte[12], 2, 2, 8, 2, 5, idatChunk: int.MaxValue);
            var e = Assert.Throws<InvalidDataException>(() => PngReader.Decode(file, "bad.png"));
            Assert.That(e.Message, Is.EqualTo("bad.png has an unknown row filter 5 on row 0."));
        }

        /// <summary>A PNG of the pixels with each row filtered by the spec's formulas (filter 5 is written as is: invalid).</summary>
        static byte[] Encode(byte[] pixels, int w, int h, int bitDepth, int colorType, int filter, int idatChunk)
        {
            var bpp = pixels.Length / (w * h);
            var stride = w * bpp;
            var filtered = new byte[(stride + 1) * h];
            for (var y = 0; y < h; y++)
            {
                var type = filter >= 0 ? filter : y % 5;
                filtered[y * (stride + 1)] = (byte)type;
                for (var x = 0; x < stride; x++)
                {
                    int a = x >= bpp ? pixels[y * stride + x - bpp] : 0;
                    int b = y > 0 ? pixels[(y - 1) * stride + x] : 0;
                    int c = x >= bpp && y > 0 ? pixels[(y - 1) * stride + x - bpp] : 0;
                    int p = a + b - c, pa = Math.Abs(p - a), pb = Math.Abs(p - b), pc = Math.Abs(p - c);
                    int predictor = type == 1 ? a : type == 2 ? b : type == 3 ? (a + b) / 2 : type == 4 ? (pa <= pb && pa <= pc ? a : pb <= pc ? b : c) : 0;
                    filtered[y * (stride + 1) + 1 + x] = (byte)(pixels[y * stride + x] - predictor);
                }
            }
            var zlib = new MemoryStream();
            zlib.WriteByte(0x78);
            zlib.WriteByte(0x9C);
            using (var deflate = new DeflateStream(zlib, CompressionLevel.Optimal, leaveOpen: true)) deflate.Write(filtered, 0, filtered.Length);
            var adler = ReferencePngDecoder.SimpleAdler32(filtered);
            zlib.Write(new[] { (byte)(adler >> 24), (byte)(adler >> 16), (byte)(adler >> 8), (byte)adler }, 0, 4);
            var data = zlib.ToArray();

            var png = new MemoryStream();
            png.Write(new byte[] { 137, 80, 78, 71, 13, 10, 26, 10 }, 0, 8);
            Chunk(png, "IHDR", new byte[] { (byte)(w >> 24), (byte)(w >> 16), (byte)(w >> 8), (byte)w, (byte)(h >> 24), (byte)(h >> 16), (byte)(h >> 8), (byte)h, (byte)bitDepth, (byte)colorType, 0, 0, 0 });
            for (var i = 0; i < data.Length; i += Math.Min(idatChunk, data.Length))
            {
                var part = new byte[Math.Min(idatChunk, data.Length - i)];
                Array.Copy(data, i, part, 0, part.Length);
                Chunk(png, "IDAT", part);
            }
            Chunk(png, "IEND", new byte[0]);
            return png.ToArray();
        }

        static void Chunk(Stream s, string type, byte[] data)
        {
            var body = new byte[4 + data.Length];
            for (var i = 0; i < 4; i++) body[i] = (byte)type[i];
            Array.Copy(data, 0, body, 4, data.Length);
            var n = data.Length;
            s.Write(new[] { (byte)(n >> 24), (byte)(n >> 16), (byte)(n >> 8), (byte)n }, 0, 4);
            s.Write(body, 0, body.Length);
            var crc = ReferencePngDecoder.BitwiseCrc32(body, 0, body.Length);
            s.Write(new[] { (byte)(crc >> 24), (byte)(crc >> 16), (byte)(crc >> 8), (byte)crc }, 0, 4);
        }
    }
}
