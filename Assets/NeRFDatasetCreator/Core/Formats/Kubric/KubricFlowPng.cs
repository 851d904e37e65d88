using System;
using System.IO;
using System.IO.Compression;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Kubric's flow PNG: 16-bit RGB, R = Δrow, G = Δcol quantised over the video's range, B = 0. Kubric's
    /// <c>write_png</c> pads a two-channel image with a zero channel and writes it with pypng as 16-bit RGB
    /// (google-research/kubric 0ee21e2 kubric/file_io.py:107–117), and its readers take <c>[..., :2]</c>
    /// (challenges/movi/movi_e.py:401, 410). The plugin's PNG writer has no 16-bit RGB, so this encodes one: signature,
    /// IHDR (bit depth 16, colour type 2), one zlib IDAT of unfiltered rows (filter byte 0), IEND (PNG spec §11.2).
    /// </summary>
    public static class KubricFlowPng
    {
        static readonly byte[] Signature = { 137, 80, 78, 71, 13, 10, 26, 10 };

        /// <summary>
        /// The quantised value of <paramref name="value"/> in [<paramref name="min"/>, <paramref name="max"/>]: Kubric's
        /// <c>(data − min) · 65535 / (max − min)</c> (file_io.py:292), rounded to the nearest code where Kubric truncates
        /// (<c>astype(np.uint16)</c>), so a decoded value is within half a step, (max − min) / 131070, of the flow.
        /// </summary>
        public static ushort Quantise(double value, double min, double max)
        {
            if (!(max > min)) return 0;
            var q = Math.Round((value - min) * 65535.0 / (max - min), MidpointRounding.AwayFromZero);
            return (ushort)Math.Max(0, Math.Min(65535, q));
        }

        /// <summary>The PNG of <paramref name="rowCol"/>: two values per pixel (Δrow code, Δcol code), rows top first.</summary>
        public static byte[] Encode(ushort[] rowCol, int width, int height)
        {
            if (rowCol == null || rowCol.LongLength != 2L * width * height) throw new ArgumentException("Two codes per pixel are needed.", nameof(rowCol));
            var stride = 1 + 6 * width;
            var raw = new byte[(long)stride * height];
            for (var y = 0; y < height; y++)
            {
                var at = (long)y * stride + 1; // filter byte 0: None
                for (var x = 0; x < width; x++)
                {
                    var p = 2L * (y * (long)width + x);
                    raw[at] = (byte)(rowCol[p] >> 8);
                    raw[at + 1] = (byte)rowCol[p];
                    raw[at + 2] = (byte)(rowCol[p + 1] >> 8);
                    raw[at + 3] = (byte)rowCol[p + 1];
                    at += 6; // B stays 0
                }
            }
            using (var png = new MemoryStream())
            {
                png.Write(Signature, 0, Signature.Length);
                var ihdr = new byte[13];
                Put32(ihdr, 0, (uint)width);
                Put32(ihdr, 4, (uint)height);
                ihdr[8] = 16; // bit depth
                ihdr[9] = 2;  // colour type: RGB
                Chunk(png, "IHDR", ihdr);
                Chunk(png, "IDAT", Zlib(raw));
                Chunk(png, "IEND", new byte[0]);
                return png.ToArray();
            }
        }

        // zlib (RFC 1950): CMF/FLG 0x78 0x9C, the deflate stream, Adler-32 of the raw bytes, big-endian.
        static byte[] Zlib(byte[] raw)
        {
            using (var output = new MemoryStream())
            {
                output.WriteByte(0x78);
                output.WriteByte(0x9C);
                using (var deflate = new DeflateStream(output, CompressionLevel.Fastest, true)) deflate.Write(raw, 0, raw.Length);
                var adler = new byte[4];
                Put32(adler, 0, Adler32.Compute(raw, 0, raw.Length));
                output.Write(adler, 0, 4);
                return output.ToArray();
            }
        }

        static void Chunk(Stream png, string type, byte[] data)
        {
            var header = new byte[8];
            Put32(header, 0, (uint)data.Length);
            for (var i = 0; i < 4; i++) header[4 + i] = (byte)type[i];
            png.Write(header, 0, 8);
            png.Write(data, 0, data.Length);
            var crc = Crc32.Update(Crc32.Start, header, 4, 4);
            crc = Crc32.Update(crc, data, 0, data.Length);
            var tail = new byte[4];
            Put32(tail, 0, Crc32.Finish(crc));
            png.Write(tail, 0, 4);
        }

        static void Put32(byte[] b, int at, uint v)
        {
            b[at] = (byte)(v >> 24); b[at + 1] = (byte)(v >> 16); b[at + 2] = (byte)(v >> 8); b[at + 3] = (byte)v;
        }
    }
}
