namespace NerfDatasetCreator
{
    /// <summary>
    /// The five PNG filter types applied to one row (PNG spec §9.2): x is the byte, a the byte one pixel to the
    /// left, b the byte above, c the byte above-left; missing neighbours are 0. The first row's "above" is a row
    /// of zeros supplied by the caller.
    /// </summary>
    internal static class PngRowFilter
    {
        /// <summary>Writes the filter-type byte and the filtered row (n bytes from <paramref name="src"/>[s]) at <paramref name="dst"/>[d].</summary>
        internal static void Apply(int type, byte[] src, int s, byte[] prev, int p, int n, int bpp, byte[] dst, int d)
        {
            dst[d++] = (byte)type;
            switch (type)
            {
                case 0:
                    System.Buffer.BlockCopy(src, s, dst, d, n);
                    break;
                case 1:
                    for (int i = 0; i < bpp && i < n; i++) dst[d + i] = src[s + i];
                    for (int i = bpp; i < n; i++) dst[d + i] = (byte)(src[s + i] - src[s + i - bpp]);
                    break;
                case 2:
                    for (int i = 0; i < n; i++) dst[d + i] = (byte)(src[s + i] - prev[p + i]);
                    break;
                case 3:
                    for (int i = 0; i < bpp && i < n; i++) dst[d + i] = (byte)(src[s + i] - (prev[p + i] >> 1));
                    for (int i = bpp; i < n; i++) dst[d + i] = (byte)(src[s + i] - ((src[s + i - bpp] + prev[p + i]) >> 1));
                    break;
                default:
                    // With a = c = 0 the Paeth predictor is b.
                    for (int i = 0; i < bpp && i < n; i++) dst[d + i] = (byte)(src[s + i] - prev[p + i]);
                    for (int i = bpp; i < n; i++) dst[d + i] = (byte)(src[s + i] - Paeth(src[s + i - bpp], prev[p + i], prev[p + i - bpp]));
                    break;
            }
        }

        /// <summary>
        /// The filter type whose output for this row has the smallest sum of |signed byte| (PNG spec §12.8); ties go
        /// to the lower type. One pass computes all five sums.
        /// </summary>
        internal static int ChooseMinimumSum(byte[] src, int s, byte[] prev, int p, int n, int bpp)
        {
            long none = 0, sub = 0, up = 0, avg = 0, paeth = 0;
            int head = bpp < n ? bpp : n;
            for (int i = 0; i < head; i++)
            {
                // No left neighbour: Sub = None, and Paeth predicts b (= Up).
                int x = src[s + i], b = prev[p + i];
                int rawMagnitude = Magnitude(x), upMagnitude = Magnitude(x - b);
                none += rawMagnitude;
                sub += rawMagnitude;
                up += upMagnitude;
                avg += Magnitude(x - (b >> 1));
                paeth += upMagnitude;
            }
            for (int i = head; i < n; i++)
            {
                int x = src[s + i], a = src[s + i - bpp], b = prev[p + i], c = prev[p + i - bpp];
                none += Magnitude(x);
                sub += Magnitude(x - a);
                up += Magnitude(x - b);
                avg += Magnitude(x - ((a + b) >> 1));
                paeth += Magnitude(x - Paeth(a, b, c));
            }
            int best = 0;
            long bestSum = none;
            if (sub < bestSum) { best = 1; bestSum = sub; }
            if (up < bestSum) { best = 2; bestSum = up; }
            if (avg < bestSum) { best = 3; bestSum = avg; }
            if (paeth < bestSum) best = 4;
            return best;
        }

        // |residual| with the residual read as a signed byte (0…128), without a branch: residuals are noise, so a
        // branch on their sign would be mispredicted half the time.
        static int Magnitude(int residual)
        {
            int r = (sbyte)residual;
            int sign = r >> 31;
            return (r ^ sign) - sign;
        }

        /// <summary>PNG spec §9.4 with p = a + b − c expanded: |p − a| = |b − c|, |p − b| = |a − c|, |p − c| = |(b − c) + (a − c)|.</summary>
        internal static int Paeth(int a, int b, int c)
        {
            int pa = b - c, pb = a - c, pc = pa + pb;
            pa = Abs(pa);
            pb = Abs(pb);
            pc = Abs(pc);
            int bOrC = pb <= pc ? b : c;
            return pa <= pb && pa <= pc ? a : bOrC;
        }

        static int Abs(int v)
        {
            int sign = v >> 31;
            return (v ^ sign) - sign;
        }
    }
}
