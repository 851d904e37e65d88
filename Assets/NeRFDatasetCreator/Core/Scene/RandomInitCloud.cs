using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The stand-in cloud 3DGS's own Blender loader generates when a dataset has no points3d.ply: uniform points in
    /// [−h, h]³ (h = 1.3), colours ≈ mid-grey. Used only when a COLMAP export has no real cloud, because 3DGS's
    /// COLMAP loader fails on an empty points3D.txt.
    /// </summary>
    public static class RandomInitCloud
    {
        public const int DefaultCount = 100_000;

        public static IReadOnlyList<CloudPoint> Cube(int count, double halfSize, long seed)
        {
            InvalidParameterException.ThrowIfAny(
                ValidationProblem.OutsideRange("pointCloud.count", count, 0, SurfaceSampler.MaxCount),
                ValidationProblem.OutsideRange("pointCloud.halfSize", halfSize, 1e-9, 1e9));
            var random = new SeededRandom(seed);
            var points = new List<CloudPoint>(count);
            for (var i = 0; i < count; i++)
            {
                var p = new Vector3d((2 * random.NextDouble() - 1) * halfSize, (2 * random.NextDouble() - 1) * halfSize, (2 * random.NextDouble() - 1) * halfSize);
                points.Add(new CloudPoint(p, Vector3d.Zero, 128, 128, 128));
            }
            return points;
        }
    }
}
