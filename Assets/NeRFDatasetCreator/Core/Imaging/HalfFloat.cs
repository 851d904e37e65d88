namespace NerfDatasetCreator
{
    /// <summary>
    /// IEEE 754 binary16 ("half", Unity's <c>R16G16B16A16_SFloat</c>) to float. .NET Standard 2.1 has no
    /// <c>System.Half</c>, so the 65 536 possible values are decoded once into a table (256 KB) that hot loops index.
    /// </summary>
    public static class HalfFloat
    {
        static readonly float[] Table = BuildTable();

        /// <summary>The float a half's bits stand for (exact: every half is a float).</summary>
        public static float ToFloat(ushort bits) => Table[bits];

        /// <summary>The table itself, for hot loops (do not modify).</summary>
        internal static float[] Lookup => Table;

        /// <summary>
        /// The nearest half to <paramref name="value"/> (round half to even, as a GPU's float-to-half conversion);
        /// beyond the largest half (65504) infinity, NaN stays NaN.
        /// </summary>
        public static ushort FromFloat(float value)
        {
            var bits = System.BitConverter.SingleToInt32Bits(value);
            var sign = (bits >> 16) & 0x8000;
            var exponent = (bits >> 23) & 0xFF;
            var mantissa = bits & 0x7FFFFF;
            if (exponent == 0xFF) return (ushort)(sign | 0x7C00 | (mantissa != 0 ? 0x200 : 0));
            var e = exponent - 127 + 15;
            if (e >= 31) return (ushort)(sign | 0x7C00);
            if (e <= 0)
            {
                if (e < -10) return (ushort)sign; // below half the smallest subnormal
                mantissa |= 0x800000; // the implicit 1
                var shift = 14 - e;
                var half = mantissa >> shift;
                var rest = mantissa & ((1 << shift) - 1);
                var midway = 1 << (shift - 1);
                if (rest > midway || (rest == midway && (half & 1) != 0)) half++;
                return (ushort)(sign | half);
            }
            var result = (e << 10) | (mantissa >> 13);
            var remainder = mantissa & 0x1FFF;
            // A carry out of the mantissa moves to the exponent (and to infinity at the top), as it should.
            if (remainder > 0x1000 || (remainder == 0x1000 && (result & 1) != 0)) result++;
            return (ushort)(sign | result);
        }

        static float[] BuildTable()
        {
            var table = new float[65536];
            for (int i = 0; i < table.Length; i++) table[i] = Decode(i);
            return table;
        }

        static float Decode(int bits)
        {
            int sign = (bits >> 15) & 1, exponent = (bits >> 10) & 0x1F, mantissa = bits & 0x3FF;
            double value;
            if (exponent == 0) value = mantissa * System.Math.Pow(2, -24); // zero and subnormals
            else if (exponent == 31) value = mantissa == 0 ? double.PositiveInfinity : double.NaN;
            else value = (1 + mantissa / 1024.0) * System.Math.Pow(2, exponent - 15);
            return (float)(sign == 1 ? -value : value);
        }
    }
}
