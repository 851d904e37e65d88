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
