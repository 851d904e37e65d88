using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// An environment as a float RGB equirect map in the output world (<see cref="Equirect"/>'s convention): W = 2H,
    /// 3 floats a pixel, rows top first (top row +Z). What <c>lights/&lt;name&gt;.exr</c> holds, unrotated.
    /// </summary>
    public sealed class EnvironmentMap
    {
        public EnvironmentMap(int width, int height, float[] rgb)
        {
            if (width < 2 || height < 1 || width != 2 * height)
                throw new ArgumentOutOfRangeException(nameof(width), width + "×" + height, "an equirect map is twice as wide as it is high");
            if (rgb == null || rgb.Length != width * height * 3) throw new ArgumentException("3 floats (R G B) per pixel are needed.", nameof(rgb));
            Width = width;
            Height = height;
            Rgb = rgb;
        }

        public int Width { get; }
        public int Height { get; }

        /// <summary>R G B per pixel, rows top first.</summary>
        public float[] Rgb { get; }

        /// <summary>The radiance arriving from output-world direction <paramref name="d"/> (bilinear, <see cref="Equirect.Sample"/>).</summary>
        public void Radiance(Vector3d d, double[] result)
        {
            Equirect.Uv(d, out var u, out var v);
            Equirect.Sample(Rgb, Width, Height, u, v, result);
        }

        /// <summary>
        /// The radiance from <paramref name="d"/> with the map rotated by <paramref name="degrees"/> (<see cref="Equirect"/>):
        /// the light now arriving from d arrived from Rz(−θ)·d.
        /// </summary>
        public void Radiance(Vector3d d, double degrees, double[] result) => Radiance(Equirect.RotateZ(d, -degrees), result);

        /// <summary>The map resampled onto a W×H grid, rotated by <paramref name="degrees"/> (bilinear, wrapping): what a trainer wanting one file per rotation reads.</summary>
        public EnvironmentMap Rotated(double degrees, int width = 0)
        {
            if (width <= 0) width = Width;
            int height = width / 2;
            var rgb = new float[width * height * 3];
            var sample = new double[3];
            for (var row = 0; row < height; row++)
                for (var column = 0; column < width; column++)
                {
                    Radiance(Equirect.PixelDirection(column, row, width, height), degrees, sample);
                    var at = (row * width + column) * 3;
                    for (var c = 0; c < 3; c++) rgb[at + c] = (float)sample[c];
                }
            return new EnvironmentMap(width, height, rgb);
        }

        /// <summary>R G B floats, rows bottom-up, as <see cref="ExrEncoder"/> takes them (3 channels: <see cref="ExrWriter"/>).</summary>
        public float[] ToRgbBottomUp()
        {
            var pixels = new float[Width * Height * 3];
            for (var row = 0; row < Height; row++)
                Array.Copy(Rgb, row * Width * 3, pixels, (Height - 1 - row) * Width * 3, Width * 3);
            return pixels;
        }
    }
}
