using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Uniform random points on the surface of a set of meshes: a triangle is chosen with probability proportional
    /// to its area (so density is the same everywhere), then a uniform point inside it with the square-root
    /// barycentric rule (a = 1 − √r₁, b = √r₁(1 − r₂), c = √r₁·r₂). Normals and colours are interpolated with the
    /// same weights; a triangle colour wins over vertex colours; without either the default colour is used; without
    /// vertex normals the normal is zero, as in 3DGS's own points3d.ply. Deterministic for a seed (SplitMix64).
    /// Area ratios survive rotations, reflections and uniform scales, so sampling in Unity's world and then moving
    /// the points with <see cref="CloudPoint.FromUnityWorld"/> gives the same distribution as sampling in the output.
    /// </summary>
    public static class SurfaceSampler
    {
        public const int MaxCount = 10_000_000;

        public static IReadOnlyList<CloudPoint> Sample(IReadOnlyList<SurfaceMesh> meshes, int count, long seed, Vector3d? defaultColor = null)
        {
            InvalidParameterException.ThrowIfAny(ValidationProblem.OutsideRange("pointCloud.count", count, 0, MaxCount));
            if (meshes == null) throw new ArgumentNullException(nameof(meshes));
            var fallback = defaultColor ?? new Vector3d(0.5, 0.5, 0.5);

            // Cumulative areas over every triangle of every mesh.
            var cumulative = new List<double>();
            var owners = new List<(int mesh, int triangle)>();
            double total = 0;
            for (var m = 0; m < meshes.Count; m++)
                for (var t = 0; t < meshes[m].TriangleCount; t++)
                {
                    var area = meshes[m].TriangleArea(t);
                    if (!(area > 0)) continue; // degenerate triangles can never be hit
                    total += area;
                    cumulative.Add(total);
                    owners.Add((m, t));
                }

            var points = new List<CloudPoint>(count);
            if (count == 0) return points;
            if (!(total > 0))
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("pointCloud.meshes", meshes.Count + " meshes", "have no triangle with a non-zero area to sample.", "Pick a target with visible mesh surfaces, or turn the point cloud off."),
                });

            var areas = cumulative.ToArray(); // arrays: this loop runs up to millions of times in the Editor
            var random = new SeededRandom(seed);
            for (var i = 0; i < count; i++)
            {
                var pick = Pick(areas, random.NextDouble() * total);
                var (m, t) = owners[pick];
                var s = Math.Sqrt(random.NextDouble());
                var r2 = random.NextDouble();
                points.Add(PointOn(meshes[m], t, 1 - s, s * (1 - r2), s * r2, fallback));
            }
            return points;
        }

        /// <summary>
        /// The point of triangle <paramref name="t"/> at barycentric weights (wa, wb, wc), with its interpolated normal
        /// and colour (triangle colour, else vertex colours, else <paramref name="fallback"/>).
        /// </summary>
        internal static CloudPoint PointOn(SurfaceMesh mesh, int t, double wa, double wb, double wc, Vector3d fallback)
        {
            var i0 = mesh.Triangles[3 * t];
            var i1 = mesh.Triangles[3 * t + 1];
            var i2 = mesh.Triangles[3 * t + 2];
            var position = wa * mesh.Vertices[i0] + wb * mesh.Vertices[i1] + wc * mesh.Vertices[i2];
            var normal = Vector3d.Zero;
            if (mesh.VertexNormals != null)
            {
                var n = wa * mesh.VertexNormals[i0] + wb * mesh.VertexNormals[i1] + wc * mesh.VertexNormals[i2];
                if (n.Length > 1e-12) normal = n.Normalized();
            }
            Vector3d color;
            if (mesh.TriangleColors != null) color = mesh.TriangleColors[t];
            else if (mesh.VertexColors != null) color = wa * mesh.VertexColors[i0] + wb * mesh.VertexColors[i1] + wc * mesh.VertexColors[i2];
            else color = fallback;
            return new CloudPoint(position, normal, CloudPoint.ToByte(color.X), CloudPoint.ToByte(color.Y), CloudPoint.ToByte(color.Z));
        }

        /// <summary>The first index whose cumulative area exceeds <paramref name="u"/> (binary search).</summary>
        internal static int Pick(double[] cumulative, double u)
        {
            int lo = 0, hi = cumulative.Length - 1;
            while (lo < hi)
            {
                var mid = (lo + hi) / 2;
                if (cumulative[mid] > u) hi = mid;
                else lo = mid + 1;
            }
            return lo;
        }
    }
}
