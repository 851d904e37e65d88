using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Which ground-truth surface points a set of views saw, decided by the views' own depth maps: a point is observed
    /// when it projects into a view's image (pinhole, OpenGL camera: +X right, +Y up, looking along −Z; pixel i covers
    /// [i, i + 1)) in front of the camera and the depth map at that pixel has a surface within <c>tolerance</c> +
    /// <c>pixelSlack</c> × (the pixel's footprint z / f) of the point's z-depth: the depth map holds the surface at the
    /// pixel's centre, and a sloped surface moves by about its slope × the footprint across one pixel. A point hidden behind nearer geometry, outside every frame or on a face no camera looked at is
    /// not observed. The same role as DTU's observation masks, from exact data instead of a reconstruction.
    /// </summary>
    public static class ObservedPoints
    {
        /// <summary>Pixel footprints of depth allowed besides the tolerance: surfaces up to about 56° from facing the camera.</summary>
        public const double DefaultPixelSlack = 1.5;

        /// <param name="points">x, y, z per point, output frame.</param>
        /// <param name="observed">Set to true for every point this view sees (never reset).</param>
        /// <param name="cameraToWorld">The view's transform_matrix.</param>
        /// <param name="depth">The view's z-depth per pixel in output units, rows top first (0 = no surface).</param>
        public static int Mark(float[] points, bool[] observed, Matrix4x4d cameraToWorld, float[] depth, int width, int height,
            double focal, double cx, double cy, double tolerance, double pixelSlack = DefaultPixelSlack)
        {
            var r0 = cameraToWorld.Column(0);
            var r1 = cameraToWorld.Column(1);
            var r2 = cameraToWorld.Column(2);
            var t = cameraToWorld.Translation;
            var marked = 0;
            for (var p = 0; p < observed.Length; p++)
            {
                if (observed[p]) continue;
                double dx = points[3 * p] - t.X, dy = points[3 * p + 1] - t.Y, dz = points[3 * p + 2] - t.Z;
                // Camera coordinates: the rotation's columns are the camera axes in the world.
                var xc = r0.X * dx + r0.Y * dy + r0.Z * dz;
                var yc = r1.X * dx + r1.Y * dy + r1.Z * dz;
                var z = -(r2.X * dx + r2.Y * dy + r2.Z * dz);
                if (!(z > 0)) continue;
                var u = cx + focal * xc / z;
                var v = cy - focal * yc / z;
                if (!(u >= 0 && v >= 0 && u < width && v < height)) continue;
                var surface = depth[(int)v * width + (int)u];
                if (surface > 0 && Math.Abs(surface - z) <= tolerance + pixelSlack * z / focal)
                {
                    observed[p] = true;
                    marked++;
                }
            }
            return marked;
        }
    }
}
