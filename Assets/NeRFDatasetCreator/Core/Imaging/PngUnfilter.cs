using System;
using System.Runtime.InteropServices;

namespace NerfDatasetCreator
{
    /// <summary>
    /// PNG's row filters undone (spec §9.2–9.4), one method per type so that each is a plain loop: <c>raw</c> holds the
    /// filtered row at <c>src</c>, <c>up</c> the unfiltered row above at <c>upAt</c> (zeros for the first row), and
    /// the result goes to <c>dst</c> in <c>pixels</c>. The first <c>bpp</c> bytes have no left neighbour (a = c = 0).
    /// Up, and Sub and Average on 2- and 4-byte pixels (16-bit grey, RGBA), add several bytes per step within a word
    /// (SWAR: the low seven bits of each byte added without carrying into the next byte, the top bits by exclusive or),
    /// since byte loops are what Mono runs slowest; on 3-byte pixels (normal maps) Sub, Average and Paeth keep the left
    /// pixel's channels in locals (three independent dependency chains, no reload of the byte just stored); the rest go
    /// byte by byte.
    /// </summary>
    static class PngUnfilter
    {
        const ulong Low7 = 0x7F7F7F7F7F7F7F7FUL, High = 0x8080808080808080UL, NotLow = 0xFEFEFEFEFEFEFEFEUL;

        /// <summary>Bytewise (x + y) mod 256 in every byte of a word.</summary>
        static ulong Add(ulong x, ulong y) => ((x & Low7) + (y & Low7)) ^ ((x ^ y) & High);

        public static void Sub(byte[] raw, int src, byte[] pixels, int dst, int stride, int bpp)
        {
            if (bpp == 4 && (stride & 3) == 0) { Sub4(raw, src, pixels, dst, stride); return; }
            if (bpp == 2 && (stride & 1) == 0) { Sub2(raw, src, pixels, dst, stride); return; }
            if (bpp == 3) { Sub3(raw, src, pixels, dst, stride); return; }
            for (var x = 0; x < bpp; x++) pixels[dst + x] = raw[src + x];
            for (int end = dst + stride, o = dst + bpp, i = src + bpp; o < end; o++, i++) pixels[o] = (byte)(raw[i] + pixels[o - bpp]);
        }

        static void Sub4(byte[] raw, int src, byte[] pixels, int dst, int stride)
        {
            var r = MemoryMarshal.Cast<byte, uint>(new Span<byte>(raw, src, stride));
            var o = MemoryMarshal.Cast<byte, uint>(new Span<byte>(pixels, dst, stride));
            ulong left = 0;
            for (var x = 0; x < r.Length; x++)
            {
                left = Add(r[x], left) & 0xFFFFFFFFUL;
                o[x] = (uint)left;
            }
        }

        static void Sub2(byte[] raw, int src, byte[] pixels, int dst, int stride)
        {
            var r = MemoryMarshal.Cast<byte, ushort>(new Span<byte>(raw, src, stride));
            var o = MemoryMarshal.Cast<byte, ushort>(new Span<byte>(pixels, dst, stride));
            ulong left = 0;
            for (var x = 0; x < r.Length; x++)
            {
                left = Add(r[x], left) & 0xFFFFUL;
                o[x] = (ushort)left;
            }
        }

        public static void Up(byte[] raw, int src, byte[] pixels, int dst, byte[] up, int upAt, int stride)
        {
            var words = stride >> 3;
            var r = MemoryMarshal.Cast<byte, ulong>(new Span<byte>(raw, src, words * 8));
            var u = MemoryMarshal.Cast<byte, ulong>(new Span<byte>(up, upAt, words * 8));
            var o = MemoryMarshal.Cast<byte, ulong>(new Span<byte>(pixels, dst, words * 8));
            for (var x = 0; x < o.Length; x++) o[x] = Add(r[x], u[x]);
            for (var x = words * 8; x < stride; x++) pixels[dst + x] = (byte)(raw[src + x] + up[upAt + x]);
        }

