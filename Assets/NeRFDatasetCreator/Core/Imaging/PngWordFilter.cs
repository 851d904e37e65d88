using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// PNG's five filters (PNG spec §9.2) on a row held as 64-bit words, eight bytes at a time:
    /// byte k of a word is row byte 8·j + k (the words are filled with Buffer.BlockCopy on a little-endian machine).
    /// Bytes are subtracted and averaged within their own 8 bits (SWAR) so that no borrow or carry crosses into the
    /// next byte. Mono, which runs the editor, neither vectorises nor removes the bounds checks of a byte loop, and a
    /// word loop does an eighth of the iterations; Paeth's byte comparisons too are done on whole words.
    /// </summary>
    internal static class PngWordFilter
    {
        const ulong High = 0x8080808080808080UL;
        const ulong Low7 = 0x7F7F7F7F7F7F7F7FUL;
        const ulong EvenBytes = 0x00FF00FF00FF00FFUL;
        const ulong NotLowBits = 0xFEFEFEFEFEFEFEFEUL;

        /// <summary>
        /// Words per pair of adjacent words that <see cref="Choose"/> samples on a long row (1 in 16: on the
        /// benchmark's 800-pixel rows within ±1 % of 1 in 8, at half the cost of the estimate, which the Paeth
        /// candidate had doubled); shorter rows are sampled more densely, down to every word, so that each row
        /// has at least <see cref="MinSamples"/> pairs where it can (a 200-pixel gray row at 1 in 16 has two).
        /// </summary>
        internal const int SampleEvery = 16;

        const int MinSamples = 8;

        /// <summary>
        /// Writes the residuals of filter <paramref name="type"/> (0–4) for the row <paramref name="row"/>[0…words)
        /// with the row above <paramref name="up"/> (zeros for the first row) at <paramref name="output"/>[at].
        /// <paramref name="shift"/> is 8 × bytes per pixel (8…32).
        /// </summary>
        internal static void Apply(int type, ulong[] row, ulong[] up, int words, int shift, ulong[] output, int at)
        {
            int back = 64 - shift;
            switch (type)
            {
                case 0:
                    System.Array.Copy(row, 0, output, at, words);
                    break;
                case 1:
                {
                    ulong before = 0;
                    for (int j = 0; j < words; j++)
                    {
                        ulong x = row[j];
                        ulong a = (x << shift) | (before >> back);
                        output[at + j] = ((x | High) - (a & Low7)) ^ ((x ^ ~a) & High);
                        before = x;
                    }
                    break;
                }
                case 2:
                    for (int j = 0; j < words; j++)
                    {
                        ulong x = row[j], b = up[j];
                        output[at + j] = ((x | High) - (b & Low7)) ^ ((x ^ ~b) & High);
                    }
                    break;
                case 3:
                {
                    ulong before = 0;
                    for (int j = 0; j < words; j++)
                    {
                        ulong x = row[j], b = up[j];
                        ulong a = (x << shift) | (before >> back);
                        // floor((a + b) / 2) per byte: the common bits plus half the differing ones.
                        ulong average = (a & b) + (((a ^ b) & NotLowBits) >> 1);
                        output[at + j] = ((x | High) - (average & Low7)) ^ ((x ^ ~average) & High);
                        before = x;
                    }
                    break;
                }
                default:
                {
                    ulong before = 0, beforeUp = 0;
                    for (int j = 0; j < words; j++)
                    {
                        ulong x = row[j], b = up[j];
                        ulong a = (x << shift) | (before >> back), c = (b << shift) | (beforeUp >> back);
                        ulong paeth = PaethPredictor(a, b, c);
                        output[at + j] = ((x | High) - (paeth & Low7)) ^ ((x ^ ~paeth) & High);
                        before = x;
                        beforeUp = b;
                    }
                    break;
                }
            }
        }

        /// <summary>
        /// PNG's Paeth predictor (spec §9.4) of every byte of a word from the bytes to the left (<paramref name="a"/>),
        /// above (<paramref name="b"/>) and above-left (<paramref name="c"/>), with no branch per byte. With
        /// pa = |b − c| and pb = |a − c|: where a − c and b − c have the same sign, pc = pa + pb is never below either,
        /// so the choice is a if pa ≤ pb, else b; where c lies between a and b (signs differ), pc = |pa − pb|, so a if
        /// 2·pa ≤ pb, else b if 2·pb ≤ pa, else c. 2·p ≤ q is p ≤ ⌊q / 2⌋, which stays within a byte. An unsigned
        /// byte test x ≥ y: the low seven bits compared by a subtraction that cannot borrow out of the byte, the top
        /// bits combined with it; the results live in each byte's top bit, spread to a byte mask by a multiplication.
        /// The tests check it through the filter against the reference decoder's byte-wise Paeth for every (a, b, c).
        /// </summary>
        static ulong PaethPredictor(ulong a, ulong b, ulong c)
        {
            // Flat stretches first: where c equals a in every byte, pb = 0 and the prediction is b; where it equals
            // b, pa = 0 and it is a.
            if (a == c) return b;
            if (b == c) return a;
            ulong ac = a ^ c, bc = b ^ c;
            ulong aAtLeastC = ((a & ~c) | (~ac & ((a | High) - (c & Low7)))) & High;
            ulong bAtLeastC = ((b & ~c) | (~bc & ((b | High) - (c & Low7)))) & High;
            // |a − c| and |b − c|: the larger byte minus the smaller, which cannot borrow.
            ulong top = c ^ (ac & ((aAtLeastC >> 7) * 0xFF));
            ulong pb = top - (top ^ ac);
            top = c ^ (bc & ((bAtLeastC >> 7) * 0xFF));
            ulong pa = top - (top ^ bc);
            ulong paAtMostPb = ((pb & ~pa) | (~(pb ^ pa) & ((pb | High) - (pa & Low7)))) & High;
            ulong twicePaAtMostPb = ~pa & ((((pb >> 1) & Low7) | High) - (pa & Low7)) & High;
            ulong twicePbAtMostPa = ~pb & ((((pa >> 1) & Low7) | High) - (pb & Low7)) & High;
            ulong between = aAtLeastC ^ bAtLeastC;
            ulong takeA = paAtMostPb ^ ((paAtMostPb ^ twicePaAtMostPb) & between);
            ulong takeB = (~between | twicePbAtMostPa) & High;
            ulong bOrC = c ^ (bc & ((takeB >> 7) * 0xFF));
            return bOrC ^ ((a ^ bOrC) & ((takeA >> 7) * 0xFF));
        }

        /// <summary>
        /// The filter among the five that leaves the least to code, estimated on pairs of adjacent words, one pair in
        /// every <see cref="SampleEvery"/> words or more often on short rows: the <see cref="Cost"/> of the second
        /// word's residuals — about the bits a literal needs, nothing for bytes inside a run that
        /// <see cref="HuffmanDeflate"/> sends as a match.
        /// The first word serves for the residuals a pixel earlier, except for Paeth (twice the cost of the other
        /// four together), whose sampled word is compared with zeros a pixel before it. Ties go to the lower type, so
        /// an all-zero row gets None, whose type byte 0 lets a run of zeros go on into the next row; a row whose None
        /// costs nothing (empty, or a mask's) is decided before any other filter is tried.
        /// </summary>
        internal static int Choose(ulong[] row, ulong[] up, int words, int shift)
        {
            int back = 64 - shift;
            int step = Math.Max(2, Math.Min(SampleEvery, words / MinSamples));
            ulong none = 0, sub = 0, upSum = 0, average = 0, paethSum = 0;
            for (int j = 0; j + 1 < words; j += step)
            {
                ulong x0 = row[j], x1 = row[j + 1];
                none += Cost(x1, x1 ^ ((x1 << shift) | (x0 >> back)));
            }
            if (none == 0) return 0;
            for (int j = 0; j + 1 < words; j += step)
            {
                ulong x0 = row[j], x1 = row[j + 1], b0 = up[j], b1 = up[j + 1];
                ulong a0 = (x0 << shift) | ((j == 0 ? 0 : row[j - 1]) >> back), a1 = (x1 << shift) | (x0 >> back);
                ulong c0 = (b0 << shift) | ((j == 0 ? 0 : up[j - 1]) >> back), c1 = (b1 << shift) | (b0 >> back);
                ulong m0 = (a0 & b0) + (((a0 ^ b0) & NotLowBits) >> 1), m1 = (a1 & b1) + (((a1 ^ b1) & NotLowBits) >> 1);
                // The residuals of the pair under each filter (the first word only for the byte a pixel earlier),
                // written out rather than called: Mono does not inline, and this runs a few hundred times a row.
                ulong s0 = ((x0 | High) - (a0 & Low7)) ^ ((x0 ^ ~a0) & High), s1 = ((x1 | High) - (a1 & Low7)) ^ ((x1 ^ ~a1) & High);
                ulong u0 = ((x0 | High) - (b0 & Low7)) ^ ((x0 ^ ~b0) & High), u1 = ((x1 | High) - (b1 & Low7)) ^ ((x1 ^ ~b1) & High);
                ulong v0 = ((x0 | High) - (m0 & Low7)) ^ ((x0 ^ ~m0) & High), v1 = ((x1 | High) - (m1 & Low7)) ^ ((x1 ^ ~m1) & High);
                sub += Cost(s1, s1 ^ ((s1 << shift) | (s0 >> back)));
                upSum += Cost(u1, u1 ^ ((u1 << shift) | (u0 >> back)));
                average += Cost(v1, v1 ^ ((v1 << shift) | (v0 >> back)));
                ulong p1 = PaethPredictor(a1, b1, c1);
                p1 = ((x1 | High) - (p1 & Low7)) ^ ((x1 ^ ~p1) & High);
                paethSum += Cost(p1, p1 ^ (p1 << shift));
            }
            // None is credited a bit per sampled pair: its type byte 0 lets the runs at a row's ends go on across
            // rows, which a per-word estimate does not see (on a mask, 3.8 KB instead of 4.3).
            int best = 0;
            ulong samples = (ulong)((words - 2) / step + 1);
            ulong bestSum = none > samples ? none - samples : 0;
            if (sub < bestSum) { best = 1; bestSum = sub; }
            if (upSum < bestSum) { best = 2; bestSum = upSum; }
            if (average < bestSum) { best = 3; bestSum = average; }
            if (paethSum < bestSum) best = 4;
            return best;
        }

        /// <summary>
        /// An estimate of the bits the residual bytes <paramref name="r"/> cost: per byte the bit length of |signed
        /// byte| (0 for 0, 1 for ±1, 2 for ±2…3, … 8 for −128), a rough code length that, unlike the sum of |residual|
        /// the PNG specification suggests, does not let a few edge bytes outweigh many small ones; nothing for a byte
        /// inside a run of at least four bytes that equal the byte a pixel earlier (zero bytes of
        /// <paramref name="equal"/>), which becomes a nearly free match — runs are seen within this word only.
        /// Summed over the word.
        /// </summary>
        static ulong Cost(ulong r, ulong equal)
        {
            ulong zero = ~(((equal & Low7) + Low7) | equal) & High;
            ulong starts = zero & (zero >> 8) & (zero >> 16) & (zero >> 24);
            ulong free = starts | (starts << 8) | (starts << 16) | (starts << 24);
            ulong differs = ((~free & High) >> 7) * 0xFF;
            // |r| per byte: negate the bytes whose top bit is set (~r + 1 cannot carry out of a byte here).
            ulong negative = (r & High) >> 7;
            ulong m = ((r ^ (negative * 0xFF)) + negative) & differs;
            // Bit length per byte: every bit below a byte's highest set bit set too, then the set bits counted.
            m |= (m >> 1) & 0x7F7F7F7F7F7F7F7FUL;
            m |= (m >> 2) & 0x3F3F3F3F3F3F3F3FUL;
            m |= (m >> 4) & 0x0F0F0F0F0F0F0F0FUL;
            m = m - ((m >> 1) & 0x5555555555555555UL);
            m = (m & 0x3333333333333333UL) + ((m >> 2) & 0x3333333333333333UL);
            m = (m + (m >> 4)) & 0x0F0F0F0F0F0F0F0FUL;
            return (m * 0x0101010101010101UL) >> 56;
        }

        /// <summary>Swaps the two bytes of every 16-bit lane: little-endian ushorts become PNG's big-endian samples.</summary>
        internal static void SwapBytePairs(ulong[] row, int words)
        {
            for (int j = 0; j < words; j++)
            {
                ulong w = row[j];
                row[j] = ((w & EvenBytes) << 8) | ((w >> 8) & EvenBytes);
            }
        }
    }
}
