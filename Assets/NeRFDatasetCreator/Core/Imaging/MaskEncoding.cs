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
            var quarter = QuarterOfSum;
            int step = 2 * stride, row = width * stride;
            for (int oy = 0; oy < oh; oy++)
            {
                int p = RowOrder.SourceBlockRow(oy, oh, 2) * row, q = p + row, o = oy * ow, end = o + ow;
                for (; o < end; o++, p += step, q += step)
                    gray[o] = quarter[mask[p] + mask[p + stride] + mask[q] + mask[q + stride]];
            }
        }

        /// <summary>round(sum / k²) with halves rounded up: the mean of the block's mask bytes, i.e. round(255·coverage).</summary>
        internal static byte AlphaOf(int coverageSum, int samples) => (byte)((2 * coverageSum + samples) / (2 * samples));
    }
}