        public static void Average(byte[] raw, int src, byte[] pixels, int dst, byte[] up, int upAt, int stride, int bpp)
        {
            if (bpp == 4 && (stride & 3) == 0) { Average4(raw, src, pixels, dst, up, upAt, stride); return; }
            if (bpp == 3) { Average3(raw, src, pixels, dst, up, upAt, stride); return; }
            for (var x = 0; x < bpp; x++) pixels[dst + x] = (byte)(raw[src + x] + (up[upAt + x] >> 1));
            for (int i = src + bpp, o = dst + bpp, u = upAt + bpp, end = dst + stride; o < end; i++, o++, u++)
                pixels[o] = (byte)(raw[i] + ((pixels[o - bpp] + up[u]) >> 1));
        }

        static void Average4(byte[] raw, int src, byte[] pixels, int dst, byte[] up, int upAt, int stride)
        {
            var r = MemoryMarshal.Cast<byte, uint>(new Span<byte>(raw, src, stride));
            var u = MemoryMarshal.Cast<byte, uint>(new Span<byte>(up, upAt, stride));
            var o = MemoryMarshal.Cast<byte, uint>(new Span<byte>(pixels, dst, stride));
            ulong left = 0;
            for (var x = 0; x < r.Length; x++)
            {
                ulong b = u[x];
                // ⌊(a + b) / 2⌋ per byte: the common bits plus half the differing ones.
                var mean = (left & b) + (((left ^ b) & NotLow) >> 1);
                left = Add(r[x], mean) & 0xFFFFFFFFUL;
                o[x] = (uint)left;
            }
        }

        public static void Paeth(byte[] raw, int src, byte[] pixels, int dst, byte[] up, int upAt, int stride, int bpp)
        {
            if (bpp == 3) { Paeth3(raw, src, pixels, dst, up, upAt, stride); return; }
            if (bpp == 4) { Paeth4(raw, src, pixels, dst, up, upAt, stride); return; }
            // Paeth(0, b, 0) = b.
            for (var x = 0; x < bpp; x++) pixels[dst + x] = (byte)(raw[src + x] + up[upAt + x]);
            for (int i = src + bpp, o = dst + bpp, u = upAt + bpp, end = dst + stride; o < end; i++, o++, u++)
            {
                int a = pixels[o - bpp], b = up[u], c = up[u - bpp];
                // p = a + b − c; pa = |p − a| = |b − c|, pb = |a − c|, pc = |a + b − 2c|; ties prefer a, then b.
                // Without branches (on rendered images the choice is unpredictable): sign masks pick the predictor.
                int pa = b - c, pb = a - c;
                int pc = pa + pb;
                int sa = pa >> 31, sb = pb >> 31, sc = pc >> 31;
                pa = (pa ^ sa) - sa;
                pb = (pb ^ sb) - sb;
                pc = (pc ^ sc) - sc;
                int notA = ((pb - pa) | (pc - pa)) >> 31; // −1 when pa > pb or pa > pc
                int notB = (pc - pb) >> 31; // −1 when pb > pc
                int predictor = (a & ~notA) | (notA & ((b & ~notB) | (c & notB)));
                pixels[o] = (byte)(raw[i] + predictor);
            }
        }

