using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>What <see cref="SphereSurfaceSampler.Sample"/> kept and how many points it drew for it.</summary>
    public sealed class SphereSurfaceSample
    {
        public SphereSurfaceSample(IReadOnlyList<CloudPoint> points, int drawn)
        {
            Points = points;
            Drawn = drawn;
        }

        /// <summary>The points within the sphere: the requested count unless the draws ran out (see <see cref="SphereSurfaceSampler.MaxDrawsPerPoint"/>).</summary>
        public IReadOnlyList<CloudPoint> Points { get; }

        /// <summary>Points drawn on the candidate surface, kept or not.</summary>
        public int Drawn { get; }
    }

    /// <summary>
    /// Uniform random points on the part of a set of meshes that lies within a sphere — an environment's surface near
    /// its capture volume, for 3DGS's initial cloud. Every triangle is cut down to the sphere first: a piece with all
    /// corners inside is kept whole, a piece whose bounding sphere misses the sphere is dropped, and a piece that
    /// straddles its surface is split in four at its edge midpoints until it is no longer than
    /// radius / <see cref="StraddleDivisions"/> (at most <see cref="MaxDepth"/> times), so a ground plane a kilometre
    /// wide does not make most draws miss a ten-metre sphere. Points are then drawn area-uniformly on the kept pieces
    /// (<see cref="SurfaceSampler"/>'s square-root rule inside a piece, mapped to its triangle's barycentric weights
    /// for the normal and colour) and the few that land outside the sphere are rejected and drawn again: rejection
    /// keeps the distribution uniform over the surface inside, and drawing on until <c>count</c> are kept gives the
    /// requested count exactly. Deterministic for a seed.
    /// </summary>
    public static class SphereSurfaceSampler
    {
        /// <summary>A straddling piece is split until its longest edge is at most radius / this.</summary>
        public const int StraddleDivisions = 8;

        /// <summary>Splits of one triangle at most (4^24 pieces could only come from a triangle ~10⁷ times the radius).</summary>
        public const int MaxDepth = 24;

        /// <summary>Draws per wanted point before giving up: only reached when almost no kept area lies inside.</summary>
        public const int MaxDrawsPerPoint = 64;

        public static SphereSurfaceSample Sample(IReadOnlyList<SurfaceMesh> meshes, int count, long seed, Vector3d centre, double radius,
            Vector3d? defaultColor = null)
        {
            InvalidParameterException.ThrowIfAny(ValidationProblem.OutsideRange("pointCloud.count", count, 0, SurfaceSampler.MaxCount));
            if (meshes == null) throw new ArgumentNullException(nameof(meshes));
            if (!(radius > 0) || double.IsInfinity(radius) || !centre.IsFinite)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("pointCloudRadius", ValidationProblem.Format(radius), "must be a finite distance above 0 around a finite centre.", "Use a positive radius."),
                });
            var fallback = defaultColor ?? new Vector3d(0.5, 0.5, 0.5);
            var pieces = Pieces(meshes, centre, radius);
            var points = new List<CloudPoint>(count);
            if (count == 0) return new SphereSurfaceSample(points, 0);
            if (pieces.Count == 0)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("pointCloudRadius", ValidationProblem.Format(radius),
                        "holds no mesh surface: no triangle of the " + meshes.Count + " meshes comes within it of the capture volume's centre " + centre + ".",
                        "Raise pointCloudRadius (0 picks it from the volume boxes), or set pointCloudPoints to 0."),
                });

            var cumulative = new double[pieces.Count];
            double total = 0;
            for (var i = 0; i < pieces.Count; i++) cumulative[i] = total += pieces[i].Area;
            var random = new SeededRandom(seed);
            var r2 = radius * radius;
            var maxDraws = (long)count * MaxDrawsPerPoint;
            var drawn = 0;
            while (points.Count < count && drawn < maxDraws)
            {
                var piece = pieces[SurfaceSampler.Pick(cumulative, random.NextDouble() * total)];
                var s = Math.Sqrt(random.NextDouble());
                var u = random.NextDouble();
                double a = 1 - s, b = s * (1 - u), c = s * u;
                drawn++;
                // The piece's corners are barycentric weights of its triangle; the point's weights are their blend.
                var w = a * piece.W0 + b * piece.W1 + c * piece.W2;
                var point = SurfaceSampler.PointOn(meshes[piece.Mesh], piece.Triangle, w.X, w.Y, w.Z, fallback);
                if ((point.Position - centre).LengthSquared > r2) continue;
                points.Add(point);
            }
            return new SphereSurfaceSample(points, drawn);
        }

        /// <summary>The pieces of every triangle that may reach into the sphere (see the class summary).</summary>
        internal static List<Piece> Pieces(IReadOnlyList<SurfaceMesh> meshes, Vector3d centre, double radius)
        {
            var pieces = new List<Piece>();
            var stack = new Stack<(Vector3d p0, Vector3d p1, Vector3d p2, Vector3d w0, Vector3d w1, Vector3d w2, int depth)>();
            var smallEnough = radius / StraddleDivisions;
            for (var m = 0; m < meshes.Count; m++)
            {
                var mesh = meshes[m];
                for (var t = 0; t < mesh.TriangleCount; t++)
                {
                    if (!(mesh.TriangleArea(t) > 0)) continue;
                    stack.Push((mesh.Vertices[mesh.Triangles[3 * t]], mesh.Vertices[mesh.Triangles[3 * t + 1]], mesh.Vertices[mesh.Triangles[3 * t + 2]],
                        Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ, 0));
                    while (stack.Count > 0)
                    {
                        var q = stack.Pop();
                        var inside = Inside(q.p0, centre, radius) && Inside(q.p1, centre, radius) && Inside(q.p2, centre, radius);
                        if (!inside)
                        {
                            var mid = (q.p0 + q.p1 + q.p2) * (1.0 / 3);
                            var reach = Math.Max((q.p0 - mid).Length, Math.Max((q.p1 - mid).Length, (q.p2 - mid).Length));
                            if ((mid - centre).Length - reach > radius) continue; // the piece's bounding sphere misses
                            var longest = Math.Max((q.p1 - q.p0).Length, Math.Max((q.p2 - q.p1).Length, (q.p0 - q.p2).Length));
                            if (longest > smallEnough && q.depth < MaxDepth)
                            {
                                Vector3d p01 = 0.5 * (q.p0 + q.p1), p12 = 0.5 * (q.p1 + q.p2), p20 = 0.5 * (q.p2 + q.p0);
                                Vector3d w01 = 0.5 * (q.w0 + q.w1), w12 = 0.5 * (q.w1 + q.w2), w20 = 0.5 * (q.w2 + q.w0);
                                var d = q.depth + 1;
                                stack.Push((q.p0, p01, p20, q.w0, w01, w20, d));
                                stack.Push((p01, q.p1, p12, w01, q.w1, w12, d));
                                stack.Push((p20, p12, q.p2, w20, w12, q.w2, d));
                                stack.Push((p01, p12, p20, w01, w12, w20, d));
                                continue;
                            }
                        }
                        var area = 0.5 * Vector3d.Cross(q.p1 - q.p0, q.p2 - q.p0).Length;
                        if (area > 0) pieces.Add(new Piece(m, t, q.w0, q.w1, q.w2, area));
                    }
                }
            }
            return pieces;
        }

        static bool Inside(Vector3d p, Vector3d centre, double radius) => (p - centre).LengthSquared <= radius * radius;

        /// <summary>Part of a triangle: its corners as barycentric weights of the triangle, and its area.</summary>
        internal readonly struct Piece
        {
            public Piece(int mesh, int triangle, Vector3d w0, Vector3d w1, Vector3d w2, double area)
            {
                Mesh = mesh;
                Triangle = triangle;
                W0 = w0;
                W1 = w1;
                W2 = w2;
                Area = area;
            }

            public int Mesh { get; }
            public int Triangle { get; }
            public Vector3d W0 { get; }
            public Vector3d W1 { get; }
            public Vector3d W2 { get; }
            public double Area { get; }
        }
    }
}
