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
    /// </summary>
    public sealed class SubFrameAccumulator
    {
        readonly int _width, _height, _count;
        readonly double _readout;
        readonly bool _gamma;
        readonly double[] _black, _white;
        readonly double[] _rowWeight;
        readonly bool[] _added;

        public SubFrameAccumulator(int width, int height, int subFrames, double readout, bool gammaEncoded)
        {
            if (width < 1 || height < 1) throw new ArgumentOutOfRangeException(nameof(width), "the frame has no pixels");
            if (subFrames < 1) throw new ArgumentOutOfRangeException(nameof(subFrames), subFrames, "at least one sub-frame");
            _width = width;
            _height = height;
            _count = subFrames;
            _readout = readout;
            _gamma = gammaEncoded;
            _black = new double[width * height * 3];
            _white = new double[width * height * 3];
            _rowWeight = new double[height];
            _added = new bool[subFrames];
        }

        public int SubFrames => _count;

        /// <summary>Adds sub-frame <paramref name="k"/>'s two renders (4 halves a pixel, RGBA; A is ignored).</summary>
        public void Add(int k, ushort[] overBlack, ushort[] overWhite)
        {
            if (k < 0 || k >= _count) throw new ArgumentOutOfRangeException(nameof(k), k, "not a sub-frame of this view");
            if (_added[k]) throw new InvalidOperationException("Sub-frame " + k + " was added twice.");
            var expected = _width * _height * 4;
            if (overBlack == null || overWhite == null || overBlack.Length != expected || overWhite.Length != expected)
                throw new ArgumentException("A sub-frame needs both renders at " + _width + "×" + _height + " (4 halves a pixel).");
            _added[k] = true;
            var table = HalfFloat.Lookup;
            for (var y = 0; y < _height; y++)
            {
                var w = RollingShutter.Weight(k, _count, RollingShutter.V(y, _height), _readout);
                if (w == 0) continue;
                _rowWeight[y] += w;
                for (var x = 0; x < _width; x++)
                {
                    int p = y * _width + x, src = p * 4, dst = p * 3;
                    for (var c = 0; c < 3; c++)
                    {
                        _black[dst + c] += w * Linear(table[overBlack[src + c]]);
                        _white[dst + c] += w * Linear(table[overWhite[src + c]]);
                    }
                }
            }
        }

        /// <summary>True once every sub-frame was added.</summary>
        public bool IsComplete => Array.TrueForAll(_added, a => a);

        /// <summary>Writes the averaged renders into <paramref name="overBlack"/> and <paramref name="overWhite"/> (4 halves a pixel, A = 1).</summary>
        public void Finish(ushort[] overBlack, ushort[] overWhite)
        {
            if (!IsComplete) throw new InvalidOperationException("Not every sub-frame was added (" + Array.FindAll(_added, a => a).Length + " of " + _count + ").");
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

        double Linear(float value) => _gamma ? (value <= 0 ? 0 : Srgb.DecodeExact(Math.Min(1, (double)value))) : value;

        double Encoded(double linear) => _gamma ? Srgb.EncodeExact(Math.Max(0, Math.Min(1, linear))) : linear;

        /// <summary>The nearest IEEE half to a finite value (ties to even; beyond the largest half: infinity), for the averaged renders.</summary>
        public static ushort ToHalf(double value)
        {
            if (double.IsNaN(value)) return 0x7E00;
            var sign = value < 0 ? 0x8000 : 0;
            var a = Math.Abs(value);
            if (a == 0) return (ushort)sign;
            if (a >= 65520) return (ushort)(sign | 0x7C00);
            var exponent = (int)Math.Floor(Math.Log(a, 2));
            if (a < Math.Pow(2, exponent)) exponent--; // Log's rounding
            else if (a >= Math.Pow(2, exponent + 1)) exponent++;
            if (exponent < -14)
            {
                var sub = RoundEven(a / Math.Pow(2, -24));
                return (ushort)(sign | (int)sub); // 1024 rounds up into the smallest normal, which has the same bits
            }
            var mantissa = RoundEven((a / Math.Pow(2, exponent) - 1) * 1024);
            if (mantissa >= 1024)
            {
                mantissa = 0;
                exponent++;
            }
            if (exponent > 15) return (ushort)(sign | 0x7C00);
            return (ushort)(sign | ((exponent + 15) << 10) | (int)mantissa);
        }

        static double RoundEven(double v) => Math.Round(v, MidpointRounding.ToEven);
    }
}
