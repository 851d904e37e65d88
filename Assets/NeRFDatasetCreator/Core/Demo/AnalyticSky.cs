using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A small analytic HDR environment for the relight demo and the tests, in the output world (<see cref="Equirect"/>):
    /// a sky from a warm horizon to a blue zenith, a dark ground, and a sun disc whose radiance is far above 1, so that
    /// a rotation moves a clear highlight and shading.
    /// </summary>
    public static class AnalyticSky
    {
        /// <summary>The sun's direction (towards it): 30° azimuth from +X towards +Y, 35° above the horizon.</summary>
        public static readonly Vector3d Sun = Equirect.Direction(0.5 - 30.0 / 360, (90.0 - 35) / 180);

        /// <summary>The sun disc's angular radius (degrees) and radiance (linear, per channel).</summary>
        public const double SunRadiusDegrees = 4, SunRadiance = 120;

        static readonly double[] Zenith = { 0.25, 0.45, 0.95 }, Horizon = { 0.95, 0.8, 0.6 }, Ground = { 0.18, 0.16, 0.14 };

        /// <summary>The radiance arriving from <paramref name="d"/> (unit, output world) into <paramref name="result"/>.</summary>
        public static void Radiance(Vector3d d, double[] result)
        {
            if (Vector3d.Dot(d, Sun) >= Math.Cos(SunRadiusDegrees * Math.PI / 180))
            {
                for (var c = 0; c < 3; c++) result[c] = SunRadiance;
                return;
            }
            if (d.Z < 0)
            {
                for (var c = 0; c < 3; c++) result[c] = Ground[c];
                return;
            }
            var t = Math.Sqrt(d.Z); // the blue deepens quickly above the horizon
            for (var c = 0; c < 3; c++) result[c] = Horizon[c] * (1 - t) + Zenith[c] * t;
        }

        /// <summary>The sky as a W × W/2 equirect (pixel centres sampled).</summary>
        public static EnvironmentMap Map(int width = 128)
        {
            int height = width / 2;
            var rgb = new float[width * height * 3];
            var sample = new double[3];
            for (var row = 0; row < height; row++)
                for (var column = 0; column < width; column++)
                {
                    Radiance(Equirect.PixelDirection(column, row, width, height), sample);
                    for (var c = 0; c < 3; c++) rgb[(row * width + column) * 3 + c] = (float)sample[c];
                }
            return new EnvironmentMap(width, height, rgb);
        }
    }
}
