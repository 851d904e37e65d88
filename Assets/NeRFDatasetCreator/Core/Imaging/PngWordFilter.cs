namespace NerfDatasetCreator
{
    /// <summary>
    /// PNG's None, Sub, Up and Average filters (PNG spec §9.2) on a row held as 64-bit words, eight bytes at a time:
    /// byte k of a word is row byte 8·j + k (the words are filled with Buffer.BlockCopy on a little-endian machine).
    /// Bytes are subtracted and averaged within their own 8 bits (SWAR) so that no borrow or carry crosses into the
    /// next byte. Mono, which runs the editor, neither vectorises nor removes the bounds checks of a byte loop, and a
    /// word loop does an eighth of the iterations. Paeth needs byte-wise comparisons and stays in
    /// <see cref="PngRowFilter"/>.
    /// </summary>
    internal static class PngWordFilter
    {
        const ulong High = 0x8080808080808080UL;
        const ulong Low7 = 0x7F7F7F7F7F7F7F7FUL;
        const ulong EvenBytes = 0x00FF00FF00FF00FFUL;
        const ulong NotLowBits = 0xFEFEFEFEFEFEFEFEUL;
        const ulong LaneSum = 0x0001000100010001UL;

        /// <summary>Words sampled per row by <see cref="Choose"/>: every this-many-th word.</summary>
        internal const int SampleEvery = 2;

        /// <summary>
        /// Writes the residuals of filter <paramref name="type"/> (0–3) for the row <paramref name="row"/>[0…words)
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
                default:
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
            }
        }

        /// <summary>
        /// The filter among None, Sub, Up and Average whose residuals have the smallest sum of |signed byte| over every
        /// <see cref="SampleEvery"/>-th word of the row (the heuristic the PNG specification recommends, sampled; Paeth
        /// is left out because it cannot be computed on words). Ties go to the lower type, so an all-zero row gets None,
        /// whose type byte 0 lets a run of zeros go on into the next row. The padding bytes of a row's last word take
        /// part in its sums, which only sways the choice on rows a few words long.
        /// </summary>
        internal static int Choose(ulong[] row, ulong[] up, int words, int shift)
        {
            int back = 64 - shift;
            long none = 0, sub = 0, upSum = 0, average = 0;
            for (int j = 0; j < words; j += SampleEvery)
            {
                ulong x = row[j], b = up[j];
                ulong a = (x << shift) | ((j == 0 ? 0 : row[j - 1]) >> back);
                ulong avg = (a & b) + (((a ^ b) & NotLowBits) >> 1);

                // |r| per byte: negate the bytes whose top bit is set (~r + 1 cannot carry out of a byte here).
                ulong r = x;
                ulong negative = (r & High) >> 7;
                ulong m = (r ^ (negative * 0xFF)) + negative;
                ulong lanes = (m & EvenBytes) + ((m >> 8) & EvenBytes);
                none += (long)((lanes * LaneSum) >> 48);

                r = ((x | High) - (a & Low7)) ^ ((x ^ ~a) & High);
                negative = (r & High) >> 7;
                m = (r ^ (negative * 0xFF)) + negative;
                lanes = (m & EvenBytes) + ((m >> 8) & EvenBytes);
                sub += (long)((lanes * LaneSum) >> 48);

                r = ((x | High) - (b & Low7)) ^ ((x ^ ~b) & High);
                negative = (r & High) >> 7;
                m = (r ^ (negative * 0xFF)) + negative;
                lanes = (m & EvenBytes) + ((m >> 8) & EvenBytes);
                upSum += (long)((lanes * LaneSum) >> 48);

                r = ((x | High) - (avg & Low7)) ^ ((x ^ ~avg) & High);
                negative = (r & High) >> 7;
                m = (r ^ (negative * 0xFF)) + negative;
                lanes = (m & EvenBytes) + ((m >> 8) & EvenBytes);
                average += (long)((lanes * LaneSum) >> 48);
            }
            int best = 0;
            long bestSum = none;
            if (sub < bestSum) { best = 1; bestSum = sub; }
            if (upSum < bestSum) { best = 2; bestSum = upSum; }
            if (average < bestSum) best = 3;
            return best;
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
