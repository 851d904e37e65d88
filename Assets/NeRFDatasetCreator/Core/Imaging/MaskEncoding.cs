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

        /// <summary>round(sum / k²) with halves rounded up: the mean of the block's mask bytes, i.e. round(255·coverage).</summary>
        internal static byte AlphaOf(int coverageSum, int samples) => (byte)((2 * coverageSum + samples) / (2 * samples));
    }
}
