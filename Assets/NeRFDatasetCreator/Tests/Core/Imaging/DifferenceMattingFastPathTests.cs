using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The transparent, linear-light path of <see cref="DifferenceMatting.Resolve"/> (written out without calls, with
    /// whole-block tests for the background and for fully covered blocks at k = 2) must give exactly the bytes of
    /// the straightforward per-sample loop it replaced, kept here as <see cref="Reference"/>: on blocks that are
    /// empty, fully covered, partly covered, tinted, negative, subnormal, ±0, infinite and NaN, for k = 1, 2, 3.
    /// </summary>
    public class DifferenceMattingFastPathTests
    {
        [TestCase(1, 0)]
        [TestCase(2, 1)]
        [TestCase(2, 2)]
        [TestCase(2, 3)]
        [TestCase(3, 4)]
        public void BytesEqualThePerSampleLoop(int k, int seed)
        {
            const int outputWidth = 37, outputHeight = 23;
            var frame = new RawFrame(outputWidth * k, outputHeight * k, k);
            int samples = frame.Width * frame.Height;
            frame.ColorOverBlack = new ushort[samples * 4];
            frame.ColorOverWhite = new ushort[samples * 4];
            var random = new SeededRandom(seed);
            // Whole output blocks of one kind, so the k = 2 block tests see every case, plus mixed blocks.
            for (int oy = 0; oy < outputHeight; oy++)
                for (int ox = 0; ox < outputWidth; ox++)
                {
                    int kind = (int)(random.NextUInt64() % 10);
                    for (int dy = 0; dy < k; dy++)
                        for (int dx = 0; dx < k; dx++)
                        {
                            int p = ((oy * k + dy) * frame.Width + ox * k + dx) * 4;
                            int sampleKind = kind == 7 ? (int)(random.NextUInt64() % 7) : kind >= 8 ? kind - 8 : kind;
                            for (int c = 0; c < 4; c++)
                            {
                                Fill(sampleKind, c, random, out ushort black, out ushort white);
                                frame.ColorOverBlack[p + c] = black;
                                frame.ColorOverWhite[p + c] = white;
                            }
                        }
                    if (kind >= 8)
                    {
                        // Background or fully covered but for one channel of one sample: the block tests must see it.
                        int p = ((oy * k + (int)(random.NextUInt64() % (ulong)k)) * frame.Width + ox * k + (int)(random.NextUInt64() % (ulong)k)) * 4
                                + (int)(random.NextUInt64() % 3);
                        if (kind == 8) frame.ColorOverWhite[p] = (ushort)(random.NextUInt64() % 0x3C00);
                        else frame.ColorOverWhite[p] = (ushort)(frame.ColorOverBlack[p] ^ (1 + (int)(random.NextUInt64() % 0x3FF)));
                    }
                }

            var fast = new byte[outputWidth * outputHeight * 4];
            DifferenceMatting.Resolve(frame, fast);
            var expected = Reference(frame);
            Assert.That(fast, Is.EqualTo(expected));
            Assert.That(Array.FindAll(fast, b => b != 0).Length, Is.GreaterThan(fast.Length / 4), "the inputs cover something");
        }

        /// <summary>
        /// The k = 2 path tests a block's four samples as 64-bit words (R, G, B in the low 48 bits; alpha ignored) and
        /// the exponent fields of three lanes at once: every lane of every sample must count. Background and fully
        /// covered blocks with exactly one half changed — one bit of one lane of one sample, or one lane set to an
        /// infinity, a NaN, the largest finite half, −0 or a subnormal — give the bytes of the per-sample loop.
        /// </summary>
        [Test]
        public void TwoByTwoWordTestsSeeEveryLaneOfEverySample()
        {
            const int k = 2;
            ushort[] specials = { 0x7C00, 0xFC00, 0x7E00, 0x7C01, 0xFFFF, 0x7BFF, 0xFBFF, 0x8000, 0x0001, 0x3C00, 0x0000 };
            int cases = 4 * 4 * (16 * 2 + specials.Length * 2) + 8; // sample × lane (alpha included) × changes, + plain blocks
            int outputWidth = 41, outputHeight = (cases + outputWidth - 1) / outputWidth;
            var frame = new RawFrame(outputWidth * k, outputHeight * k, k);
            frame.ColorOverBlack = new ushort[frame.Width * frame.Height * 4];
            frame.ColorOverWhite = new ushort[frame.Width * frame.Height * 4];
            var random = new SeededRandom(11);
            int block = 0;
            void Block(bool covered, int sample, int lane, bool inWhite, Func<ushort, ushort> change)
            {
                int ox = block % outputWidth, oy = block / outputWidth;
                block++;
                for (int s = 0; s < 4; s++)
                {
                    int p = ((oy * k + s / 2) * frame.Width + ox * k + s % 2) * 4;
                    for (int c = 0; c < 4; c++)
                    {
                        ushort value = (ushort)(0x3000 | (int)(random.NextUInt64() % 0xC00));
                        frame.ColorOverBlack[p + c] = covered ? value : (ushort)0;
                        frame.ColorOverWhite[p + c] = covered ? value : (ushort)0x3C00;
                        if (c == 3) frame.ColorOverWhite[p + c] = (ushort)random.NextUInt64(); // alpha: anything
                    }
                    if (s == sample && change != null)
                    {
                        ushort[] target = inWhite ? frame.ColorOverWhite : frame.ColorOverBlack;
                        target[p + lane] = change(target[p + lane]);
                    }
                }
            }
            for (int sample = 0; sample < 4; sample++)
                for (int lane = 0; lane < 4; lane++)
                {
                    for (int bit = 0; bit < 16; bit++)
                    {
                        int flip = 1 << bit;
                        Block(false, sample, lane, bit % 2 == 0, v => (ushort)(v ^ flip));
                        Block(true, sample, lane, bit % 2 == 1, v => (ushort)(v ^ flip));
                    }
                    foreach (ushort special in specials)
                    {
                        Block(false, sample, lane, false, v => special);
                        int before = block;
                        Block(true, sample, lane, false, v => special);
                        // The same special value in both renders: still "equal", so only the exponent test can reject it.
                        int ox = before % outputWidth, oy = before / outputWidth;
                        int p = ((oy * k + sample / 2) * frame.Width + ox * k + sample % 2) * 4 + lane;
                        frame.ColorOverWhite[p] = frame.ColorOverBlack[p];
                    }
                }
            for (int i = 0; i < 4; i++)
            {
                Block(false, 0, 0, false, null);
                Block(true, 0, 0, false, null);
            }
            Assert.That(block, Is.EqualTo(cases));

            var fast = new byte[outputWidth * outputHeight * 4];
            DifferenceMatting.Resolve(frame, fast);
            Assert.That(fast, Is.EqualTo(Reference(frame)));
        }

        /// <summary>
        /// Where <see cref="System.Numerics.Vector.IsHardwareAccelerated"/> (this test's .NET on x64 or Arm64), k = 2
        /// takes several blocks at a time (two with AVX2): runs of background and of covered blocks — covered by
        /// halves from 0 and subnormals to the largest finite, 1 and above, −0 and negatives, infinities and NaN
        /// (which must leave the vector path) — for widths 1 to 33, so that groups straddle every position of a row and
        /// the row's last pixels fall outside whole groups; the sample after each group (which the vector path loads
        /// and clears) is anything. Same bytes as the per-sample loop.
        /// </summary>
        [Test]
        public void TwoByTwoGroupsOfBlocksEqualThePerSampleLoop()
        {
            const int k = 2;
            ushort[] covers = { 0x0000, 0x0001, 0x03FF, 0x0400, 0x2E66, 0x3BFF, 0x3C00, 0x3C01, 0x4400, 0x7BFF };
            ushort[] leaves = { 0x8000, 0xBC00, 0x8001, 0x7C00, 0xFC00, 0x7E00, 0x7C01 };
            var random = new SeededRandom(23);
            int checkedBlocks = 0;
            for (int outputWidth = 1; outputWidth <= 33; outputWidth++)
            {
                const int outputHeight = 5;
                var frame = new RawFrame(outputWidth * k, outputHeight * k, k);
                frame.ColorOverBlack = new ushort[frame.Width * frame.Height * 4];
                frame.ColorOverWhite = new ushort[frame.Width * frame.Height * 4];
                for (int i = 0; i < frame.ColorOverBlack.Length; i++)
                {
                    frame.ColorOverBlack[i] = (ushort)random.NextUInt64();
                    frame.ColorOverWhite[i] = (ushort)random.NextUInt64();
                }
                int kind = 0;
                for (int oy = 0; oy < outputHeight; oy++)
                    for (int ox = 0; ox < outputWidth; ox++)
                    {
                        // Runs: mostly the kind of the block before, so that whole groups are background or covered.
                        if (random.NextUInt64() % 4 == 0) kind = (int)(random.NextUInt64() % 5);
                        for (int s = 0; s < 4; s++)
                        {
                            int p = ((oy * k + s / 2) * frame.Width + ox * k + s % 2) * 4;
                            for (int c = 0; c < 3; c++)
                            {
                                ushort black, white;
                                switch (kind)
                                {
                                    case 0: black = 0; white = 0x3C00; break; // background
                                    case 1: black = white = (ushort)(0x3000 | (int)(random.NextUInt64() % 0xC00)); break; // covered, [0.125, 1)
                                    case 2: black = white = covers[random.NextUInt64() % (ulong)covers.Length]; break; // covered, edge values
                                    case 3: // covered but for a rare lane that leaves the vector path
                                        black = white = random.NextUInt64() % 24 == 0 ? leaves[random.NextUInt64() % (ulong)leaves.Length] : (ushort)0x3555;
                                        break;
                                    default: black = (ushort)(0x3000 | (int)(random.NextUInt64() % 0xC00)); white = 0x3C00; break; // partly covered
                                }
                                frame.ColorOverBlack[p + c] = black;
                                frame.ColorOverWhite[p + c] = white;
                            }
                        }
                        checkedBlocks++;
                    }
                var fast = new byte[outputWidth * outputHeight * 4];
                DifferenceMatting.Resolve(frame, fast);
                Assert.That(fast, Is.EqualTo(Reference(frame)), $"output width {outputWidth}");
            }
            Assert.That(checkedBlocks, Is.EqualTo(5 * 33 * 34 / 2));
        }

        static void Fill(int kind, int channel, SeededRandom random, out ushort black, out ushort white)
        {
            ushort any = (ushort)random.NextUInt64();
            ushort unit = (ushort)(0x3000 | (int)(random.NextUInt64() % 0xC00)); // [0.125, 1)
            switch (kind)
            {
                case 0: black = 0; white = 0x3C00; break; // background
                case 1: black = white = unit; break; // opaque
                case 2: black = white = any; break; // opaque, any bits: negatives, subnormals, infinities, NaN
                case 3: black = (ushort)(random.NextUInt64() % 2 == 0 ? 0x8000 : 0); white = 0x3C00; break; // ±0 background
                case 4: black = (ushort)(unit >> 1 & 0x3BFF); white = unit; break; // partly covered
                case 5: black = (ushort)(random.NextUInt64() % 0x400); white = (ushort)(0x3800 + random.NextUInt64() % 0x800); break; // subnormal over black
                default: black = any; white = (ushort)random.NextUInt64(); break; // anything
            }
            if (channel == 3) { black = (ushort)random.NextUInt64(); white = (ushort)random.NextUInt64(); } // alpha is ignored
        }

        /// <summary>The per-sample loop of DifferenceMatting.Resolve before its fast path (transparent, linear light).</summary>
        static byte[] Reference(RawFrame frame)
        {
            int ow = frame.OutputWidth, oh = frame.OutputHeight, k = frame.Supersampling, width = frame.Width;
            var rgba = new byte[ow * oh * 4];
            float inverseSamples = 1f / (k * k);
            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = (oh - 1 - oy) * k;
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
                            float kr = HalfFloat.ToFloat(frame.ColorOverBlack[c]), kg = HalfFloat.ToFloat(frame.ColorOverBlack[c + 1]), kb = HalfFloat.ToFloat(frame.ColorOverBlack[c + 2]);
                            float tr = HalfFloat.ToFloat(frame.ColorOverWhite[c]) - kr, tg = HalfFloat.ToFloat(frame.ColorOverWhite[c + 1]) - kg, tb = HalfFloat.ToFloat(frame.ColorOverWhite[c + 2]) - kb;
                            float a = Clamp01(1f - (tr + tg + tb) * (1f / 3f));
                            if (a <= 0) continue;
                            float t = 1f - a;
                            float pr = (kr + kr + tr - t) * 0.5f, pg = (kg + kg + tg - t) * 0.5f, pb = (kb + kb + tb - t) * 0.5f;
                            alphaSum += a;
                            r += pr;
                            g += pg;
                            b += pb;
                        }
                    }
                    int alpha = (int)(alphaSum * inverseSamples * 255f + 0.5f);
                    if (alpha <= 0) continue;
                    float unpremultiply = 1f / alphaSum;
                    rgba[o] = Srgb.Encode(r * unpremultiply);
                    rgba[o + 1] = Srgb.Encode(g * unpremultiply);
                    rgba[o + 2] = Srgb.Encode(b * unpremultiply);
                    rgba[o + 3] = alpha > 255 ? (byte)255 : (byte)alpha;
                }
            }
            return rgba;
        }

        static float Clamp01(float v) => v > 1 ? 1 : v > 0 ? v : 0;
    }
}
