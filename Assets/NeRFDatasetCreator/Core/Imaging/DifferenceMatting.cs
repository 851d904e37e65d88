namespace NerfDatasetCreator
{
    /// <summary>
    /// The colour image from two renders of the same view, one over a black clear (K) and one over a white clear (W):
    /// per-pixel alpha and straight colour, k×k box-filtered in linear light, as 8-bit sRGB RGBA, top row first.
    /// <para>
    /// Why it works for every kind of content: whatever a shader does — opaque, alpha-clipped, two-sided, blended glass,
    /// particles, sprites, lines, terrain — the GPU composites it over the clear colour B as out = F + T·B, where F is
    /// what the content adds and T how much of B still shows through (per channel). Over black out = F, over white
    /// out = F + T, so T = W − K and F = K, in the space the GPU blends in (linear light in a Linear project, gamma
    /// space in a Gamma one). Alpha is 1 − T: the coverage of what the colour pass shows, anti-aliased by the
    /// supersampling, with no help from the lit shader's alpha or a separate mask pass.
    /// </para>
    /// <para>
    /// One alpha for three channels: T differs per channel only for tinted transmission (coloured glass drawn with a
    /// multiplicative blend). A straight-alpha PNG has one alpha, so the solve takes the least-squares fit over the two
    /// backgrounds: alpha = 1 − mean(T) and premultiplied colour (K + W − (1 − alpha))/2, the mean of what black and white
    /// say. For ordinary blending (one alpha for all channels) this is exact; for tinted glass the error is split evenly
    /// between dark and light backgrounds. The mean, not the max, because the max of three noisy estimates is biased
    /// upwards (empty pixels would get alpha > 0) while the mean is unbiased and a third as noisy. Light added without
    /// covering anything (additive particles, glows: K = F, W = 1 + F) has alpha 0 and cannot be stored in a
    /// straight-alpha pixel on its own; over covered content it is kept in the colour.
    /// </para>
    /// </summary>
    public static class DifferenceMatting
    {
        /// <summary>
        /// Writes OutputWidth×OutputHeight×4 bytes (R G B A) into <paramref name="rgba"/> from
        /// <see cref="RawFrame.ColorOverBlack"/> and <see cref="RawFrame.ColorOverWhite"/>. Transparent background (the
        /// default): alpha = round(255·mean alpha), colour = Σ premultiplied / Σ alpha in linear light, clamped to [0, 1],
        /// sRGB-encoded; alpha 0 gives (0,0,0,0). Solid background B: each sample is composited exactly, per channel,
        /// as K + T·B — what rendering over B would have given, tinted glass included — averaged in linear light, alpha 255.
        /// <para>
        /// Returns the samples the matting model cannot explain (<see cref="MattingDiagnostics"/>): over white darker
        /// than over black, and — when the frame has a <see cref="RawFrame.Mask"/> and <paramref name="checkBackground"/>
        /// — samples outside the mask's geometry that are not exactly the clear colours. Pass false when the background
        /// is not a clear (a skybox rendered into both halves). The bytes written do not depend on either.
        /// </para>
        /// </summary>
        public static MattingDiagnostics Resolve(RawFrame frame, byte[] rgba, Background background = default, bool checkBackground = true)
        {
            var problems = frame.Validate();
            if (frame.ColorOverBlack == null && frame.ColorOverWhite == null)
                problems.Add(new ValidationProblem("frame.ColorOverBlack", "null", "is required: difference matting reads the colour pass over black and over white.",
                    "Read back both colour renders into frame.ColorOverBlack and frame.ColorOverWhite."));
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            int ow = frame.OutputWidth, oh = frame.OutputHeight;
            RawFrame.RequireOutput("rgba", rgba, (long)ow * oh * 4, "bytes (4 per output pixel)");

            int k = frame.Supersampling, width = frame.Width;
            float inverseSamples = 1f / (k * k);
            ushort[] black = frame.ColorOverBlack, white = frame.ColorOverWhite;
            byte[] mask = checkBackground ? frame.Mask : null;
            int maskBytes = frame.MaskBytesPerPixel, darker = 0, stray = 0;
            var diagnostics = new MattingDiagnostics { Samples = (long)width * frame.Height, BackgroundChecked = mask != null };
            if (!background.IsSolid && !frame.ColorIsGammaEncoded)
            {
                // One RGBA half pixel is one 64-bit word on a little-endian machine (every Unity editor platform).
                // Several blocks at a time where Vector<T> is accelerated (.NET); Mono, Unity's runtime, takes the scalar path.
                if (k == 2 && System.BitConverter.IsLittleEndian && System.Numerics.Vector.IsHardwareAccelerated)
                    DifferenceMattingVectors.ResolveTransparentLinearTwoByTwo(black, white, rgba, width, ow, oh, mask, maskBytes, ref darker, ref stray);
                else if (k == 2 && System.BitConverter.IsLittleEndian) ResolveTransparentLinearTwoByTwo(black, white, rgba, width, ow, oh, mask, maskBytes, ref darker, ref stray);
                else ResolveTransparentLinear(black, white, rgba, k, width, ow, oh, mask, maskBytes, ref darker, ref stray);
                diagnostics.DarkerOverWhite = darker;
                diagnostics.StrayBackground = stray;
                return diagnostics;
            }
            float[] half = HalfFloat.Lookup;
            bool gamma = frame.ColorIsGammaEncoded;
            // The solid background in the space the GPU blends in: T·B must be added where the blend happened.
            float br = background.LinearR, bg = background.LinearG, bb = background.LinearB;
            if (gamma) { br = ToGamma(br); bg = ToGamma(bg); bb = ToGamma(bb); }

            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                int o = oy * ow * 4;
                for (int ox = 0; ox < ow; ox++, o += 4)
                {
                    int first = blockRow * width + ox * k;
                    float alphaSum = 0, r = 0, g = 0, b = 0;
                    for (int dy = 0; dy < k; dy++)
                    {
                        int c = (first + dy * width) * 4;
                        for (int dx = 0; dx < k; dx++, c += 4)
                        {
                            float kr = half[black[c]], kg = half[black[c + 1]], kb = half[black[c + 2]];
                            float tr = half[white[c]] - kr, tg = half[white[c + 1]] - kg, tb = half[white[c + 2]] - kb;
                            // Diagnostics (MattingDiagnostics): the same per-sample tests as SumSamples.
                            if (tr < -MattingDiagnostics.DarkerTolerance || tg < -MattingDiagnostics.DarkerTolerance || tb < -MattingDiagnostics.DarkerTolerance) darker++;
                            if (mask != null && mask[(c >> 2) * maskBytes] == 0
                                && (black[c] != 0 || black[c + 1] != 0 || black[c + 2] != 0 || white[c] != WhiteHalf || white[c + 1] != WhiteHalf || white[c + 2] != WhiteHalf))
                                stray++;
                            if (background.IsSolid)
                            {
                                r += Linear(kr + tr * br, gamma);
                                g += Linear(kg + tg * bg, gamma);
                                b += Linear(kb + tb * bb, gamma);
                                continue;
                            }
                            float a = Clamp01(1f - (tr + tg + tb) * (1f / 3f));
                            if (a <= 0) continue; // nothing covers this sample: it adds neither alpha nor colour
                            float t = 1f - a;
                            // Least-squares premultiplied colour: the mean of the over-black (K) and over-white (W − T) estimates.
                            float pr = (kr + kr + tr - t) * 0.5f, pg = (kg + kg + tg - t) * 0.5f, pb = (kb + kb + tb - t) * 0.5f;
                            if (gamma)
                            {
                                // Blended in gamma space: un-premultiply there, then weight the linear straight colour by alpha.
                                float inverse = 1f / a;
                                pr = a * Linear(Clamp01(pr * inverse), true);
                                pg = a * Linear(Clamp01(pg * inverse), true);
                                pb = a * Linear(Clamp01(pb * inverse), true);
                            }
                            alphaSum += a;
                            r += pr;
                            g += pg;
                            b += pb;
                        }
                    }

                    if (background.IsSolid)
                    {
                        rgba[o] = Srgb.Encode(r * inverseSamples);
                        rgba[o + 1] = Srgb.Encode(g * inverseSamples);
                        rgba[o + 2] = Srgb.Encode(b * inverseSamples);
                        rgba[o + 3] = 255;
                        continue;
                    }
                    // round(255·mean alpha), halves up.
                    int alpha = (int)(alphaSum * inverseSamples * 255f + 0.5f);
                    if (alpha <= 0)
                    {
                        rgba[o] = rgba[o + 1] = rgba[o + 2] = rgba[o + 3] = 0;
                        continue;
                    }
                    float unpremultiply = 1f / alphaSum;
                    rgba[o] = Srgb.Encode(r * unpremultiply);
                    rgba[o + 1] = Srgb.Encode(g * unpremultiply);
                    rgba[o + 2] = Srgb.Encode(b * unpremultiply);
                    rgba[o + 3] = alpha > 255 ? (byte)255 : (byte)alpha;
                }
            }
            diagnostics.DarkerOverWhite = darker;
            diagnostics.StrayBackground = stray;
            return diagnostics;
        }

        /// <summary>The clear white, 1.0, as an IEEE half.</summary>
        const ushort WhiteHalf = 0x3C00;

        /// <summary>
        /// The transparent-background, linear-light case of <see cref="Resolve"/> (a Linear project's capture), with
        /// the same arithmetic in the same order, so the bytes are identical, written out without calls (Mono does not
        /// inline small methods). k = 2 on a little-endian machine — the default capture — takes
        /// <see cref="ResolveTransparentLinearTwoByTwo"/> instead.
        /// </summary>
        static void ResolveTransparentLinear(ushort[] black, ushort[] white, byte[] rgba, int k, int width, int ow, int oh,
            byte[] mask, int maskBytes, ref int darker, ref int stray)
        {
            float[] half = HalfFloat.Lookup;
            byte[] encodeTable = Srgb.EncodeBucketLookup;
            float[] threshold = Srgb.EncodeThresholdLookup;
            float inverseSamples = 1f / (k * k);
            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                int o = oy * ow * 4;
                for (int ox = 0; ox < ow; ox++, o += 4)
                {
                    int first = blockRow * width + ox * k;
                    float alphaSum = 0, r = 0, g = 0, b = 0;
                    SumSamples(black, white, half, first, width, k, ref alphaSum, ref r, ref g, ref b, mask, maskBytes, ref darker, ref stray);

                    // round(255·mean alpha), halves up.
                    int alpha = (int)(alphaSum * inverseSamples * 255f + 0.5f);
                    if (alpha <= 0)
                    {
                        rgba[o] = rgba[o + 1] = rgba[o + 2] = rgba[o + 3] = 0;
                        continue;
                    }
                    float unpremultiply = 1f / alphaSum;
                    // Srgb.Encode written out.
                    float v = r * unpremultiply;
                    int e;
                    if (!(v > 0)) rgba[o] = 0;
                    else if (v >= 1) rgba[o] = 255;
                    else { e = encodeTable[(int)(v * Srgb.EncodeBucketScale)]; rgba[o] = v >= threshold[e + 1] ? (byte)(e + 1) : (byte)e; }
                    v = g * unpremultiply;
                    if (!(v > 0)) rgba[o + 1] = 0;
                    else if (v >= 1) rgba[o + 1] = 255;
                    else { e = encodeTable[(int)(v * Srgb.EncodeBucketScale)]; rgba[o + 1] = v >= threshold[e + 1] ? (byte)(e + 1) : (byte)e; }
                    v = b * unpremultiply;
                    if (!(v > 0)) rgba[o + 2] = 0;
                    else if (v >= 1) rgba[o + 2] = 255;
                    else { e = encodeTable[(int)(v * Srgb.EncodeBucketScale)]; rgba[o + 2] = v >= threshold[e + 1] ? (byte)(e + 1) : (byte)e; }
                    rgba[o + 3] = alpha > 255 ? (byte)255 : (byte)alpha;
                }
            }
        }

        // The R, G, B halves of one RGBA half pixel read as a little-endian 64-bit word (alpha, the top 16 bits, is
        // ignored); white's RGB; each lane's exponent field; the carry that reaches a lane's top bit only from an
        // all-ones exponent (infinity or NaN).
        internal const ulong RgbLanes = 0xFFFF_FFFF_FFFF, WhiteRgb = 0x3C00_3C00_3C00, ExponentLanes = 0x7C00_7C00_7C00,
            ExponentCarry = 0x0400_0400_0400, LaneTops = 0x8000_8000_8000;

        /// <summary>
        /// <see cref="ResolveTransparentLinear"/> for k = 2 (the default capture), with the same bytes, one output row
        /// at a time through <see cref="TwoByTwoRun"/>.
        /// </summary>
        static void ResolveTransparentLinearTwoByTwo(ushort[] black, ushort[] white, byte[] rgba, int width, int ow, int oh,
            byte[] mask, int maskBytes, ref int darker, ref int stray)
        {
            System.Span<ulong> blackWords = System.Runtime.InteropServices.MemoryMarshal.Cast<ushort, ulong>(new System.Span<ushort>(black));
            System.Span<ulong> whiteWords = System.Runtime.InteropServices.MemoryMarshal.Cast<ushort, ulong>(new System.Span<ushort>(white));
            // One output pixel R, G, B, A is one little-endian 32-bit word.
            System.Span<uint> pixels = System.Runtime.InteropServices.MemoryMarshal.Cast<byte, uint>(new System.Span<byte>(rgba));
            for (int oy = 0; oy < oh; oy++)
                TwoByTwoRun(black, white, blackWords, whiteWords, pixels, RowOrder.SourceBlockRow(oy, oh, 2) * width, width, oy * ow, ow,
                    mask, maskBytes, ref darker, ref stray);
        }

        /// <summary>
        /// <paramref name="count"/> output pixels from <paramref name="o"/> on, whose first block starts at sample
        /// <paramref name="first"/> (the next ones 2 samples apart): each sample is read as one 64-bit word
        /// (<see cref="System.Runtime.InteropServices.MemoryMarshal.Cast{TFrom,TTo}(System.Span{TFrom})"/>, no copy, no
        /// unsafe code), so the background test (black RGB all +0, white RGB all 1) and the fully covered test (equal
        /// RGB, no infinite or NaN lane, tested for three lanes at once) are 8 loads and a few ALU operations per block
        /// instead of 24 to 48 loads; the covered block's halves come from the words already read. Written out without
        /// calls: Mono does not inline. Diagnostics: a background block has nothing to count; a covered block's
        /// samples (W = K) are never darker and are stray wherever the mask is 0; other blocks count per sample in
        /// <see cref="SumSamples"/>. Counts are kept in locals and added to <paramref name="darker"/> and
        /// <paramref name="stray"/> once per run.
        /// </summary>
        internal static void TwoByTwoRun(ushort[] black, ushort[] white, System.Span<ulong> blackWords, System.Span<ulong> whiteWords,
            System.Span<uint> pixels, int first, int width, int o, int count, byte[] mask, int maskBytes, ref int darker, ref int stray)
        {
            int darkerHere = 0, strayHere = 0;
            float[] half = HalfFloat.Lookup;
            byte[] encodeTable = Srgb.EncodeBucketLookup;
            float[] threshold = Srgb.EncodeThresholdLookup;
            for (int end = o + count; o < end; o++, first += 2)
            {
                int below = first + width;
                ulong b0 = blackWords[first], b1 = blackWords[first + 1], b2 = blackWords[below], b3 = blackWords[below + 1];
                ulong w0 = whiteWords[first], w1 = whiteWords[first + 1], w2 = whiteWords[below], w3 = whiteWords[below + 1];
                float r = 0, g = 0, b = 0, unpremultiply;
                uint alpha;
                if (((b0 | b1 | b2 | b3) & RgbLanes) == 0
                    && (w0 & RgbLanes) == WhiteRgb && (w1 & RgbLanes) == WhiteRgb && (w2 & RgbLanes) == WhiteRgb && (w3 & RgbLanes) == WhiteRgb)
                {
                    pixels[o] = 0;
                    continue;
                }
                if ((((b0 ^ w0) | (b1 ^ w1) | (b2 ^ w2) | (b3 ^ w3)) & RgbLanes) == 0
                    && ((((b0 & ExponentLanes) + ExponentCarry) | ((b1 & ExponentLanes) + ExponentCarry)
                         | ((b2 & ExponentLanes) + ExponentCarry) | ((b3 & ExponentLanes) + ExponentCarry)) & LaneTops) == 0)
                {
                    // Per sample a = 1, t = 0 and (K + K + 0 − 0)·0.5 = K exactly; sums from +0 in the same order.
                    // Alpha sum 4: round(255·4/4) = 255, and 1/4 is exact.
                    r += half[(int)(b0 & 0xFFFF)];
                    g += half[(int)(b0 >> 16) & 0xFFFF];
                    b += half[(int)(b0 >> 32) & 0xFFFF];
                    r += half[(int)(b1 & 0xFFFF)];
                    g += half[(int)(b1 >> 16) & 0xFFFF];
                    b += half[(int)(b1 >> 32) & 0xFFFF];
                    r += half[(int)(b2 & 0xFFFF)];
                    g += half[(int)(b2 >> 16) & 0xFFFF];
                    b += half[(int)(b2 >> 32) & 0xFFFF];
                    r += half[(int)(b3 & 0xFFFF)];
                    g += half[(int)(b3 >> 16) & 0xFFFF];
                    b += half[(int)(b3 >> 32) & 0xFFFF];
                    alpha = 255;
                    unpremultiply = 0.25f;
                    if (mask != null)
                    {
                        // Covered: W = K, so each sample differs from the clear pair; stray where the mask is empty. One
                        // branch for the usual all-covered block (255 & 255 & 255 & 255 ≠ 0); a zero AND counts byte by byte.
                        int m0 = mask[first * maskBytes], m1 = mask[(first + 1) * maskBytes], m2 = mask[below * maskBytes], m3 = mask[(below + 1) * maskBytes];
                        if ((m0 & m1 & m2 & m3) == 0)
                        {
                            if (m0 == 0) strayHere++;
                            if (m1 == 0) strayHere++;
                            if (m2 == 0) strayHere++;
                            if (m3 == 0) strayHere++;
                        }
                    }
                }
                else
                {
                    float alphaSum = 0;
                    SumSamples(black, white, half, first, width, 2, ref alphaSum, ref r, ref g, ref b, mask, maskBytes, ref darkerHere, ref strayHere);
                    // round(255·mean alpha), halves up.
                    int rounded = (int)(alphaSum * 0.25f * 255f + 0.5f);
                    if (rounded <= 0)
                    {
                        pixels[o] = 0;
                        continue;
                    }
                    alpha = rounded > 255 ? 255u : (uint)rounded;
                    unpremultiply = 1f / alphaSum;
                }

                // Srgb.Encode written out.
                uint pixel = alpha << 24;
                int e;
                float v = r * unpremultiply;
                if (v >= 1) pixel |= 255;
                else if (v > 0)
                {
                    e = encodeTable[(int)(v * Srgb.EncodeBucketScale)];
                    if (v >= threshold[e + 1]) e++;
                    pixel |= (uint)e;
                }
                v = g * unpremultiply;
                if (v >= 1) pixel |= 255 << 8;
                else if (v > 0)
                {
                    e = encodeTable[(int)(v * Srgb.EncodeBucketScale)];
                    if (v >= threshold[e + 1]) e++;
                    pixel |= (uint)e << 8;
                }
                v = b * unpremultiply;
                if (v >= 1) pixel |= 255 << 16;
                else if (v > 0)
                {
                    e = encodeTable[(int)(v * Srgb.EncodeBucketScale)];
                    if (v >= threshold[e + 1]) e++;
                    pixel |= (uint)e << 16;
                }
                pixels[o] = pixel;
            }
            darker += darkerHere;
            stray += strayHere;
        }

        /// <summary>
        /// The per-sample solve of <see cref="Resolve"/> (transparent, linear) over one k×k block, without calls, and the
        /// per-sample diagnostics: over white darker than over black by more than the tolerance in any channel; outside
        /// the mask and not exactly the clear pair (black +0, white 1.0: the halves, bit for bit, as the block tests read them).
        /// </summary>
        static void SumSamples(ushort[] black, ushort[] white, float[] half, int first, int width, int k,
            ref float alphaSum, ref float r, ref float g, ref float b, byte[] mask, int maskBytes, ref int darker, ref int stray)
        {
            float sa = alphaSum, sr = r, sg = g, sb = b;
            for (int dy = 0; dy < k; dy++)
            {
                int c = (first + dy * width) * 4;
                for (int dx = 0; dx < k; dx++, c += 4)
                {
                    float kr = half[black[c]], kg = half[black[c + 1]], kb = half[black[c + 2]];
                    float tr = half[white[c]] - kr, tg = half[white[c + 1]] - kg, tb = half[white[c + 2]] - kb;
                    if (tr < -MattingDiagnostics.DarkerTolerance || tg < -MattingDiagnostics.DarkerTolerance || tb < -MattingDiagnostics.DarkerTolerance) darker++;
                    if (mask != null && mask[(c >> 2) * maskBytes] == 0
                        && (black[c] != 0 || black[c + 1] != 0 || black[c + 2] != 0 || white[c] != WhiteHalf || white[c + 1] != WhiteHalf || white[c + 2] != WhiteHalf))
                        stray++;
                    float a = 1f - (tr + tg + tb) * (1f / 3f);
                    a = a > 1 ? 1 : a > 0 ? a : 0; // Clamp01
                    if (a <= 0) continue;
                    float t = 1f - a;
                    sa += a;
                    sr += (kr + kr + tr - t) * 0.5f;
                    sg += (kg + kg + tg - t) * 0.5f;
                    sb += (kb + kb + tb - t) * 0.5f;
                }
            }
            alphaSum = sa;
            r = sr;
            g = sg;
            b = sb;
        }

        // NaN (a broken shader) becomes 0 rather than poisoning the sums.
        static float Clamp01(float v) => v > 1 ? 1 : v > 0 ? v : 0;

        static float Linear(float value, bool gamma) => gamma ? GammaToLinear(value) : value;

        const int GammaSegments = 4096;
        static readonly float[] GammaTable = BuildGammaTable();

        static float[] BuildGammaTable()
        {
            var table = new float[GammaSegments + 2];
            for (int i = 0; i <= GammaSegments; i++) table[i] = (float)Srgb.DecodeExact(i / (double)GammaSegments);
            table[GammaSegments + 1] = table[GammaSegments];
            return table;
        }

        /// <summary>
        /// The sRGB decode of a gamma-space value, clamped to [0, 1], by linear interpolation in a 4097-entry table
        /// (error below 3e-8: the curve's second derivative is under 3 and the step 1/4096).
        /// </summary>
        internal static float GammaToLinear(float value)
        {
            if (!(value > 0)) return 0;
            if (value >= 1) return 1;
            float x = value * GammaSegments;
            int i = (int)x;
            float f = x - i;
            return GammaTable[i] + (GammaTable[i + 1] - GammaTable[i]) * f;
        }

        static float ToGamma(float linear) => (float)Srgb.EncodeExact(linear);
    }
}
