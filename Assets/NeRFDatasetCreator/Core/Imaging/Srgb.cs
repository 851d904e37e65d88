using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The sRGB transfer function (IEC 61966-2-1) between 8-bit encoded values and linear light in [0, 1].
    /// Decoding is a 256-entry table; encoding is a 65 536-bucket table plus one threshold comparison, which gives
    /// exactly the byte that rounding the standard formula gives (up to float rounding at a threshold), without a
    /// Math.Pow per pixel.
    /// </summary>
    public static class Srgb
    {
        const int EncodeBuckets = 65536;

        // Immutable after the static constructor, so every thread may read them.
        static readonly float[] DecodeTable = new float[256];
        // One entry more than buckets so that exactly 1.0 indexes it (255) without a test.
        static readonly byte[] EncodeTable = new byte[EncodeBuckets + 1];

        // Threshold[b] is the smallest linear value that encodes to at least b; Threshold[256] = +infinity so that
        // the correction step needs no bounds test.
        static readonly float[] Threshold = new float[257];

        static Srgb()
        {
            for (int b = 0; b < 256; b++) DecodeTable[b] = (float)DecodeExact(b / 255.0);
            Threshold[0] = float.NegativeInfinity;
            for (int b = 1; b < 256; b++) Threshold[b] = (float)DecodeExact((b - 0.5) / 255.0);
            Threshold[256] = float.PositiveInfinity;
            for (int i = 0; i <= EncodeBuckets; i++) EncodeTable[i] = EncodeByteExact(i / (double)EncodeBuckets);
        }

        /// <summary>The standard decode: c/12.92 for c ≤ 0.04045, else ((c + 0.055)/1.055)^2.4.</summary>
        public static double DecodeExact(double encoded) =>
            encoded <= 0.04045 ? encoded / 12.92 : Math.Pow((encoded + 0.055) / 1.055, 2.4);

        /// <summary>The standard encode: 12.92·l for l ≤ 0.0031308, else 1.055·l^(1/2.4) − 0.055.</summary>
        public static double EncodeExact(double linear) =>
            linear <= 0.0031308 ? linear * 12.92 : 1.055 * Math.Pow(linear, 1 / 2.4) - 0.055;

        /// <summary>round(255·encode(clamp(l, 0, 1))) by the formula; the reference the fast path is tested against.</summary>
        public static byte EncodeByteExact(double linear)
        {
            if (!(linear > 0)) return 0;
            if (linear >= 1) return 255;
            return (byte)Math.Floor(EncodeExact(linear) * 255 + 0.5);
        }

        /// <summary>Linear value of an sRGB-encoded byte.</summary>
        public static float Decode(byte encoded) => DecodeTable[encoded];

        /// <summary>
        /// sRGB byte of a linear value; NaN and negatives give 0, values ≥ 1 give 255. A bucket is 1/65536 wide
        /// and the closest two thresholds are 1/3295 apart, so a bucket holds at most one threshold: the table
        /// gives the byte at the bucket's lower edge and one comparison moves it up if the value passed it.
        /// </summary>
        public static byte Encode(float linear)
        {
            if (!(linear > 0)) return 0;
            if (linear >= 1) return 255;
            int b = EncodeTable[(int)(linear * EncodeBuckets)];
            return linear >= Threshold[b + 1] ? (byte)(b + 1) : (byte)b;
        }

        /// <summary>Like <see cref="Encode"/> for a value already known to be in [0, 1] (no range tests).</summary>
        internal static byte EncodeUnit(float linear)
        {
            int b = EncodeTable[(int)(linear * EncodeBuckets)];
            return linear >= Threshold[b + 1] ? (byte)(b + 1) : (byte)b;
        }

        /// <summary>The decode table itself, for hot loops that index it directly (do not modify).</summary>
        internal static float[] DecodeLookup => DecodeTable;

        /// <summary>The tables behind <see cref="EncodeUnit"/>, for hot loops that write it out (do not modify).</summary>
        internal static byte[] EncodeBucketLookup => EncodeTable;

        internal static float[] EncodeThresholdLookup => Threshold;

        internal const float EncodeBucketScale = EncodeBuckets;
    }
}
