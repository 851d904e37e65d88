using System;
using System.IO;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A Radiance RGBE (.hdr) writer for the environment maps TensoIR, NeRFactor and GS-IR read (Greg Ward, "Real Pixels",
    /// Graphics Gems II; the format of Radiance's color.c): the header <c>#?RADIANCE</c>, <c>FORMAT=32-bit_rle_rgbe</c>, a
    /// blank line, <c>-Y h +X w</c> (top row first), then per scan line the "new" run-length form — 2, 2, width (big
    /// endian), then each of R, G, B, E as literal runs of at most 128 bytes. Literal runs only: every reader decodes them
    /// (a flat scan line could be mistaken for a run-length one when its first pixel starts 2, 2). Widths outside
    /// 8 … 32767, which the run-length form cannot hold, are written flat.
    /// </summary>
    public static class RadianceHdr
    {
        /// <summary>The four RGBE bytes of a linear colour (color.c setcolr: frexp of the largest component).</summary>
        public static void Rgbe(double r, double g, double b, byte[] into, int at)
        {
            var v = Math.Max(r, Math.Max(g, b));
            if (!(v >= 1e-32))
            {
                into[at] = into[at + 1] = into[at + 2] = into[at + 3] = 0;
                return;
            }
            var e = (int)Math.Floor(Math.Log(v, 2)) + 1;
            var m = v / Math.Pow(2, e);
            if (m >= 1) { m /= 2; e++; }
            else if (m < 0.5) { m *= 2; e--; }
            var scale = m * 256.0 / v;
            into[at] = (byte)Math.Max(0, Math.Min(255, Math.Floor(Math.Max(0, r) * scale)));
            into[at + 1] = (byte)Math.Max(0, Math.Min(255, Math.Floor(Math.Max(0, g) * scale)));
            into[at + 2] = (byte)Math.Max(0, Math.Min(255, Math.Floor(Math.Max(0, b) * scale)));
            into[at + 3] = (byte)Math.Max(0, Math.Min(255, e + 128));
        }

        /// <summary>The linear colour of four RGBE bytes (color.c colr_color: (m + 0.5)·2^(e − 136)).</summary>
        public static double[] Decode(byte r, byte g, byte b, byte e)
        {
            if (e == 0) return new double[3];
            var f = Math.Pow(2, e - 136);
            return new[] { (r + 0.5) * f, (g + 0.5) * f, (b + 0.5) * f };
        }

        /// <summary>The file of an RGB(A) float image given top row first (<paramref name="channels"/> 3 or 4; alpha ignored).</summary>
        public static byte[] Encode(float[] pixels, int width, int height, int channels)
        {
            using (var stream = new MemoryStream())
            {
                var header = Encoding.ASCII.GetBytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + height + " +X " + width + "\n");
                stream.Write(header, 0, header.Length);
                var row = new byte[width * 4];
                var runLength = width >= 8 && width <= 32767;
                for (var y = 0; y < height; y++)
                {
                    for (var x = 0; x < width; x++)
                    {
                        var p = ((long)y * width + x) * channels;
                        Rgbe(pixels[p], pixels[p + 1], pixels[p + 2], row, 4 * x);
                    }
                    if (!runLength)
                    {
                        stream.Write(row, 0, row.Length);
                        continue;
                    }
                    stream.WriteByte(2);
                    stream.WriteByte(2);
                    stream.WriteByte((byte)(width >> 8));
                    stream.WriteByte((byte)(width & 255));
                    var run = new byte[128];
                    for (var c = 0; c < 4; c++)
                        for (var x = 0; x < width; x += 128)
                        {
                            var count = Math.Min(128, width - x);
                            stream.WriteByte((byte)count);
                            for (var k = 0; k < count; k++) run[k] = row[4 * (x + k) + c];
                            stream.Write(run, 0, count);
                        }
                }
                return stream.ToArray();
            }
        }
    }
}
