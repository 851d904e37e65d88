using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-view error picture: per pixel the mean absolute difference over R, G, B (in [0, 1]) through a black →
    /// purple → orange → pale yellow ramp (after matplotlib's 'inferno'), saturating at <see cref="FullScale"/>, as an
    /// 8-bit RGB image; and box-filtered thumbnails for the HTML report.
    /// </summary>
    public static class ErrorMap
    {
        /// <summary>The error that reaches the ramp's end: 0.2, about 51 of 255 levels.</summary>
        public const double FullScale = 0.2;

        static readonly double[,] Stops =
        {
            { 0.0, 0.0, 0.0, 0.02 },
            { 0.33, 0.34, 0.06, 0.43 },
            { 0.66, 0.87, 0.32, 0.23 },
            { 1.0, 0.99, 0.99, 0.64 },
        };

        public static byte[] Render(float[] render, float[] truth, int width, int height)
        {
            var rgb = new byte[width * height * 3];
            for (var p = 0; p < width * height; p++)
            {
                var e = (Math.Abs(render[3 * p] - truth[3 * p]) + Math.Abs(render[3 * p + 1] - truth[3 * p + 1]) + Math.Abs(render[3 * p + 2] - truth[3 * p + 2])) / 3.0;
                Ramp(Math.Min(1, e / FullScale), rgb, 3 * p);
            }
            return rgb;
        }

        public static void Ramp(double t, byte[] rgb, int at)
        {
            var k = 0;
            while (k < Stops.GetLength(0) - 2 && t > Stops[k + 1, 0]) k++;
            var f = (t - Stops[k, 0]) / (Stops[k + 1, 0] - Stops[k, 0]);
            f = Math.Max(0, Math.Min(1, f));
            for (var c = 0; c < 3; c++)
                rgb[at + c] = (byte)Math.Round(255 * (Stops[k, c + 1] + f * (Stops[k + 1, c + 1] - Stops[k, c + 1])));
        }

        /// <summary>8-bit RGB from float RGB in [0, 1].</summary>
        public static byte[] ToBytes(float[] rgb)
        {
            var bytes = new byte[rgb.Length];
            for (var i = 0; i < rgb.Length; i++) bytes[i] = (byte)Math.Round(255 * Math.Max(0, Math.Min(1, rgb[i])));
            return bytes;
        }

        /// <summary>An 8-bit RGB image shrunk by an integer box filter so that its longer side is at most <paramref name="maxSide"/>.</summary>
        public static byte[] Thumbnail(byte[] rgb, int width, int height, int maxSide, out int thumbWidth, out int thumbHeight)
        {
            var factor = Math.Max(1, (Math.Max(width, height) + maxSide - 1) / maxSide);
            thumbWidth = width / factor;
            thumbHeight = height / factor;
            var result = new byte[thumbWidth * thumbHeight * 3];
            var area = factor * factor;
            for (var y = 0; y < thumbHeight; y++)
                for (var x = 0; x < thumbWidth; x++)
                    for (var c = 0; c < 3; c++)
                    {
                        var sum = 0;
                        for (var dy = 0; dy < factor; dy++)
                        {
                            var row = ((y * factor + dy) * width + x * factor) * 3 + c;
                            for (var dx = 0; dx < factor; dx++) sum += rgb[row + 3 * dx];
                        }
                        result[(y * thumbWidth + x) * 3 + c] = (byte)((sum + area / 2) / area);
                    }
            return result;
        }
    }
}
