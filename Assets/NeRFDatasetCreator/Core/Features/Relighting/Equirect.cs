using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The equirect convention of lights.json (contract of issue 38), Blender's world convention that TensoIR, NeRFactor
    /// and R3DG share (Documentation~/maintainers/relighting.md cites each loader): for a unit direction d FROM the
    /// surface TOWARDS the light in the output world (+Z up), u = 0.5 − atan2(y, x) / 2π and v = acos(z) / π, both in
    /// [0, 1); column u·W from the left, row v·H from the top (top row +Z), u wraps. A rotation by θ degrees is
    /// counter-clockwise about +Z seen from above: the light that arrived from d arrives from Rz(θ)·d.
    /// </summary>
    public static class Equirect
    {
        /// <summary>(u, v) of a direction (any length &gt; 0), u in [0, 1).</summary>
        public static void Uv(Vector3d d, out double u, out double v)
        {
            var n = d.Normalized();
            u = 0.5 - Math.Atan2(n.Y, n.X) / (2 * Math.PI);
            if (u >= 1) u -= 1;
            if (u < 0) u += 1;
            v = Math.Acos(Math.Max(-1, Math.Min(1, n.Z))) / Math.PI;
        }

        /// <summary>The unit direction of (u, v): the inverse of <see cref="Uv"/>.</summary>
        public static Vector3d Direction(double u, double v)
        {
            double phi = (0.5 - u) * 2 * Math.PI, theta = v * Math.PI;
            var s = Math.Sin(theta);
            return new Vector3d(s * Math.Cos(phi), s * Math.Sin(phi), Math.Cos(theta));
        }

        /// <summary>The direction through the centre of pixel (column, row) of a W×H map.</summary>
        public static Vector3d PixelDirection(int column, int row, int width, int height) =>
            Direction((column + 0.5) / width, (row + 0.5) / height);

        /// <summary>Rz(θ)·d: counter-clockwise about +Z seen from above by <paramref name="degrees"/>.</summary>
        public static Vector3d RotateZ(Vector3d d, double degrees)
        {
            var a = degrees * Math.PI / 180;
            double c = Math.Cos(a), s = Math.Sin(a);
            return new Vector3d(c * d.X - s * d.Y, s * d.X + c * d.Y, d.Z);
        }

        /// <summary>
        /// Bilinear sample of a W×H RGB map (3 floats a pixel, rows top first) at (u, v): between pixel centres, columns
        /// wrapping around (u = 0 meets u = 1), rows clamped at the poles.
        /// </summary>
        public static void Sample(float[] rgb, int width, int height, double u, double v, double[] result)
        {
            double x = u * width - 0.5, y = v * height - 0.5;
            int x0 = (int)Math.Floor(x), y0 = (int)Math.Floor(y);
            double fx = x - x0, fy = y - y0;
            int xa = Wrap(x0, width), xb = Wrap(x0 + 1, width);
            int ya = Clamp(y0, height), yb = Clamp(y0 + 1, height);
            for (var c = 0; c < 3; c++)
            {
                double top = rgb[(ya * width + xa) * 3 + c] * (1 - fx) + rgb[(ya * width + xb) * 3 + c] * fx;
                double bottom = rgb[(yb * width + xa) * 3 + c] * (1 - fx) + rgb[(yb * width + xb) * 3 + c] * fx;
                result[c] = top * (1 - fy) + bottom * fy;
            }
        }

        static int Wrap(int x, int n) => ((x % n) + n) % n;

        static int Clamp(int y, int n) => y < 0 ? 0 : y >= n ? n - 1 : y;
    }
}
