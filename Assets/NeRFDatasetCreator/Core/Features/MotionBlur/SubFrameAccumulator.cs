using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Averages the colour renders of one view's sub-frames (<see cref="SubFrameSchedule"/>) in linear light: the
    /// blurred image. Takes the difference-matting pair (over black, over white; IEEE halves, rows bottom first, as the
    /// capture reads them back) and sums each with the sub-frame's weight — 1/N, or the row's
    /// <see cref="RollingShutter.Weight"/> with a rolling shutter — then gives the averaged pair back as halves, so the
    /// rest of the writer (matting, straight alpha, downsampling) runs unchanged. Averaging the two premultiplied renders
    /// separately is exact: each is linear in (α·c, α), so the matting of the averages is the average coverage and
    /// the coverage-weighted colour. Gamma-space renders (a Gamma project) are decoded to linear first and encoded back.
    /// <para>
    /// Reusable (issue 32, R4-2): a capture makes one per run and calls <see cref="Restart"/> per view, so its sums are
    /// allocated once, not per view (Unity's collector is not generational: 164 MB of garbage per 800×800 view at k = 2
    /// was paid in full). Each half's linear value comes from a 65 536-entry table built once per colour space, and the
    /// averaged pair is rounded to halves by bit arithmetic: the same values as before, computed without a
    /// <c>Math.Pow</c>/<c>Math.Log</c> per sample (<c>SubFrameAccumulatorTests</c>, <c>ViewPipelineBytesTests</c>).
    /// Not thread-safe: one thread at a time (<see cref="BackgroundSubFrameSum"/> runs it on a worker).
    /// </para>
    /// </summary>
    public sealed class SubFrameAccumulator
    {
        readonly int _width, _height;
        readonly double _readout;
        readonly double[] _linear;
        readonly bool _gamma;
        readonly double[] _black, _white;
        readonly double[] _rowWeight;
        bool[] _added;
        int _count, _addedCount;

        public SubFrameAccumulator(int width, int height, int subFrames, double readout, bool gammaEncoded)
        {
            if (width < 1 || height < 1) throw new ArgumentOutOfRangeException(nameof(width), "the frame has no pixels");
            _width = width;
            _height = height;
            _readout = readout;
            _gamma = gammaEncoded;
            _linear = gammaEncoded ? GammaLinear.Value : PlainLinear.Value;
            _black = new double[width * height * 3];
            _white = new double[width * height * 3];
            _rowWeight = new double[height];
            _added = new bool[0];
            Restart(subFrames);
        }

        public int SubFrames => _count;

        /// <summary>The frame's width in samples.</summary>
        public int Width => _width;

        /// <summary>The frame's height in samples.</summary>
        public int Height => _height;

        /// <summary>Clears the sums for the next view of <paramref name="subFrames"/> sub-frames (no allocation unless the count grows).</summary>
        public void Restart(int subFrames)
        {
            if (subFrames < 1) throw new ArgumentOutOfRangeException(nameof(subFrames), subFrames, "at least one sub-frame");
            Array.Clear(_black, 0, _black.Length);
            Array.Clear(_white, 0, _white.Length);
            Array.Clear(_rowWeight, 0, _rowWeight.Length);
            if (_added.Length < subFrames) _added = new bool[subFrames];
            else Array.Clear(_added, 0, _added.Length);
            _count = subFrames;
            _addedCount = 0;
        }

        /// <summary>Adds sub-frame <paramref name="k"/>'s two renders (4 halves a pixel, RGBA; A is ignored).</summary>
        public void Add(int k, ushort[] overBlack, ushort[] overWhite)
        {
            if (k < 0 || k >= _count) throw new ArgumentOutOfRangeException(nameof(k), k, "not a sub-frame of this view");
            if (_added[k]) throw new InvalidOperationException("Sub-frame " + k + " was added twice.");
            var expected = _width * _height * 4;
            if (overBlack == null || overWhite == null || overBlack.Length != expected || overWhite.Length != expected)
                throw new ArgumentException("A sub-frame needs both renders at " + _width + "×" + _height + " (4 halves a pixel).");
            _added[k] = true;
            _addedCount++;
            double[] linear = _linear, black = _black, white = _white;
            for (var y = 0; y < _height; y++)
            {
                var w = RollingShutter.Weight(k, _count, RollingShutter.V(y, _height), _readout);
                if (w == 0) continue;
                _rowWeight[y] += w;
                int src = y * _width * 4, dst = y * _width * 3, end = dst + _width * 3;
                // Written out (Mono does not inline): the same products and sums, in the same order, as per channel before.
                for (; dst < end; dst += 3, src += 4)
                {
                    black[dst] += w * linear[overBlack[src]];
                    black[dst + 1] += w * linear[overBlack[src + 1]];
                    black[dst + 2] += w * linear[overBlack[src + 2]];
                    white[dst] += w * linear[overWhite[src]];
                    white[dst + 1] += w * linear[overWhite[src + 1]];
                    white[dst + 2] += w * linear[overWhite[src + 2]];
                }
            }
        }

        /// <summary>True once every sub-frame was added.</summary>
        public bool IsComplete => _addedCount == _count;

        /// <summary>Writes the averaged renders into <paramref name="overBlack"/> and <paramref name="overWhite"/> (4 halves a pixel, A = 1).</summary>
        public void Finish(ushort[] overBlack, ushort[] overWhite)
        {
            if (!IsComplete) throw new InvalidOperationException("Not every sub-frame was added (" + _addedCount + " of " + _count + ").");
            var expected = _width * _height * 4;
            if (overBlack == null || overWhite == null || overBlack.Length != expected || overWhite.Length != expected)
                throw new ArgumentException("The averaged renders need " + expected + " halves each.");
            for (var y = 0; y < _height; y++)
            {
                // The weights of a row sum to 1 up to rounding; dividing by their sum keeps a flat colour exact.
                var norm = _rowWeight[y] > 0 ? 1 / _rowWeight[y] : 0;
                for (var x = 0; x < _width; x++)
                {
                    int p = y * _width + x, dst = p * 4, src = p * 3;
                    for (var c = 0; c < 3; c++)
                    {
                        overBlack[dst + c] = ToHalf(Encoded(_black[src + c] * norm));
                        overWhite[dst + c] = ToHalf(Encoded(_white[src + c] * norm));
                    }
                    overBlack[dst + 3] = overWhite[dst + 3] = 0x3C00;
                }
            }
        }

        // The linear value of every half, per colour space: what was computed per sample before, once.
        static readonly Lazy<double[]> PlainLinear = new Lazy<double[]>(() => LinearTable(false));
        static readonly Lazy<double[]> GammaLinear = new Lazy<double[]>(() => LinearTable(true));

        static double[] LinearTable(bool gamma)
        {
            var half = HalfFloat.Lookup;
            var table = new double[65536];
            for (var h = 0; h < table.Length; h++)
            {
                var value = half[h];
                table[h] = gamma ? (value <= 0 ? 0 : Srgb.DecodeExact(Math.Min(1, (double)value))) : value;
            }
            return table;
        }

        double Encoded(double linear) => _gamma ? Srgb.EncodeExact(Math.Max(0, Math.Min(1, linear))) : linear;

        /// <summary>
        /// The nearest IEEE half to a value (ties to even; beyond the largest half: infinity; NaN: 0x7E00), for the
        /// averaged renders. Bit arithmetic on the double: its 52-bit fraction is cut to the half's 10 bits (or fewer for
        /// a subnormal half) and the dropped bits decide the rounding, exactly.
        /// </summary>
        public static ushort ToHalf(double value)
        {
            var bits = BitConverter.DoubleToInt64Bits(value);
            var sign = (int)((bits >> 48) & 0x8000);
            var biased = (int)((bits >> 52) & 0x7FF);
            var fraction = bits & 0xFFFFFFFFFFFFFL;
            if (value == 0) return 0; // −0 too, as before: the sums never produce it
            if (biased == 0x7FF) return fraction != 0 ? (ushort)0x7E00 : (ushort)(sign | 0x7C00);
            var exponent = biased - 1023;
            if (exponent > 15) return (ushort)(sign | 0x7C00);
            if (exponent < -25) return (ushort)sign; // below half the smallest subnormal (2⁻²⁵): zero (2⁻²⁵ itself ties to 0 below)
            var significand = fraction | (1L << 52);
            // A normal half keeps 10 fraction bits (shift 42); a subnormal one counts units of 2⁻²⁴ (shift 28 − exponent).
            var shift = exponent >= -14 ? 42 : 28 - exponent;
            var kept = significand >> shift;
            var dropped = significand & ((1L << shift) - 1);
            var halfway = 1L << (shift - 1);
            if (dropped > halfway || (dropped == halfway && (kept & 1) != 0)) kept++;
            if (exponent < -14) return (ushort)(sign | (int)kept); // 1024 rounds up into the smallest normal, which has the same bits
            // kept holds the implicit 1 (bit 10); a carry into bit 11 moves to the next binade.
            if (kept >= 2048)
            {
                kept >>= 1;
                exponent++;
            }
            if (exponent > 15) return (ushort)(sign | 0x7C00);
            return (ushort)(sign | ((exponent + 15) << 10) | (int)(kept & 0x3FF));
        }
    }
}
