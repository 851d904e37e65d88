using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>A colour as plain floats in [0, 1] (sRGB, straight alpha), so Core can own the preview's palette.</summary>
    [Serializable]
    public readonly struct RgbaColor
    {
        public RgbaColor(float r, float g, float b, float a = 1f)
        {
            R = r;
            G = g;
            B = b;
            A = a;
        }

        public float R { get; }
        public float G { get; }
        public float B { get; }
        public float A { get; }

        /// <summary>The colour of 8-bit sRGB components, as palettes are usually published.</summary>
        public static RgbaColor FromBytes(byte r, byte g, byte b) => new RgbaColor(r / 255f, g / 255f, b / 255f, 1f);

        public override string ToString() =>
            string.Format(CultureInfo.InvariantCulture, "RGBA({0:R}, {1:R}, {2:R}, {3:R})", R, G, B, A);
    }
}
