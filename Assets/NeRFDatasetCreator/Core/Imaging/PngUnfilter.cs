namespace NerfDatasetCreator
{
    /// <summary>
    /// PNG's row filters undone (spec §9.2–9.4), one method per type so that each is a plain loop: <c>raw</c> holds the
    /// filtered row at <c>src</c>, <c>up</c> the unfiltered row above at <c>upAt</c> (zeros for the first row), and
    /// the result goes to <c>dst</c> in <c>pixels</c>. The first <c>bpp</c> bytes have no left neighbour (a = c = 0).
    /// </summary>
    static class PngUnfilter
    {
        public static void Sub(byte[] raw, int src, byte[] pixels, int dst, int stride, int bpp)
        {
            for (var x = 0; x < bpp; x++) pixels[dst + x] = raw[src + x];
            for (int end = dst + stride, o = dst + bpp, i = src + bpp; o < end; o++, i++) pixels[o] = (byte)(raw[i] + pixels[o - bpp]);
        }

        public static void Up(byte[] raw, int src, byte[] pixels, int dst, byte[] up, int upAt, int stride)
        {
            for (int i = src, o = dst, u = upAt, end = dst + stride; o < end; i++, o++, u++) pixels[o] = (byte)(raw[i] + up[u]);
        }

        public static void Average(byte[] raw, int src, byte[] pixels, int dst, byte[] up, int upAt, int stride, int bpp)
        {
            for (var x = 0; x < bpp; x++) pixels[dst + x] = (byte)(raw[src + x] + (up[upAt + x] >> 1));
            for (int i = src + bpp, o = dst + bpp, u = upAt + bpp, end = dst + stride; o < end; i++, o++, u++)
                pixels[o] = (byte)(raw[i] + ((pixels[o - bpp] + up[u]) >> 1));
        }

        public static void Paeth(byte[] raw, int src, byte[] pixels, int dst, byte[] up, int upAt, int stride, int bpp)
        {
            // Paeth(0, b, 0) = b.
            for (var x = 0; x < bpp; x++) pixels[dst + x] = (byte)(raw[src + x] + up[upAt + x]);
            for (int i = src + bpp, o = dst + bpp, u = upAt + bpp, end = dst + stride; o < end; i++, o++, u++)
            {
                int a = pixels[o - bpp], b = up[u], c = up[u - bpp];
                // p = a + b − c; pa = |p − a| = |b − c|, pb = |a − c|, pc = |a + b − 2c|; ties prefer a, then b.
                int pa = b - c, pb = a - c;
                int pc = pa + pb;
                if (pa < 0) pa = -pa;
                if (pb < 0) pb = -pb;
                if (pc < 0) pc = -pc;
                int predictor;
                if (pa <= pb && pa <= pc) predictor = a;
                else if (pb <= pc) predictor = b;
                else predictor = c;
                pixels[o] = (byte)(raw[i] + predictor);
            }
        }
    }
}
