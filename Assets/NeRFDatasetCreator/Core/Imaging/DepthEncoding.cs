namespace NerfDatasetCreator
{
    /// <summary>
    /// Depth images from the depth pass (eye z in Unity units, 0 = no surface), optionally scaled into output units
    /// (the scene normalisation's scale), taken per output pixel from its block's central samples (<see cref="Sample"/>:
    /// never a mean across an edge) and flipped to top row first. "Metres" below means depth units: Unity units × scale.
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
        /// <param name="scale">Output units per depth-pass unit (the scene normalisation's scale): the PNG then holds thousandths of an output unit.</param>
        public static int ToMillimetres(RawFrame frame, ushort[] millimetres, double scale = 1)
        {
            RequireScale(scale);
            frame.Require(color: false, mask: false, depth: true, normals: false);
            int ow = frame.OutputWidth, oh = frame.OutputHeight;
            RawFrame.RequireOutput("millimetres", millimetres, (long)ow * oh, "values (1 per output pixel)");

            int k = frame.Supersampling, width = frame.Width, clamped = 0;
            float[] depth = frame.Depth;
            if (k == 1) return MillimetresOneSamplePerPixel(frame, millimetres, scale);
            int[] order = PointSampling.Order(k, width);
            int central = k % 2 == 0 ? 4 : 1;

            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                int o = oy * ow;
                for (int ox = 0; ox < ow; ox++)
                {
                    float z = Scaled(Sample(depth, blockRow * width + ox * k, order, central), scale);
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
        /// Supersampling 1 (the capture renders its data passes at the output size): each pixel is its own sample, so
        /// the loop needs no sampling order and no helper calls, which Mono would not inline. Same values as above.
        /// </summary>
        static int MillimetresOneSamplePerPixel(RawFrame frame, ushort[] millimetres, double scale)
        {
            // Fields read here rather than passed in, one index per array, truncation through int: each measured
            // faster on Mono (fewer spilled locals), same values.
            float[] depth = frame.Depth;
            int ow = frame.OutputWidth, oh = frame.OutputHeight, clamped = 0;
            bool unscaled = scale == 1;
            for (int oy = 0; oy < oh; oy++)
            {
                int d = (oh - 1 - oy) * ow; // source rows are bottom-up
                int o = oy * ow;
                for (int end = o + ow; o < end; o++, d++)
                {
                    float z = depth[d];
                    if (!unscaled) z = (float)(z * scale);
                    if (!(z > 0))
                    {
                        millimetres[o] = 0;
                        continue;
                    }
                    float scaled = z * 1000f + 0.5f;
                    if (scaled >= 65536f)
                    {
                        millimetres[o] = 65535;
                        clamped++;
                    }
                    else if (scaled < 2f) millimetres[o] = 1;
                    else millimetres[o] = (ushort)(int)scaled;
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
        /// <param name="scale">Output units per depth-pass unit (the scene normalisation's scale).</param>
        public static void ToMetres(RawFrame frame, float[] metres, RowDirection rows, double scale = 1)
        {
            RequireScale(scale);
            frame.Require(color: false, mask: false, depth: true, normals: false);
            int ow = frame.OutputWidth, oh = frame.OutputHeight;
            RawFrame.RequireOutput("metres", metres, (long)ow * oh, "values (1 per output pixel)");

            int k = frame.Supersampling, width = frame.Width;
            float[] depth = frame.Depth;
            int[] order = PointSampling.Order(k, width);
            int central = k % 2 == 0 ? 4 : 1;

            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                int o = (rows == RowDirection.TopRowFirst ? oy : oh - 1 - oy) * ow;
                for (int ox = 0; ox < ow; ox++)
                {
                    float z = Scaled(Sample(depth, blockRow * width + ox * k, order, central), scale);
                    metres[o + ox] = z > 0 ? z : 0f;
                }
            }
        }

        // Scale 1 keeps the depth pass's floats bit for bit; otherwise the product is rounded once, in double.
        static float Scaled(float z, double scale) => scale == 1 ? z : (float)(z * scale);

        static void RequireScale(double scale) =>
            InvalidParameterException.ThrowIfAny(scale > 0 && !double.IsInfinity(scale) ? null : ValidationProblem.OutsideRange("depthScale", scale, 1e-9, 1e9));

        /// <summary>
        /// Neighbouring central samples within this share of each other are one smooth surface (averaged); farther apart
        /// they are a step (the nearest is taken). A plane seen at 80° from its normal changes depth by ~2 % across half an
        /// output pixel at a 0.5° pixel (128 px over 60°), so 2 % keeps slanted surfaces smooth; separate objects, and a
        /// surface and what lies behind its silhouette, are farther apart than that in any scene a capture frames.
        /// </summary>
        internal const float SmoothTolerance = 0.02f;

        /// <summary>
        /// The depth of one output pixel from its block (first = the block's lower-left sample). Odd k: the centre sample,
        /// which lies on the pixel centre. Even k: the central samples (2×2) straddle the centre at ±1/(2k) pixel; where all
        /// hit one smooth surface (<see cref="SmoothTolerance"/>) the pixel takes n / Σ(1/zᵢ) — 1/z of a plane is affine
        /// in screen position, so the harmonic mean of samples placed symmetrically around the centre is the plane's depth
        /// AT the centre (the point sample was a quarter pixel off it at k = 2); across a step, or where some missed, the
        /// nearest surface among those that hit (never a mean of two surfaces). None hit: the rest of the block by
        /// <see cref="PointSampling"/> order; nothing: background (0).
        /// </summary>
        static float Sample(float[] depth, int first, int[] order, int central)
        {
            // The first candidate is a hit for every pixel inside the silhouette: test it before entering the loop.
            float centre = depth[first + order[0]];
            if (central == 1)
            {
                if (centre > 0) return centre;
                return Rest(depth, first, order, 1);
            }
            float nearest = float.PositiveInfinity, farthest = 0f;
            double inverse = 0;
            int hits = 0;
            for (int i = 0; i < central; i++)
            {
                float z = depth[first + order[i]];
                if (!(z > 0)) continue; // no surface (0, negative, NaN)
                hits++;
                if (z < nearest) nearest = z;
                if (z > farthest) farthest = z;
                inverse += 1.0 / z;
            }
            if (hits == 0) return Rest(depth, first, order, central);
            if (hits < central || float.IsPositiveInfinity(farthest) || farthest > nearest * (1 + SmoothTolerance)) return nearest;
            var harmonic = (float)(central / inverse);
            // Rounding can leave the mean a float step outside [nearest, farthest]; keep it a depth the block holds.
            return harmonic < nearest ? nearest : harmonic > farthest ? farthest : harmonic;
        }

        static float Rest(float[] depth, int first, int[] order, int from)
        {
            for (int i = from; i < order.Length; i++)
            {
                float z = depth[first + order[i]];
                if (z > 0) return z;
            }
            return 0f;
        }
    }
}
