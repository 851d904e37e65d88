namespace NerfDatasetCreator
{
    /// <summary>
    /// Depth images from the depth pass (eye z in metres, 0 = no surface), point-sampled per output pixel by the
    /// <see cref="PointSampling"/> rule and flipped to top row first.
    /// </summary>
    public static class DepthEncoding
    {
        /// <summary>The largest depth a 16-bit millimetre PNG holds: 65.535 m.</summary>
        public const double MaxMetres = 65.535;

        /// <summary>
        /// 16-bit depth in millimetres (round half up) for a 16-bit gray PNG; 0 where there is no surface. A surface
        /// nearer than 0.5 mm is written as 1 so it stays distinguishable from background. Returns how many pixels
        /// were farther than 65.535 m and were clamped to 65535, so the caller can report it once per run.
        /// </summary>
        public static int ToMillimetres(RawFrame frame, ushort[] millimetres)
        {
            frame.Require(color: false, mask: false, depth: true, normals: false);
            int ow = frame.OutputWidth, oh = frame.OutputHeight;
            RawFrame.RequireOutput("millimetres", millimetres, (long)ow * oh, "values (1 per output pixel)");

            int k = frame.Supersampling, width = frame.Width, clamped = 0;
            float[] depth = frame.Depth;
            int[] order = PointSampling.Order(k, width);

            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                int o = oy * ow;
                for (int ox = 0; ox < ow; ox++)
                {
                    float z = Sample(depth, blockRow * width + ox * k, order);
                    ushort mm;
                    if (!(z > 0)) mm = 0;
                    else
                    {
                        float scaled = z * 1000f + 0.5f;
                        if (scaled >= 65536f) { mm = 65535; clamped++; }
                        else if (scaled < 2f) mm = 1;
                        else mm = (ushort)scaled;
                    }
                    millimetres[o + ox] = mm;
                }
            }
            return clamped;
        }

        /// <summary>
        /// Depth in metres as floats, one per output pixel, 0 where there is no surface, nothing clamped: the array
        /// for Unity's ImageConversion.EncodeArrayToEXR (GraphicsFormat.R32_SFloat), which takes texture order —
        /// pass <see cref="RowDirection.BottomRowFirst"/> for it. <see cref="RowDirection.TopRowFirst"/> gives file
        /// order, for writers that store rows as given.
        /// </summary>
        public static void ToMetres(RawFrame frame, float[] metres, RowDirection rows)
        {
            frame.Require(color: false, mask: false, depth: true, normals: false);
            int ow = frame.OutputWidth, oh = frame.OutputHeight;
            RawFrame.RequireOutput("metres", metres, (long)ow * oh, "values (1 per output pixel)");

            int k = frame.Supersampling, width = frame.Width;
            float[] depth = frame.Depth;
            int[] order = PointSampling.Order(k, width);

            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                int o = (rows == RowDirection.TopRowFirst ? oy : oh - 1 - oy) * ow;
                for (int ox = 0; ox < ow; ox++)
                {
                    float z = Sample(depth, blockRow * width + ox * k, order);
                    metres[o + ox] = z > 0 ? z : 0f;
                }
            }
        }

        static float Sample(float[] depth, int first, int[] order)
        {
            // The first candidate is a hit for every pixel inside the silhouette: test it before entering the loop.
            float centre = depth[first + order[0]];
            if (centre > 0) return centre;
            for (int i = 1; i < order.Length; i++)
            {
                float z = depth[first + order[i]];
                if (z > 0) return z;
            }
            return 0f;
        }
    }
}
