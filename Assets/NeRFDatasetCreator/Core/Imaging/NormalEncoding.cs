namespace NerfDatasetCreator
{
    /// <summary>
    /// The normal image: 8-bit RGB, top row first, each channel round((n·0.5 + 0.5)·255) of a unit normal given in
    /// the dataset's frame (the rotation into it happens before, in the capture layer). Negative components keep
    /// their full range (−1 → 0, 0 → 128, +1 → 255); background is (0,0,0), which no unit vector encodes to.
    /// Point-sampled by the <see cref="PointSampling"/> rule, never averaged.
    /// </summary>
    public static class NormalEncoding
    {
        /// <summary>Writes OutputWidth×OutputHeight×3 bytes (R G B) into <paramref name="rgb"/>.</summary>
        public static void Encode(RawFrame frame, byte[] rgb)
        {
            frame.Require(color: false, mask: false, depth: false, normals: true);
            int ow = frame.OutputWidth, oh = frame.OutputHeight;
            RawFrame.RequireOutput("rgb", rgb, (long)ow * oh * 3, "bytes (3 per output pixel)");

            int k = frame.Supersampling, width = frame.Width, stride = frame.NormalFloatsPerPixel;
            float[] normals = frame.Normals;
            int[] order = PointSampling.Order(k, width);
            int samples = k * k;

            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                int o = oy * ow * 3;
                for (int ox = 0; ox < ow; ox++, o += 3)
                {
                    int first = blockRow * width + ox * k;
                    int hit = -1;
                    for (int i = 0; i < samples; i++)
                    {
                        int n = (first + order[i]) * stride;
                        float x = normals[n], y = normals[n + 1], z = normals[n + 2];
                        // The clear is (0,0,0); a real normal has length ≈ 1. NaN fails the test and counts as background.
                        if (x * x + y * y + z * z > 0.25f) { hit = n; break; }
                    }
                    if (hit < 0)
                    {
                        rgb[o] = 0;
                        rgb[o + 1] = 0;
                        rgb[o + 2] = 0;
                        continue;
                    }
                    rgb[o] = Component(normals[hit]);
                    rgb[o + 1] = Component(normals[hit + 1]);
                    rgb[o + 2] = Component(normals[hit + 2]);
                }
            }
        }

        /// <summary>round((v·0.5 + 0.5)·255) with halves up, v clamped to [−1, 1]: floor(v·127.5 + 128).</summary>
        public static byte Component(float v)
        {
            if (!(v > -1)) return 0;
            if (v >= 1) return 255;
            return (byte)(v * 127.5f + 128f);
        }
    }
}