        /// <summary>Paeth on 3-byte pixels: the 3 channels' left and upper-left bytes stay in locals, so the 3 dependency chains run side by side.</summary>
        static void Paeth3(byte[] raw, int src, byte[] pixels, int dst, byte[] up, int upAt, int stride)
        {
            for (var x = 0; x < 3; x++) pixels[dst + x] = (byte)(raw[src + x] + up[upAt + x]);
            int a0 = pixels[dst + 0], a1 = pixels[dst + 1], a2 = pixels[dst + 2];
            int cl0 = up[upAt + 0], cl1 = up[upAt + 1], cl2 = up[upAt + 2];
            for (int i = src + 3, o = dst + 3, u = upAt + 3, end = dst + stride; o < end; i += 3, o += 3, u += 3)
            {
                    {
                        int b = up[u + 0], c = cl0;
                        int pa = b - c, pb = a0 - c;
                        int pc = pa + pb;
                        int sa = pa >> 31, sb = pb >> 31, sc = pc >> 31;
                        pa = (pa ^ sa) - sa;
                        pb = (pb ^ sb) - sb;
                        pc = (pc ^ sc) - sc;
                        int notA = ((pb - pa) | (pc - pa)) >> 31;
                        int notB = (pc - pb) >> 31;
                        a0 = (raw[i + 0] + ((a0 & ~notA) | (notA & ((b & ~notB) | (c & notB))))) & 0xFF;
                        cl0 = b;
                        pixels[o + 0] = (byte)a0;
                    }
                    {
                        int b = up[u + 1], c = cl1;
                        int pa = b - c, pb = a1 - c;
                        int pc = pa + pb;
                        int sa = pa >> 31, sb = pb >> 31, sc = pc >> 31;
                        pa = (pa ^ sa) - sa;
                        pb = (pb ^ sb) - sb;
                        pc = (pc ^ sc) - sc;
                        int notA = ((pb - pa) | (pc - pa)) >> 31;
                        int notB = (pc - pb) >> 31;
                        a1 = (raw[i + 1] + ((a1 & ~notA) | (notA & ((b & ~notB) | (c & notB))))) & 0xFF;
                        cl1 = b;
                        pixels[o + 1] = (byte)a1;
                    }
                    {
                        int b = up[u + 2], c = cl2;
                        int pa = b - c, pb = a2 - c;
                        int pc = pa + pb;
                        int sa = pa >> 31, sb = pb >> 31, sc = pc >> 31;
                        pa = (pa ^ sa) - sa;
                        pb = (pb ^ sb) - sb;
                        pc = (pc ^ sc) - sc;
                        int notA = ((pb - pa) | (pc - pa)) >> 31;
                        int notB = (pc - pb) >> 31;
                        a2 = (raw[i + 2] + ((a2 & ~notA) | (notA & ((b & ~notB) | (c & notB))))) & 0xFF;
                        cl2 = b;
                        pixels[o + 2] = (byte)a2;
                    }
            }
        }

        /// <summary>Paeth on 4-byte pixels: the 4 channels' left and upper-left bytes stay in locals, so the 4 dependency chains run side by side.</summary>
        static void Paeth4(byte[] raw, int src, byte[] pixels, int dst, byte[] up, int upAt, int stride)
        {
            for (var x = 0; x < 4; x++) pixels[dst + x] = (byte)(raw[src + x] + up[upAt + x]);
            int a0 = pixels[dst + 0], a1 = pixels[dst + 1], a2 = pixels[dst + 2], a3 = pixels[dst + 3];
            int cl0 = up[upAt + 0], cl1 = up[upAt + 1], cl2 = up[upAt + 2], cl3 = up[upAt + 3];
            for (int i = src + 4, o = dst + 4, u = upAt + 4, end = dst + stride; o < end; i += 4, o += 4, u += 4)
            {
                    {
                        int b = up[u + 0], c = cl0;
                        int pa = b - c, pb = a0 - c;
                        int pc = pa + pb;
                        int sa = pa >> 31, sb = pb >> 31, sc = pc >> 31;
                        pa = (pa ^ sa) - sa;
                        pb = (pb ^ sb) - sb;
                        pc = (pc ^ sc) - sc;
                        int notA = ((pb - pa) | (pc - pa)) >> 31;
                        int notB = (pc - pb) >> 31;
                        a0 = (raw[i + 0] + ((a0 & ~notA) | (notA & ((b & ~notB) | (c & notB))))) & 0xFF;
                        cl0 = b;
                        pixels[o + 0] = (byte)a0;
                    }
                    {
                        int b = up[u + 1], c = cl1;
                        int pa = b - c, pb = a1 - c;
                        int pc = pa + pb;
                        int sa = pa >> 31, sb = pb >> 31, sc = pc >> 31;
                        pa = (pa ^ sa) - sa;
                        pb = (pb ^ sb) - sb;
                        pc = (pc ^ sc) - sc;
                        int notA = ((pb - pa) | (pc - pa)) >> 31;
                        int notB = (pc - pb) >> 31;
                        a1 = (raw[i + 1] + ((a1 & ~notA) | (notA & ((b & ~notB) | (c & notB))))) & 0xFF;
                        cl1 = b;
                        pixels[o + 1] = (byte)a1;
                    }
                    {
                        int b = up[u + 2], c = cl2;
                        int pa = b - c, pb = a2 - c;
                        int pc = pa + pb;
                        int sa = pa >> 31, sb = pb >> 31, sc = pc >> 31;
                        pa = (pa ^ sa) - sa;
                        pb = (pb ^ sb) - sb;
                        pc = (pc ^ sc) - sc;
                        int notA = ((pb - pa) | (pc - pa)) >> 31;
                        int notB = (pc - pb) >> 31;
                        a2 = (raw[i + 2] + ((a2 & ~notA) | (notA & ((b & ~notB) | (c & notB))))) & 0xFF;
                        cl2 = b;
                        pixels[o + 2] = (byte)a2;
                    }
                    {
                        int b = up[u + 3], c = cl3;
                        int pa = b - c, pb = a3 - c;
                        int pc = pa + pb;
                        int sa = pa >> 31, sb = pb >> 31, sc = pc >> 31;
                        pa = (pa ^ sa) - sa;
                        pb = (pb ^ sb) - sb;
                        pc = (pc ^ sc) - sc;
                        int notA = ((pb - pa) | (pc - pa)) >> 31;
                        int notB = (pc - pb) >> 31;
                        a3 = (raw[i + 3] + ((a3 & ~notA) | (notA & ((b & ~notB) | (c & notB))))) & 0xFF;
                        cl3 = b;
                        pixels[o + 3] = (byte)a3;
                    }
            }
        }

