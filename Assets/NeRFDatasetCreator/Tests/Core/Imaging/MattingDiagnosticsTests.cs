using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The counters of <see cref="DifferenceMatting.Resolve"/> (<see cref="MattingDiagnostics"/>): exact counts on
    /// hand-made blocks, whichever path resolves them — one block per row (no whole group for the vector path: the
    /// scalar word run), runs of equal blocks in wide rows (whole groups: the vector path where
    /// <see cref="System.Numerics.Vector.IsHardwareAccelerated"/>, the word run on Mono), k = 1 and 3 (the per-sample
    /// run), a Gamma project and a solid background (the general loop) — and, on random frames, the same counts as a
    /// plain per-sample reference, with the output bytes unchanged by the mask.
    /// </summary>
    public class MattingDiagnosticsTests
    {
        const ushort Zero = 0x0000, Half = 0x3800, One = 0x3C00, Quarter = 0x3400;

        /// <summary>One sample's R, G, B over black and over white, and its mask byte.</summary>
        struct Sample
        {
            public ushort K, W, KG, WG;
            public byte Mask;
            public static Sample Of(ushort k, ushort w, byte mask, ushort? kGreen = null, ushort? wGreen = null) =>
                new Sample { K = k, W = w, KG = kGreen ?? k, WG = wGreen ?? w, Mask = mask };
        }

        // The hand-made blocks (k = 2: four samples) and what each must count: (darker, stray).
        static readonly (Sample[] Samples, int Darker, int Stray)[] Blocks =
        {
            // Background, exactly the clear pair, outside the geometry: nothing.
            (Four(Sample.Of(Zero, One, 0)), 0, 0),
            // Covered, inside the geometry: nothing.
            (Four(Sample.Of(Half, Half, 255)), 0, 0),
            // Covered (W = K) where the mask is empty in two samples (first and last): a veil or a full-screen pass over the background.
            (new[] { Sample.Of(Half, Half, 0), Sample.Of(Half, Half, 255), Sample.Of(Half, Half, 255), Sample.Of(Half, Half, 0) }, 0, 2),
            // A vignette: white background dimmed to 0.5 (K = 0, W = 0.5, alpha 0.5) outside the geometry: all four.
            (Four(Sample.Of(Zero, Half, 0)), 0, 4),
            // Green over white darker than over black: by 16 half steps (counted), by exactly the tolerance 2⁻⁹ and by
            // 4 steps (not counted), and in red by 16 steps inside the geometry (counted; the mask does not matter).
            (new[]
            {
                Sample.Of(Quarter, One, 255, Half, 0x37F0), // G: 0.49609375 − 0.5 = −2⁻⁸
                Sample.Of(Quarter, One, 255, Half, 0x37F8), // G: −2⁻⁹, the tolerance itself
                Sample.Of(Quarter, One, 255, Half, 0x37FC), // G: −2⁻¹⁰
                Sample.Of(Half, 0x37F0, 255),               // R, G, B all −2⁻⁸: one sample
            }, 2, 0),
            // Partly covered edge, outside the mask's geometry by one sample that is exactly clear, and one that is not.
            (new[] { Sample.Of(Quarter, One, 255), Sample.Of(Zero, One, 0), Sample.Of(Quarter, 0x3A00, 0), Sample.Of(Zero, One, 255) }, 0, 1),
            // Darker and stray in one sample: counted once in each.
            (new[] { Sample.Of(Half, Quarter, 0), Sample.Of(Zero, One, 0), Sample.Of(Zero, One, 0), Sample.Of(Zero, One, 0) }, 1, 1),
        };

        static Sample[] Four(Sample s) => new[] { s, s, s, s };

        [Test]
        public void OneBlockPerRowCountsExactly()
        {
            // Output width 1: no group of blocks for the vector path, every block goes through the scalar word run.
            foreach (int maskBytes in new[] { 1, 4 })
            {
                var layout = new List<int>();
                for (int i = 0; i < Blocks.Length; i++) layout.Add(i);
                var (frame, darker, stray) = Build(layout, 1, maskBytes);
                var result = DifferenceMatting.Resolve(frame, new byte[frame.OutputWidth * frame.OutputHeight * 4]);
                Assert.That(result.DarkerOverWhite, Is.EqualTo(darker), "darker, mask bytes " + maskBytes);
                Assert.That(result.StrayBackground, Is.EqualTo(stray), "stray, mask bytes " + maskBytes);
                Assert.That(result.Samples, Is.EqualTo(frame.Width * frame.Height));
                Assert.That(result.BackgroundChecked, Is.True);
                Assert.That((darker, stray), Is.EqualTo((3, 8)), "the hand count of the blocks above");
            }
        }

        [Test]
        public void RunsOfEqualBlocksInWideRowsCountExactly()
        {
            // Runs of 8 equal blocks in rows 24 wide: whole groups of background and covered blocks for the vector path.
            const int width = 24;
            var layout = new List<int>();
            for (int i = 0; i < Blocks.Length; i++)
                for (int r = 0; r < 8; r++) layout.Add(i);
            while (layout.Count % width != 0) layout.Add(0);
            var (frame, darker, stray) = Build(layout, width, 1);
            var result = DifferenceMatting.Resolve(frame, new byte[frame.OutputWidth * frame.OutputHeight * 4]);
            Assert.That(result.DarkerOverWhite, Is.EqualTo(darker));
            Assert.That(result.StrayBackground, Is.EqualTo(stray));
            Assert.That((darker, stray), Is.EqualTo((8 * 3, 8 * 8)));
        }

        [Test]
        public void WithoutAMaskOnlyDarkerSamplesAreCounted()
        {
            var layout = new List<int>();
            for (int i = 0; i < Blocks.Length; i++) layout.Add(i);
            var (frame, darker, _) = Build(layout, 1, 1);
            frame.Mask = null;
            var result = DifferenceMatting.Resolve(frame, new byte[frame.OutputWidth * frame.OutputHeight * 4]);
            Assert.That(result.DarkerOverWhite, Is.EqualTo(darker));
            Assert.That(result.StrayBackground, Is.EqualTo(0));
            Assert.That(result.BackgroundChecked, Is.False);
            Assert.That(result.ToString(), Does.Contain("background not checked"));
        }

        [Test]
        public void CheckBackgroundFalseIgnoresTheMask()
        {
            var (frame, darker, _) = Build(new List<int> { 2, 3 }, 1, 1);
            var result = DifferenceMatting.Resolve(frame, new byte[8], default, checkBackground: false);
            Assert.That(result.StrayBackground, Is.EqualTo(0));
            Assert.That(result.BackgroundChecked, Is.False);
            Assert.That(result.DarkerOverWhite, Is.EqualTo(darker));
        }

        /// <summary>
        /// Random frames on every path (k = 1, 2, 3; transparent linear, Gamma, solid background; widths 1–33 at k = 2
        /// so that vector groups straddle every position): the counts equal the plain per-sample reference, and the
        /// bytes are those without a mask.
        /// </summary>
        [Test]
        public void CountsEqualThePerSampleReferenceOnEveryPath()
        {
            var random = new SeededRandom(5);
            int frames = 0;
            foreach (var (k, gamma, solid) in new[] { (2, false, false), (1, false, false), (3, false, false), (2, true, false), (2, false, true) })
                for (int outputWidth = 1; outputWidth <= (k == 2 && !gamma && !solid ? 33 : 9); outputWidth++)
                {
                    const int outputHeight = 4;
                    var frame = new RawFrame(outputWidth * k, outputHeight * k, k) { ColorIsGammaEncoded = gamma, MaskBytesPerPixel = 1 };
                    int samples = frame.Width * frame.Height;
                    frame.ColorOverBlack = new ushort[samples * 4];
                    frame.ColorOverWhite = new ushort[samples * 4];
                    frame.Mask = new byte[samples];
                    int kind = 0;
                    for (int oy = 0; oy < outputHeight; oy++)
                        for (int ox = 0; ox < outputWidth; ox++)
                        {
                            if (random.NextUInt64() % 3 == 0) kind = (int)(random.NextUInt64() % 6);
                            for (int s = 0; s < k * k; s++)
                            {
                                int sample = (oy * k + s / k) * frame.Width + ox * k + s % k;
                                frame.Mask[sample] = random.NextUInt64() % 4 == 0 ? (byte)0 : (byte)255;
                                for (int c = 0; c < 4; c++)
                                {
                                    ushort black, white, any = (ushort)random.NextUInt64();
                                    ushort unit = (ushort)(0x3000 | (int)(random.NextUInt64() % 0xC00));
                                    switch (kind)
                                    {
                                        case 0: black = 0; white = One; break;
                                        case 1: black = white = unit; break;
                                        case 2: black = unit; white = (ushort)(unit - random.NextUInt64() % 24); break; // darker by 0–23 steps
                                        case 3: black = (ushort)(unit >> 1 & 0x3BFF); white = unit; break;
                                        case 4: black = 0; white = random.NextUInt64() % 2 == 0 ? One : unit; break;
                                        default: black = any; white = (ushort)random.NextUInt64(); break;
                                    }
                                    frame.ColorOverBlack[sample * 4 + c] = black;
                                    frame.ColorOverWhite[sample * 4 + c] = white;
                                }
                            }
                        }
                    var background = solid ? Background.SolidSrgb(40, 90, 200) : default;
                    var withMask = new byte[outputWidth * outputHeight * 4];
                    var result = DifferenceMatting.Resolve(frame, withMask, background);
                    var (darker, stray) = Reference(frame);
                    string where = $"k {k}, gamma {gamma}, solid {solid}, width {outputWidth}";
                    Assert.That(result.DarkerOverWhite, Is.EqualTo(darker), where);
                    Assert.That(result.StrayBackground, Is.EqualTo(stray), where);
                    var mask = frame.Mask;
                    frame.Mask = null;
                    var withoutMask = new byte[withMask.Length];
                    Assert.That(DifferenceMatting.Resolve(frame, withoutMask, background).DarkerOverWhite, Is.EqualTo(darker), where);
                    Assert.That(withMask, Is.EqualTo(withoutMask), "the mask must not change the bytes: " + where);
                    frame.Mask = mask;
                    frames++;
                }
            Assert.That(frames, Is.EqualTo(33 + 4 * 9));
        }

        [Test]
        public void SumsAndFractionsAndCauses()
        {
            var a = new MattingDiagnostics { Samples = 1000, DarkerOverWhite = 2, StrayBackground = 0, BackgroundChecked = true };
            var b = new MattingDiagnostics { Samples = 3000, DarkerOverWhite = 0, StrayBackground = 4 };
            var sum = a + b;
            Assert.That((sum.Samples, sum.DarkerOverWhite, sum.StrayBackground, sum.BackgroundChecked), Is.EqualTo((4000L, 2L, 4L, true)));
            Assert.That(sum.DarkerFraction, Is.EqualTo(0.0005));
            Assert.That(sum.AboveThreshold, Is.False, "0.05 % and 0.1 % are not above 0.1 %");
            Assert.That(a.AboveThreshold, Is.True, "0.2 %");
            Assert.That(new MattingDiagnostics { Samples = 10 }.LikelyCauses(), Is.Empty);
            Assert.That(sum.LikelyCauses(), Does.Contain("Full Screen Pass").And.Contain("particles"));
        }

        /// <summary>The definitions, sample by sample, with nothing shared with the code under test.</summary>
        static (int Darker, int Stray) Reference(RawFrame frame)
        {
            int darker = 0, stray = 0;
            for (int s = 0; s < frame.Width * frame.Height; s++)
            {
                bool isDarker = false, clear = true;
                for (int c = 0; c < 3; c++)
                {
                    ushort k = frame.ColorOverBlack[s * 4 + c], w = frame.ColorOverWhite[s * 4 + c];
                    if (HalfFloat.ToFloat(w) - HalfFloat.ToFloat(k) < -1.0 / 512) isDarker = true;
                    if (k != 0 || w != One) clear = false;
                }
                if (isDarker) darker++;
                if (frame.Mask != null && frame.Mask[s * frame.MaskBytesPerPixel] == 0 && !clear) stray++;
            }
            return (darker, stray);
        }

        /// <summary>A k = 2 frame of the given blocks, row by row (top row first), and the counts they add up to.</summary>
        static (RawFrame Frame, int Darker, int Stray) Build(List<int> layout, int outputWidth, int maskBytes)
        {
            int outputHeight = layout.Count / outputWidth;
            var frame = new RawFrame(outputWidth * 2, outputHeight * 2, 2) { MaskBytesPerPixel = maskBytes };
            int samples = frame.Width * frame.Height;
            frame.ColorOverBlack = new ushort[samples * 4];
            frame.ColorOverWhite = new ushort[samples * 4];
            frame.Mask = new byte[samples * maskBytes];
            int darker = 0, stray = 0;
            for (int i = 0; i < layout.Count; i++)
            {
                var block = Blocks[layout[i]];
                darker += block.Darker;
                stray += block.Stray;
                int ox = i % outputWidth, oy = i / outputWidth;
                for (int s = 0; s < 4; s++)
                {
                    var v = block.Samples[s];
                    int sample = (oy * 2 + s / 2) * frame.Width + ox * 2 + s % 2;
                    frame.ColorOverBlack[sample * 4] = v.K;
                    frame.ColorOverBlack[sample * 4 + 1] = v.KG;
                    frame.ColorOverBlack[sample * 4 + 2] = v.K;
                    frame.ColorOverBlack[sample * 4 + 3] = 0x1234; // alpha: ignored
                    frame.ColorOverWhite[sample * 4] = v.W;
                    frame.ColorOverWhite[sample * 4 + 1] = v.WG;
                    frame.ColorOverWhite[sample * 4 + 2] = v.W;
                    frame.ColorOverWhite[sample * 4 + 3] = 0x4321;
                    frame.Mask[sample * maskBytes] = v.Mask;
                    for (int extra = 1; extra < maskBytes; extra++) frame.Mask[sample * maskBytes + extra] = 77; // only the first byte counts
                }
            }
            return (frame, darker, stray);
        }
    }
}
