using System;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Readbacks of a known picture, shaped as the Unity capture delivers them (rows bottom-up, colour premultiplied
    /// by coverage over a black clear). Output 12×8 at supersampling 2: output columns 0–3 are covered, column 4 is
    /// half covered (its left samples only), columns 5–11 are background. Depth and normals come at the output size.
    /// </summary>
    static class SyntheticViews
    {
        public const int Width = 12, Height = 8, K = 2;
        public static readonly byte[] Srgb = { 200, 100, 50 };

        public static RawFrame Colour()
        {
            int w = Width * K, h = Height * K;
            var frame = new RawFrame(w, h, K) { ColorSrgb = new byte[w * h * 4], Mask = new byte[w * h], MaskBytesPerPixel = 1 };
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    if (x > 4 * K) continue; // raw column 8 is the left half of output column 4
                    var i = y * w + x;
                    frame.Mask[i] = 255;
                    frame.ColorSrgb[i * 4] = Srgb[0];
                    frame.ColorSrgb[i * 4 + 1] = Srgb[1];
                    frame.ColorSrgb[i * 4 + 2] = Srgb[2];
                    frame.ColorSrgb[i * 4 + 3] = 255;
                }
            return frame;
        }

        /// <summary>
        /// The same geometry as <see cref="Colour"/> seen through grey glass (alpha 0.5, straight linear colour 0.5), as the
        /// capture delivers it for difference matting: the colour pass over black (K = 0.25) and over white (W = 0.75;
        /// empty samples 0 and 1) as halves, and the mask pass's geometry coverage (255 where the glass is).
        /// </summary>
        public static RawFrame MattedColour()
        {
            int w = Width * K, h = Height * K;
            var frame = new RawFrame(w, h, K) { ColorOverBlack = new ushort[w * h * 4], ColorOverWhite = new ushort[w * h * 4], Mask = new byte[w * h], MaskBytesPerPixel = 1 };
            const ushort quarter = 0x3400, threeQuarters = 0x3A00, one = 0x3C00;
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    var i = y * w + x;
                    var covered = x <= 4 * K;
                    if (covered) frame.Mask[i] = 255;
                    for (var c = 0; c < 3; c++)
                    {
                        frame.ColorOverBlack[i * 4 + c] = covered ? quarter : (ushort)0;
                        frame.ColorOverWhite[i * 4 + c] = covered ? threeQuarters : one;
                    }
                }
            return frame;
        }

        /// <summary>Depth 2 m + 0.1 m per row from the bottom where covered; normals straight up (output +Z).</summary>
        public static RawFrame Data(double extraMetres = 0)
        {
            var frame = new RawFrame(Width, Height, 1) { Depth = new float[Width * Height], Normals = new float[Width * Height * 4] };
            for (var y = 0; y < Height; y++)
                for (var x = 0; x <= 4; x++)
                {
                    var i = y * Width + x;
                    frame.Depth[i] = (float)(2.0 + 0.1 * y + extraMetres);
                    frame.Normals[i * 4 + 2] = 1;
                    frame.Normals[i * 4 + 3] = 1;
                }
            return frame;
        }

        /// <summary>An EXR stand-in that records its calls (Core has no EXR writer; Unity's encoder is passed in).</summary>
        public static byte[] FakeExr(float[] pixels, int width, int height, int channels)
        {
            if (pixels.Length != width * height * channels) throw new ArgumentException("pixel count does not match the size");
            return new[] { (byte)'E', (byte)'X', (byte)'R', (byte)channels };
        }
    }
}
