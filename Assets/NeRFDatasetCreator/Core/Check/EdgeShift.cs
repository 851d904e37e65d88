using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Which whole-pixel shift (dx, dy), |dx|, |dy| ≤ <see cref="Reach"/>, best lines up one coverage picture with another
    /// along the second's edges: for each shift, the number of pixels p within a pixel of an edge of G where
    /// A(p + shift) ≠ G(p). Only the band around G's edges counts, so glass or particles away from the edges do not matter.
    /// An instance keeps its buffers from view to view (one instance per thread).
    /// </summary>
    public sealed class EdgeShift
    {
        /// <summary>Shifts tried in x and y: a pass offset by one pixel is the fault; a larger offset still shows as ±1 being better than 0.</summary>
        public const int Reach = 1;

        public sealed class Result
        {
            public int BandPixels;
            public int MismatchAtZero;
            public int BestDx, BestDy, BestMismatch;
        }

        byte[] _mark = new byte[0];
        int[] _bandX = new int[0], _bandY = new int[0];

        /// <param name="a">Coverage of the picture being tested (true = something there).</param>
        /// <param name="g">Coverage of the reference whose edges define the band.</param>
        public Result Measure(bool[] a, bool[] g, int w, int h)
        {
            var count = Band(g, w, h);
            var result = new Result { BandPixels = count };
            if (count == 0) return result;
            var best = int.MaxValue;
            for (var dy = -Reach; dy <= Reach; dy++)
                for (var dx = -Reach; dx <= Reach; dx++)
                {
                    var mismatch = 0;
                    for (var k = 0; k < count; k++)
                    {
                        int x = _bandX[k], y = _bandY[k], sx = x + dx, sy = y + dy;
                        var av = sx >= 0 && sy >= 0 && sx < w && sy < h && a[sy * w + sx];
                        if (av != g[y * w + x]) mismatch++;
                    }
                    if (dx == 0 && dy == 0) result.MismatchAtZero = mismatch;
                    // Ties keep the smaller shift.
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

        /// <summary>Pixels on either side of a horizontal or vertical change of <paramref name="g"/>, and their neighbours, into the band arrays; returns their count.</summary>
        int Band(bool[] g, int w, int h)
        {
            if (_mark.Length < g.Length) _mark = new byte[g.Length];
            else Array.Clear(_mark, 0, g.Length);
            var count = 0;
            for (var y = 0; y < h; y++)
            {
                var row = y * w;
                for (var x = 0; x < w; x++)
                {
                    var i = row + x;
                    if (!((x + 1 < w && g[i] != g[i + 1]) || (y + 1 < h && g[i] != g[i + w]))) continue;
                    for (var yy = Math.Max(0, y - 1); yy <= Math.Min(h - 1, y + 2); yy++)
                        for (var xx = Math.Max(0, x - 1); xx <= Math.Min(w - 1, x + 2); xx++)
                        {
                            var j = yy * w + xx;
                            if (_mark[j] != 0) continue;
                            _mark[j] = 1;
                            count++;
                        }
                }
            }
            if (_bandX.Length < count)
            {
                _bandX = new int[count * 2];
                _bandY = new int[count * 2];
            }
            var k = 0;
            for (var i = 0; i < g.Length && k < count; i++)
                if (_mark[i] != 0)
                {
                    _bandX[k] = i % w;
                    _bandY[k] = i / w;
                    k++;
                }
            return count;
        }
    }
}
