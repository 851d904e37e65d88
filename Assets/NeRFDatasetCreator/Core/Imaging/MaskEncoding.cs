namespace NerfDatasetCreator
{
    /// <summary>
    /// The mask image: 8-bit gray, top row first, each pixel the mean coverage of its k×k block scaled to 0…255 —
    /// the same value the colour image carries as alpha.
    /// </summary>
    public static class MaskEncoding
    {
        /// <summary>Writes OutputWidth×OutputHeight bytes into <paramref name="gray"/>.</summary>
        public static void Encode(RawFrame frame, byte[] gray)
        {
            frame.Require(color: false, mask: true, depth: false, normals: false);
            int ow = frame.OutputWidth, oh = frame.OutputHeight;
            RawFrame.RequireOutput("gray", gray, (long)ow * oh, "bytes (1 per output pixel)");

            int k = frame.Supersampling, kk = k * k, width = frame.Width, stride = frame.MaskBytesPerPixel;
            byte[] mask = frame.Mask;
            if (k == 2)
            {
                EncodeTwoByTwo(mask, stride, width, ow, oh, gray);
                return;
            }
            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                int o = oy * ow;
                for (int ox = 0; ox < ow; ox++)
                {
                    int first = blockRow * width + ox * k;
                    int sum = 0;
                    for (int dy = 0; dy < k; dy++)
                    {
                        int p = (first + dy * width) * stride;
                        for (int dx = 0; dx < k; dx++, p += stride) sum += mask[p];
                    }
                    gray[o + ox] = AlphaOf(sum, kk);
                }
            }
        }

        // round(sum / 4) with halves up for every sum of four bytes: a table, because Mono calls AlphaOf (no inlining)
        // and divides for every pixel.
        static readonly byte[] QuarterOfSum = Quarters();

        static byte[] Quarters()
        {
            var table = new byte[4 * 255 + 1];
            for (var sum = 0; sum < table.Length; sum++) table[sum] = AlphaOf(sum, 4);
            return table;
        }

        /// <summary>The capture's supersampling 2 (the default): the same values as the general loop, without its inner loops and calls.</summary>
        static void EncodeTwoByTwo(byte[] mask, int stride, int width, int ow, int oh, byte[] gray)
        {
            // The capture's R8 mask with rows of whole 64-bit words (width a multiple of 8, e.g. 1600 for 800 output
            // pixels): four blocks at a time.
            if (stride == 1 && width % 8 == 0)
            {
                EncodeTwoByTwoWords(mask, width, ow, oh, gray);
                return;
            }
            var quarter = QuarterOfSum;
            int step = 2 * stride, row = width * stride;
            for (int oy = 0; oy < oh; oy++)
            {
                int p = RowOrder.SourceBlockRow(oy, oh, 2) * row, q = p + row, o = oy * ow, end = o + ow;
                for (; o < end; o++, p += step, q += step)
                    gray[o] = quarter[mask[p] + mask[p + stride] + mask[q] + mask[q + stride]];
            }
        }

        /// <summary>
        /// <see cref="EncodeTwoByTwo"/> for a one-byte mask whose width is a multiple of 8: each row pair is read as
        /// 64-bit words (<see cref="System.Runtime.InteropServices.MemoryMarshal.Cast{TFrom,TTo}(System.Span{TFrom})"/>,
        /// no copy), one word of each row being the samples of four output pixels. Both words 0 (background) or both all
        /// ones (covered) give four output bytes 0 or 255 — what round(sum / 4) gives — in one 32-bit store; other
        /// words take the table per pixel. Most of a render is one or the other, so Mono (no vectorisation, a bounds
        /// check per byte) reads 16 bytes per step instead of 4.
        /// </summary>
        static void EncodeTwoByTwoWords(byte[] mask, int width, int ow, int oh, byte[] gray)
        {
            var quarter = QuarterOfSum;
            System.Span<ulong> words = System.Runtime.InteropServices.MemoryMarshal.Cast<byte, ulong>(new System.Span<byte>(mask));
            System.Span<uint> quads = System.Runtime.InteropServices.MemoryMarshal.Cast<byte, uint>(new System.Span<byte>(gray));
            int rowWords = width / 8;
            for (int oy = 0; oy < oh; oy++)
            {
                // ow = width / 2 is a multiple of 4, so every output row starts on a 32-bit word.
                int p = RowOrder.SourceBlockRow(oy, oh, 2) * width, q = p + width, o = oy * ow, end = o + ow;
                for (int top = p / 8; o < end; o += 4, p += 8, q += 8, top++)
                {
                    ulong upper = words[top], lower = words[top + rowWords];
                    if ((upper | lower) == 0)
                    {
                        quads[o >> 2] = 0;
                        continue;
                    }
                    if ((upper & lower) == ulong.MaxValue)
                    {
                        quads[o >> 2] = uint.MaxValue;
                        continue;
                    }
                    gray[o] = quarter[mask[p] + mask[p + 1] + mask[q] + mask[q + 1]];
                    gray[o + 1] = quarter[mask[p + 2] + mask[p + 3] + mask[q + 2] + mask[q + 3]];
                    gray[o + 2] = quarter[mask[p + 4] + mask[p + 5] + mask[q + 4] + mask[q + 5]];
                    gray[o + 3] = quarter[mask[p + 6] + mask[p + 7] + mask[q + 6] + mask[q + 7]];
                }
            }
        }

        /// <summary>round(sum / k²) with halves rounded up: the mean of the block's mask bytes, i.e. round(255·coverage).</summary>
        internal static byte AlphaOf(int coverageSum, int samples) => (byte)((2 * coverageSum + samples) / (2 * samples));
    }
}
