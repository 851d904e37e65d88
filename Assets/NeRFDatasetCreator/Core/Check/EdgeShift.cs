using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Which whole-pixel shift (dx, dy), |dx|, |dy| ≤ <see cref="Reach"/>, best lines up one coverage picture with another
    /// along the second's edges: for each shift, the number of pixels p within a pixel of an edge of G where
    /// A(p + shift) ≠ G(p). Only the band around G's edges counts, so glass or particles away from the edges do not matter.
    /// </summary>
    public static class EdgeShift
    {
        public const int Reach = 2;

        public sealed class Result
        {
            public int BandPixels;
            public int MismatchAtZero;
            public int BestDx, BestDy, BestMismatch;
        }

        /// <param name="a">Coverage of the picture being tested (true = something there).</param>
        /// <param name="g">Coverage of the reference whose edges define the band.</param>
        public static Result Measure(bool[] a, bool[] g, int w, int h)
        {
            var band = Band(g, w, h);
            var result = new Result { BandPixels = band.Count };
            if (band.Count == 0) return result;
            var best = int.MaxValue;
            for (var dy = -Reach; dy <= Reach; dy++)
                for (var dx = -Reach; dx <= Reach; dx++)
                {
                    var mismatch = 0;
                    foreach (var p in band)
                    {
                        int x = p % w + dx, y = p / w + dy;
                        var av = x >= 0 && y >= 0 && x < w && y < h && a[y * w + x];
                        if (av != g[p]) mismatch++;
                    }
                    if (dx == 0 && dy == 0) result.MismatchAtZero = mismatch;
                    // Ties keep the smaller shift (visited first when equal is not better).
                    if (mismatch < best || (mismatch == best && dx * dx + dy * dy < result.BestDx * result.BestDx + result.BestDy * result.BestDy))
                    {
                        best = mismatch;
                        result.BestDx = dx;
                        result.BestDy = dy;
                    }
                }
            result.BestMismatch = best;
            return result;
        }

        /// <summary>Pixels on either side of a horizontal or vertical change of <paramref name="g"/>, and their neighbours.</summary>
        static List<int> Band(bool[] g, int w, int h)
        {
            var mark = new bool[g.Length];
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    var i = y * w + x;
                    if ((x + 1 < w && g[i] != g[i + 1]) || (y + 1 < h && g[i] != g[i + w]))
                    {
                        for (var yy = y - 1; yy <= y + 2; yy++)
                            for (var xx = x - 1; xx <= x + 2; xx++)
                                if (xx >= 0 && yy >= 0 && xx < w && yy < h) mark[yy * w + xx] = true;
                    }
                }
            var band = new List<int>();
            for (var i = 0; i < mark.Length; i++)
                if (mark[i]) band.Add(i);
            return band;
        }
    }
}
