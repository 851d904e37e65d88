using System;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// NeRF's own ray generation (bmild/nerf run_nerf_helpers.get_rays): for pixel (i, j), column i and row j from
    /// the top, the camera-space direction is ((i − W/2)/f, −(j − H/2)/f, −1), rotated by the c2w matrix's 3×3 part;
    /// the origin is its translation; f = 0.5·W / tan(0.5·camera_angle_x). Written here from the formula, not from
    /// Core, so that it is an independent arbiter.
    /// </summary>
    static class NerfRays
    {
        public static void Ray(double[][] c2w, double cameraAngleX, int width, int height, double i, double j,
            out double[] origin, out double[] direction)
        {
            var focal = 0.5 * width / Math.Tan(0.5 * cameraAngleX);
            var d = new[] { (i - width * 0.5) / focal, -(j - height * 0.5) / focal, -1.0 };
            direction = new double[3];
            origin = new double[3];
            for (var r = 0; r < 3; r++)
            {
                direction[r] = c2w[r][0] * d[0] + c2w[r][1] * d[1] + c2w[r][2] * d[2];
                origin[r] = c2w[r][3];
            }
        }

        /// <summary>Distance from <paramref name="point"/> to the ray, and the ray parameter of the closest point (along the unnormalised direction).</summary>
        public static double DistanceToRay(double[] origin, double[] direction, double[] point, out double t)
        {
            var op = new[] { point[0] - origin[0], point[1] - origin[1], point[2] - origin[2] };
            var dd = direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2];
            t = (op[0] * direction[0] + op[1] * direction[1] + op[2] * direction[2]) / dd;
            var closest = new[] { op[0] - t * direction[0], op[1] - t * direction[1], op[2] - t * direction[2] };
            return Math.Sqrt(closest[0] * closest[0] + closest[1] * closest[1] + closest[2] * closest[2]);
        }
    }
}