        /// <summary>Average on 3-byte pixels (RGB normals): the left pixel's channels stay in locals.</summary>
        static void Average3(byte[] raw, int src, byte[] pixels, int dst, byte[] up, int upAt, int stride)
        {
            int a0 = (raw[src] + (up[upAt] >> 1)) & 0xFF, a1 = (raw[src + 1] + (up[upAt + 1] >> 1)) & 0xFF, a2 = (raw[src + 2] + (up[upAt + 2] >> 1)) & 0xFF;
            pixels[dst] = (byte)a0;
            pixels[dst + 1] = (byte)a1;
            pixels[dst + 2] = (byte)a2;
            for (int i = src + 3, o = dst + 3, u = upAt + 3, end = dst + stride; o < end; i += 3, o += 3, u += 3)
            {
                a0 = (raw[i] + ((a0 + up[u]) >> 1)) & 0xFF;
                a1 = (raw[i + 1] + ((a1 + up[u + 1]) >> 1)) & 0xFF;
                a2 = (raw[i + 2] + ((a2 + up[u + 2]) >> 1)) & 0xFF;
                pixels[o] = (byte)a0;
                pixels[o + 1] = (byte)a1;
                pixels[o + 2] = (byte)a2;
            }
        }

        /// <summary>Sub on 3-byte pixels: the left pixel's channels stay in locals.</summary>
        static void Sub3(byte[] raw, int src, byte[] pixels, int dst, int stride)
        {
            int a0 = raw[src], a1 = raw[src + 1], a2 = raw[src + 2];
            pixels[dst] = (byte)a0;
            pixels[dst + 1] = (byte)a1;
            pixels[dst + 2] = (byte)a2;
            for (int i = src + 3, o = dst + 3, end = dst + stride; o < end; i += 3, o += 3)
            {
                a0 = (raw[i] + a0) & 0xFF;
                a1 = (raw[i + 1] + a1) & 0xFF;
                a2 = (raw[i + 2] + a2) & 0xFF;
                pixels[o] = (byte)a0;
                pixels[o + 1] = (byte)a1;
                pixels[o + 2] = (byte)a2;
            }
        }
    }
}
