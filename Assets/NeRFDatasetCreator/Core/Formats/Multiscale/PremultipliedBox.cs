using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The multi-scale exports' downscale: a box filter of f × f source pixels per output pixel, on the stored 8-bit
    /// sRGB code values, weighted by coverage (premultiplied alpha). With n = f², P = Σ cᵢ·aᵢ and A = Σ aᵢ over a block:
    /// <list type="bullet">
    /// <item>RGBA (mip-NeRF's layout, whose loaders read alpha): a = round(A / n), c = round(P / A) (0 where A = 0), each
    /// rounded half up in integers. Where the coverage differs inside a block this is the colour of the covered part, so
    /// compositing it later gives the average of the composited block.</item>
    /// <item>RGB over a background b (gsplat's layout, which drops alpha): c = round((P + b·(255·n − A)) / (255·n)): the
    /// average of the block composited over b, rounded once. At f = 1 this is <see cref="AlphaCompositing.Over"/>.</item>
    /// </list>
    /// Sizes: the output is ⌊W / f⌋ × ⌊H / f⌋; the last W mod f columns and H mod f rows are dropped, so output pixel
    /// (i, j) is exactly source block [f·i, f·i + f) × [f·j, f·j + f) and every intrinsic scales by exactly 1 / f
    /// (a pixel-centre coordinate x in the output is f·x in the source). The common converter (google/mipnerf
    /// convert_blender_data.py <c>down2</c>) averages straight RGBA instead, which pulls the colour of a half-covered block
    /// towards the transparent pixels' (black) colour: edges darken (Documentation~/maintainers/layouts-multiscale-hdr.md).
    /// </summary>
    public static class PremultipliedBox
    {
        /// <summary>⌊<paramref name="size"/> / <paramref name="factor"/>⌋: the size of a level (remainder dropped).</summary>
        public static int Reduced(int size, int factor)
        {
            if (factor < 1) throw new ArgumentOutOfRangeException(nameof(factor), factor, "A factor is at least 1.");
            return size / factor;
        }

        /// <summary>
        /// RGBA (straight alpha) → RGBA at 1/<paramref name="factor"/>: <paramref name="channels"/> is 4 for RGBA, 3 for RGB
        /// (alpha 255). Rows top first, as <see cref="PngReader"/> gives them.
        /// </summary>
        public static byte[] Rgba(byte[] samples, int width, int height, int channels, int factor)
        {
            Check(samples, width, height, channels);
            int w = Reduced(width, factor), h = Reduced(height, factor);
            var output = new byte[(long)w * h * 4];
            long n = (long)factor * factor;
            var d = 0;
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    BlockSums(samples, width, channels, factor, x, y, out var p0, out var p1, out var p2, out var a);
                    output[d] = Colour(p0, a);
                    output[d + 1] = Colour(p1, a);
                    output[d + 2] = Colour(p2, a);
                    output[d + 3] = (byte)((2 * a + n) / (2 * n));
                    d += 4;
                }
            return output;
        }

        /// <summary>
        /// The sums over the factor × factor block (x, y) of the output: each colour × its alpha (premultiplied, in code
        /// units) and the alpha. One call per output pixel, not per sample: cheap enough on Mono, which does not inline it.
        /// </summary>
        static void BlockSums(byte[] samples, int width, int channels, int factor, int x, int y, out long p0, out long p1, out long p2, out long a)
        {
            p0 = p1 = p2 = a = 0;
            for (var by = 0; by < factor; by++)
            {
                var s = ((long)(y * factor + by) * width + (long)x * factor) * channels;
                for (var bx = 0; bx < factor; bx++, s += channels)
                {
                    long alpha = channels == 4 ? samples[s + 3] : 255;
                    p0 += samples[s] * alpha;
                    p1 += samples[s + 1] * alpha;
                    p2 += samples[s + 2] * alpha;
                    a += alpha;
                }
            }
        }

        /// <summary>
        /// RGBA (straight alpha) → RGB at 1/<paramref name="factor"/>, each block's average composited over
        /// (<paramref name="r"/>, <paramref name="g"/>, <paramref name="b"/>), rounded once.
        /// </summary>
        public static byte[] RgbOver(byte[] samples, int width, int height, int channels, int factor, byte r, byte g, byte b)
        {
            Check(samples, width, height, channels);
            int w = Reduced(width, factor), h = Reduced(height, factor);
            var output = new byte[(long)w * h * 3];
            long whole = 255L * factor * factor;
            var d = 0;
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    BlockSums(samples, width, channels, factor, x, y, out var p0, out var p1, out var p2, out var a);
                    output[d] = Round(p0 + r * (whole - a), whole);
                    output[d + 1] = Round(p1 + g * (whole - a), whole);
                    output[d + 2] = Round(p2 + b * (whole - a), whole);
                    d += 3;
                }
            return output;
        }

        static byte Colour(long premultiplied, long alpha) => alpha == 0 ? (byte)0 : Round(premultiplied, alpha);

        /// <summary>⌊num / den + ½⌋ for num, den ≥ 0: round half up, in integers (the same on every runtime).</summary>
        static byte Round(long num, long den) => (byte)((2 * num + den) / (2 * den));

        static void Check(byte[] samples, int width, int height, int channels)
        {
            if (channels != 3 && channels != 4) throw new ArgumentOutOfRangeException(nameof(channels), channels, "RGB or RGBA samples are expected.");
            if (width < 1 || height < 1) throw new ArgumentOutOfRangeException(nameof(width), width + "×" + height, "An image has at least one pixel.");
            if (samples == null || samples.LongLength < (long)width * height * channels)
                throw new ArgumentException("The samples hold fewer than " + channels + " bytes per pixel.", nameof(samples));
        }
    }
}
