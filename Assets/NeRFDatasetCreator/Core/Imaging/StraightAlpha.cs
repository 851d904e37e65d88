namespace NerfDatasetCreator
{
    /// <summary>
    /// The colour image: k×k box downsampling in linear light, alpha from the mask pass (never the lit shader's
    /// alpha), colour un-premultiplied by that coverage, then encoded as 8-bit sRGB RGBA, top row first.
    /// <para>
    /// Why un-premultiply: the colour pass is rendered over a (0,0,0,0) clear, so an edge block's mean colour is
    /// coverage × surface colour. Dividing by the coverage restores the surface colour, which is what straight-alpha
    /// PNGs (Blender's, nerf_synthetic's) store and what loaders composite as rgb·a + bg·(1 − a).
    /// </para>
    /// </summary>
    public static class StraightAlpha
    {
        /// <summary>
        /// Writes OutputWidth×OutputHeight×4 bytes (R G B A) into <paramref name="rgba"/>. Transparent background
        /// (the default): alpha = round(255·coverage), and a pixel with alpha 0 is (0,0,0,0). Solid background: each
        /// pixel is surface·coverage + background·(1 − coverage) in linear light and alpha is 255. When
        /// <paramref name="mask"/> is given, the mask image (<see cref="MaskEncoding"/>) is written in the same pass,
        /// which is cheaper than a second pass over the mask readback.
        /// </summary>
        public static void Resolve(RawFrame frame, byte[] rgba, Background background = default, byte[] mask = null)
        {
            frame.Require(color: true, mask: true, depth: false, normals: false);
            int ow = frame.OutputWidth, oh = frame.OutputHeight;
            RawFrame.RequireOutput("rgba", rgba, (long)ow * oh * 4, "bytes (4 per output pixel)");
            if (mask != null) RawFrame.RequireOutput("mask", mask, (long)ow * oh, "bytes (1 per output pixel)");

            int k = frame.Supersampling, kk = k * k, width = frame.Width, stride = frame.MaskBytesPerPixel;
            byte[] coverageBytes = frame.Mask;
            byte[] colorBytes = frame.ColorSrgb;
            if (k == 2 && colorBytes != null && !background.IsSolid)
            {
                ResolveTwoByTwo(coverageBytes, stride, colorBytes, width, ow, oh, rgba, mask);
                return;
            }
            float[] colorFloats = frame.ColorLinear;
            float[] decode = Srgb.DecodeLookup;
            int fullCoverage = 255 * kk;
            float inverseSamples = 1f / kk;

            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                int o = oy * ow * 4;
                for (int ox = 0; ox < ow; ox++, o += 4)
                {
                    int first = blockRow * width + ox * k;
                    int coverage;
                    if (k == 2)
                    {
                        int m = first * stride, up = width * stride;
                        coverage = coverageBytes[m] + coverageBytes[m + stride] + coverageBytes[m + up] + coverageBytes[m + up + stride];
                    }
                    else
                    {
                        coverage = 0;
                        for (int dy = 0; dy < k; dy++)
                        {
                            int m = (first + dy * width) * stride;
                            for (int dx = 0; dx < k; dx++, m += stride) coverage += coverageBytes[m];
                        }
                    }
                    if (mask != null) mask[o >> 2] = MaskEncoding.AlphaOf(coverage, kk);

                    if (coverage == 0)
                    {
                        WriteBackground(rgba, o, background);
                        continue;
                    }

                    // Sum of linear colour over the block: coverage × surface colour, since uncovered samples are black.
                    float r = 0, g = 0, b = 0;
                    if (colorBytes != null)
                    {
                        if (k == 2)
                        {
                            int c = first * 4, up = width * 4;
                            r = decode[colorBytes[c]] + decode[colorBytes[c + 4]] + decode[colorBytes[c + up]] + decode[colorBytes[c + up + 4]];
                            g = decode[colorBytes[c + 1]] + decode[colorBytes[c + 5]] + decode[colorBytes[c + up + 1]] + decode[colorBytes[c + up + 5]];
                            b = decode[colorBytes[c + 2]] + decode[colorBytes[c + 6]] + decode[colorBytes[c + up + 2]] + decode[colorBytes[c + up + 6]];
                        }
                        else
                        {
                            for (int dy = 0; dy < k; dy++)
                            {
                                int c = (first + dy * width) * 4;
                                for (int dx = 0; dx < k; dx++, c += 4)
                                {
                                    r += decode[colorBytes[c]];
                                    g += decode[colorBytes[c + 1]];
                                    b += decode[colorBytes[c + 2]];
                                }
                            }
                        }
                    }
                    else
                    {
                        for (int dy = 0; dy < k; dy++)
                        {
                            int c = (first + dy * width) * 4;
                            for (int dx = 0; dx < k; dx++, c += 4)
                            {
                                r += colorFloats[c];
                                g += colorFloats[c + 1];
                                b += colorFloats[c + 2];
                            }
                        }
                    }

                    // mean colour / mean coverage = (sum / k²) / (coverage / (255·k²)) = sum · 255 / coverage.
                    float unpremultiply = coverage == fullCoverage ? inverseSamples : 255f / coverage;
                    r = Clamp01(r * unpremultiply);
                    g = Clamp01(g * unpremultiply);
                    b = Clamp01(b * unpremultiply);

                    if (background.IsSolid)
                    {
                        float a = coverage / (float)fullCoverage;
                        rgba[o] = Srgb.EncodeUnit(r * a + background.LinearR * (1 - a));
                        rgba[o + 1] = Srgb.EncodeUnit(g * a + background.LinearG * (1 - a));
                        rgba[o + 2] = Srgb.EncodeUnit(b * a + background.LinearB * (1 - a));
                        rgba[o + 3] = 255;
                        continue;
                    }

                    byte alpha = MaskEncoding.AlphaOf(coverage, kk);
                    if (alpha == 0)
                    {
                        WriteBackground(rgba, o, background);
                        continue;
                    }
                    rgba[o] = Srgb.EncodeUnit(r);
                    rgba[o + 1] = Srgb.EncodeUnit(g);
                    rgba[o + 2] = Srgb.EncodeUnit(b);
                    rgba[o + 3] = alpha;
                }
            }
        }

        /// <summary>
        /// The capture's usual case — 2×2 supersampling, sRGB bytes, transparent background — as one loop with every
        /// helper written out (Mono inlines none of them) and a fast path for fully covered pixels, which need no
        /// clamp and have alpha 255. The same bytes as the general loop above.
        /// </summary>
        static void ResolveTwoByTwo(byte[] coverageBytes, int stride, byte[] colorBytes, int width, int ow, int oh, byte[] rgba, byte[] mask)
        {
            float[] decode = Srgb.DecodeLookup;
            byte[] bucket = Srgb.EncodeBucketLookup;
            float[] threshold = Srgb.EncodeThresholdLookup;
            const float buckets = Srgb.EncodeBucketScale;
            int maskUp = width * stride, colourUp = width * 4;
            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, 2);
                int o = oy * ow * 4;
                int m = blockRow * width * stride;
                int c = blockRow * width * 4;
                int p = oy * ow;
                for (int ox = 0; ox < ow; ox++, o += 4, m += 2 * stride, c += 8, p++)
                {
                    int coverage = coverageBytes[m] + coverageBytes[m + stride] + coverageBytes[m + maskUp] + coverageBytes[m + maskUp + stride];
                    int alpha = (2 * coverage + 4) >> 3; // MaskEncoding.AlphaOf(coverage, 4)
                    if (mask != null) mask[p] = (byte)alpha;
                    if (alpha == 0)
                    {
                        rgba[o] = 0;
                        rgba[o + 1] = 0;
                        rgba[o + 2] = 0;
                        rgba[o + 3] = 0;
                        continue;
                    }
                    float r = decode[colorBytes[c]] + decode[colorBytes[c + 4]] + decode[colorBytes[c + colourUp]] + decode[colorBytes[c + colourUp + 4]];
                    float g = decode[colorBytes[c + 1]] + decode[colorBytes[c + 5]] + decode[colorBytes[c + colourUp + 1]] + decode[colorBytes[c + colourUp + 5]];
                    float b = decode[colorBytes[c + 2]] + decode[colorBytes[c + 6]] + decode[colorBytes[c + colourUp + 2]] + decode[colorBytes[c + colourUp + 6]];
                    if (coverage == 4 * 255)
                    {
                        // The mean of four values in [0, 1] stays in [0, 1]: no clamp.
                        r *= 0.25f;
                        g *= 0.25f;
                        b *= 0.25f;
                    }
                    else
                    {
                        float unpremultiply = 255f / coverage;
                        r *= unpremultiply;
                        g *= unpremultiply;
                        b *= unpremultiply;
                        r = r > 1 ? 1 : r > 0 ? r : 0;
                        g = g > 1 ? 1 : g > 0 ? g : 0;
                        b = b > 1 ? 1 : b > 0 ? b : 0;
                    }
                    int e = bucket[(int)(r * buckets)];
                    rgba[o] = r >= threshold[e + 1] ? (byte)(e + 1) : (byte)e;
                    e = bucket[(int)(g * buckets)];
                    rgba[o + 1] = g >= threshold[e + 1] ? (byte)(e + 1) : (byte)e;
                    e = bucket[(int)(b * buckets)];
                    rgba[o + 2] = b >= threshold[e + 1] ? (byte)(e + 1) : (byte)e;
                    rgba[o + 3] = (byte)alpha;
                }
            }
        }

        static void WriteBackground(byte[] rgba, int o, Background background)
        {
            if (background.IsSolid)
            {
                rgba[o] = Srgb.Encode(background.LinearR);
                rgba[o + 1] = Srgb.Encode(background.LinearG);
                rgba[o + 2] = Srgb.Encode(background.LinearB);
                rgba[o + 3] = 255;
            }
            else
            {
                rgba[o] = 0;
                rgba[o + 1] = 0;
                rgba[o + 2] = 0;
                rgba[o + 3] = 0;
            }
        }

        // NaN (e.g. from a broken shader) becomes 0 rather than poisoning the encode.
        static float Clamp01(float v) => v > 1 ? 1 : v > 0 ? v : 0;
    }
}
