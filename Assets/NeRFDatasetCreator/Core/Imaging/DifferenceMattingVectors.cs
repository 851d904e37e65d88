using System;
using System.Numerics;
using System.Runtime.InteropServices;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The k = 2, transparent, linear-light case of <see cref="DifferenceMatting.Resolve"/> several output pixels at a
    /// time with <see cref="Vector{T}"/>, for runtimes that accelerate it (.NET; Mono, Unity's editor runtime, does not
    /// and keeps <see cref="DifferenceMatting.TwoByTwoRun"/>). The same bytes: each block is background, fully covered
    /// or neither exactly as the scalar word tests say, a covered block's colour is the same float sums in the same
    /// order, and every other block goes through the scalar run.
    /// </summary>
    static class DifferenceMattingVectors
    {
        const ulong RgbLanes = DifferenceMatting.RgbLanes, WhiteRgb = DifferenceMatting.WhiteRgb, ExponentLanes = DifferenceMatting.ExponentLanes,
            ExponentCarry = DifferenceMatting.ExponentCarry, LaneTops = DifferenceMatting.LaneTops;

        /// <summary>
        /// One vector holds S = <see cref="Vector{T}.Count"/> samples of 64 bits (4 with AVX2), i.e. the top (or bottom)
        /// row of S / 2 blocks. Per group of S / 2 output pixels: four loads and a few operations say whether every block
        /// is background (then the pixels are 0) or fully covered by halves that are +0 or positive normal numbers.
        /// Then the colour sums: such a half h is the float with bits h·2¹³ times 2¹¹² (exact), so the four samples'
        /// halves become floats with a widening, an integer and a float multiplication, and K₀ + K₁ is one lane-wise addition of the row with the row loaded one sample later (no
        /// shuffle in .NET Standard 2.1's Vector API): lanes 0–3 of each block's slot hold ((K₀ + K₁) + K₂) + K₃ as the
        /// scalar path sums them (its leading +0 + K₀ is K₀ for K₀ ≥ +0). The sRGB encode's table lookups stay scalar.
        /// Groups with any other block, and the row's last pixels, go through <see cref="DifferenceMatting.TwoByTwoRun"/>.
        /// Diagnostics as the scalar run counts them: a background group has nothing to count, a covered group's samples
        /// are stray wherever the mask is 0, and the scalar run counts the rest.
        /// </summary>
        internal static void ResolveTransparentLinearTwoByTwo(ushort[] black, ushort[] white, byte[] rgba, int width, int ow, int oh,
            byte[] mask, int maskBytes, ref int darker, ref int stray)
        {
            Span<ulong> blackWords = MemoryMarshal.Cast<ushort, ulong>(new Span<ushort>(black));
            Span<ulong> whiteWords = MemoryMarshal.Cast<ushort, ulong>(new Span<ushort>(white));
            Span<uint> pixels = MemoryMarshal.Cast<byte, uint>(new Span<byte>(rgba));
            int samples = Vector<ulong>.Count, group = samples / 2;
            var rgbLanes = new Vector<ulong>(RgbLanes);
            var whiteRgb = new Vector<ulong>(WhiteRgb);
            var exponentLanes = new Vector<ulong>(ExponentLanes);
            var exponentCarry = new Vector<ulong>(ExponentCarry);
            var laneTops = new Vector<ulong>(LaneTops);
            var smallestNormal = new Vector<short>(0x0400);
            // The row loaded one sample later: its last sample belongs to the next group and its alpha lanes are
            // ignored, so both are cleared (an unknown half could be a subnormal, slow to multiply on some CPUs).
            Span<ulong> keep = stackalloc ulong[samples];
            for (int i = 0; i < samples - 1; i++) keep[i] = RgbLanes;
            var laterKeep = new Vector<ulong>(keep);
            var toFloatBits = new Vector<uint>(1u << 13);
            var halfScale = new Vector<float>(5.192296858534828e33f); // 2^112
            var quarter = new Vector<float>(0.25f);
            var buckets = new Vector<float>(Srgb.EncodeBucketScale);
            // Lanes read back one by one for the table lookups (two vectors: the widened low and high halves).
            Span<float> values = stackalloc float[2 * Vector<float>.Count];
            Span<int> indices = stackalloc int[2 * Vector<int>.Count];
            Span<Vector<float>> valueVectors = MemoryMarshal.Cast<float, Vector<float>>(values);
            Span<Vector<int>> indexVectors = MemoryMarshal.Cast<int, Vector<int>>(indices);
            byte[] encodeTable = Srgb.EncodeBucketLookup;
            float[] threshold = Srgb.EncodeThresholdLookup;
            for (int oy = 0; oy < oh; oy++)
            {
                int rowFirst = RowOrder.SourceBlockRow(oy, oh, 2) * width;
                int o = oy * ow, ox = 0;
                // Strictly before the last group: the later-by-one load reads one sample past the group.
                for (; ox + group < ow; ox += group, o += group)
                {
                    int first = rowFirst + ox * 2, below = first + width;
                    var blackTop = new Vector<ulong>(blackWords.Slice(first, samples));
                    var blackBottom = new Vector<ulong>(blackWords.Slice(below, samples));
                    var whiteTop = new Vector<ulong>(whiteWords.Slice(first, samples));
                    var whiteBottom = new Vector<ulong>(whiteWords.Slice(below, samples));
                    if (Vector.EqualsAll((blackTop | blackBottom) & rgbLanes, Vector<ulong>.Zero)
                        && Vector.EqualsAll(whiteTop & rgbLanes, whiteRgb) && Vector.EqualsAll(whiteBottom & rgbLanes, whiteRgb))
                    {
                        pixels.Slice(o, group).Clear();
                        continue;
                    }
                    // Equal RGB in both renders, and per lane neither an all-ones exponent (the carry reaches the top
                    // bit) nor a sign bit: covered, finite, ≥ +0. And no subnormal half (0 < h < 0x400): its float bits
                    // would be a subnormal float, which x64 CPUs multiply through a microcode assist ~100× slower
                    // (measured: a frame of them took 125 ms instead of 11); the scalar run reads the table instead.
                    var topHalves = Vector.AsVectorInt16(blackTop & rgbLanes);
                    var bottomHalves = Vector.AsVectorInt16(blackBottom & rgbLanes);
                    var subnormal = (Vector.GreaterThan(topHalves, Vector<short>.Zero) & Vector.LessThan(topHalves, smallestNormal))
                                    | (Vector.GreaterThan(bottomHalves, Vector<short>.Zero) & Vector.LessThan(bottomHalves, smallestNormal));
                    if (!Vector.EqualsAll((((blackTop ^ whiteTop) | (blackBottom ^ whiteBottom)) & rgbLanes)
                                          | ((((blackTop & exponentLanes) + exponentCarry) | ((blackBottom & exponentLanes) + exponentCarry)
                                              | blackTop | blackBottom) & laneTops)
                                          | Vector.AsVectorUInt64(subnormal), Vector<ulong>.Zero))
                    {
                        DifferenceMatting.TwoByTwoRun(black, white, blackWords, whiteWords, pixels, first, width, o, group, mask, maskBytes, ref darker, ref stray);
                        continue;
                    }
                    if (mask != null)
                    {
                        // Covered (W = K): every sample the mask leaves empty differs from the clear pair. With a 1-byte
                        // mask and 4 samples a row, two 32-bit reads and the zero-byte test ((x − 0x01010101) & ~x &
                        // 0x80808080 is non-zero exactly when some byte is 0) skip the usual all-covered group.
                        bool countBytes = maskBytes != 1 || samples != 4;
                        if (!countBytes)
                        {
                            uint top = BitConverter.ToUInt32(mask, first), bottom = BitConverter.ToUInt32(mask, below);
                            countBytes = ((((top - 0x0101_0101u) & ~top) | ((bottom - 0x0101_0101u) & ~bottom)) & 0x8080_8080u) != 0;
                        }
                        if (countBytes)
                            for (int s = 0, t = first * maskBytes, u = below * maskBytes; s < samples; s++, t += maskBytes, u += maskBytes)
                            {
                                if (mask[t] == 0) stray++;
                                if (mask[u] == 0) stray++;
                            }
                    }
                    var topLater = new Vector<ulong>(blackWords.Slice(first + 1, samples)) & laterKeep;
                    var bottomLater = new Vector<ulong>(blackWords.Slice(below + 1, samples)) & laterKeep;
                    Vector.Widen(Vector.AsVectorUInt16(blackTop & rgbLanes), out Vector<uint> k0Low, out Vector<uint> k0High);
                    Vector.Widen(Vector.AsVectorUInt16(topLater), out Vector<uint> k1Low, out Vector<uint> k1High);
                    Vector.Widen(Vector.AsVectorUInt16(blackBottom & rgbLanes), out Vector<uint> k2Low, out Vector<uint> k2High);
                    Vector.Widen(Vector.AsVectorUInt16(bottomLater), out Vector<uint> k3Low, out Vector<uint> k3High);
                    var sumLow = ((Vector.AsVectorSingle(k0Low * toFloatBits) * halfScale + Vector.AsVectorSingle(k1Low * toFloatBits) * halfScale)
                                  + Vector.AsVectorSingle(k2Low * toFloatBits) * halfScale) + Vector.AsVectorSingle(k3Low * toFloatBits) * halfScale;
                    var sumHigh = ((Vector.AsVectorSingle(k0High * toFloatBits) * halfScale + Vector.AsVectorSingle(k1High * toFloatBits) * halfScale)
                                   + Vector.AsVectorSingle(k2High * toFloatBits) * halfScale) + Vector.AsVectorSingle(k3High * toFloatBits) * halfScale;
                    // Alpha 255 and colour sum/4 (1/4 exact). Values ≥ 1 become 1: bucket 65 536 encodes to 255 and
                    // threshold[256] is +∞, the bytes the scalar "v ≥ 1 → 255" gives; 0 gives bucket 0, byte 0.
                    var low = Vector.Min(sumLow * quarter, Vector<float>.One);
                    var high = Vector.Min(sumHigh * quarter, Vector<float>.One);
                    valueVectors[0] = low;
                    valueVectors[1] = high;
                    indexVectors[0] = Vector.ConvertToInt32(low * buckets);
                    indexVectors[1] = Vector.ConvertToInt32(high * buckets);
                    // Block i of the group starts at sample 2i: lanes 8i, 8i + 1, 8i + 2 of the two vectors in a row.
                    for (int i = 0, at = 0; i < group; i++, at += 8)
                    {
                        int e = encodeTable[indices[at]];
                        uint pixel = 0xFF00_0000u | (values[at] >= threshold[e + 1] ? (uint)(e + 1) : (uint)e);
                        e = encodeTable[indices[at + 1]];
                        pixel |= (values[at + 1] >= threshold[e + 1] ? (uint)(e + 1) : (uint)e) << 8;
                        e = encodeTable[indices[at + 2]];
                        pixel |= (values[at + 2] >= threshold[e + 1] ? (uint)(e + 1) : (uint)e) << 16;
                        pixels[o + i] = pixel;
                    }
                }
                DifferenceMatting.TwoByTwoRun(black, white, blackWords, whiteWords, pixels, rowFirst + ox * 2, width, o, ow - ox,
                    mask, maskBytes, ref darker, ref stray);
            }
        }
    }
}
