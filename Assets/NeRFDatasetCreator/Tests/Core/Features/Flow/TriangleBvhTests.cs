using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class TriangleBvhTests
    {
        /// <summary>The nearest hit by testing every triangle (no tree), with the textbook ray–plane / inside-edges test.</summary>
        static bool BruteForce(double[] v, int[] tris, Vector3d o, Vector3d d, out double best, out int which)
        {
            best = double.PositiveInfinity;
            which = -1;
            for (var t = 0; t < tris.Length / 3; t++)
            {
                var a = new Vector3d(v[3 * tris[3 * t]], v[3 * tris[3 * t] + 1], v[3 * tris[3 * t] + 2]);
                var b = new Vector3d(v[3 * tris[3 * t + 1]], v[3 * tris[3 * t + 1] + 1], v[3 * tris[3 * t + 1] + 2]);
                var c = new Vector3d(v[3 * tris[3 * t + 2]], v[3 * tris[3 * t + 2] + 1], v[3 * tris[3 * t + 2] + 2]);
                var n = Vector3d.Cross(b - a, c - a);
                var denominator = Vector3d.Dot(n, d);
                if (denominator == 0) continue;
                var s = Vector3d.Dot(n, a - o) / denominator;
                if (s <= 0 || s >= best) continue;
                var p = o + d * s;
                // Inside when p is on the same side of all three edges as the triangle's normal.
                if (Vector3d.Dot(Vector3d.Cross(b - a, p - a), n) < 0 || Vector3d.Dot(Vector3d.Cross(c - b, p - b), n) < 0 || Vector3d.Dot(Vector3d.Cross(a - c, p - c), n) < 0) continue;
                best = s;
                which = t;
            }
            return which >= 0;
        }

        [Test]
        public void NearestHitEqualsTestingEveryTriangle()
        {
            var random = new Random(7);
            var v = new double[3 * 900];
            for (var i = 0; i < v.Length; i++) v[i] = random.NextDouble() * 2 - 1;
            var tris = new int[3 * 300];
            for (var i = 0; i < tris.Length; i++) tris[i] = i; // a soup: each triangle its own three random vertices
            var bvh = TriangleBvh.Build(v, tris);
            Assert.That(bvh.TriangleCount, Is.EqualTo(300));
            int hits = 0, misses = 0;
            for (var r = 0; r < 3000; r++)
            {
                var o = new Vector3d(random.NextDouble() * 6 - 3, random.NextDouble() * 6 - 3, random.NextDouble() * 6 - 3);
                var d = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5) - o * 0.3;
                var expected = BruteForce(v, tris, o, d, out var bestT, out var which);
                var found = bvh.Intersect(o.X, o.Y, o.Z, d.X, d.Y, d.Z, 0, double.PositiveInfinity, out var hit);
                Assert.That(found, Is.EqualTo(expected), "ray " + r);
                if (!found) { misses++; continue; }
                hits++;
                Assert.That(hit.Triangle, Is.EqualTo(which), "ray " + r);
                Assert.That(hit.T, Is.EqualTo(bestT).Within(1e-9 * Math.Max(1, bestT)), "ray " + r);
                // The barycentrics name the same point as o + t·d.
                int a = 3 * tris[3 * which], b = 3 * tris[3 * which + 1], c = 3 * tris[3 * which + 2];
                for (var axis = 0; axis < 3; axis++)
                {
                    var p = (1 - hit.U - hit.V) * v[a + axis] + hit.U * v[b + axis] + hit.V * v[c + axis];
                    var onRay = (axis == 0 ? o.X : axis == 1 ? o.Y : o.Z) + hit.T * (axis == 0 ? d.X : axis == 1 ? d.Y : d.Z);
                    Assert.That(p, Is.EqualTo(onRay).Within(1e-9), "ray " + r);
                }
            }
            // Both outcomes must be exercised for the comparison to mean anything.
            Assert.That(hits, Is.GreaterThan(300));
            Assert.That(misses, Is.GreaterThan(300));
        }

        [Test]
        public void RaysThroughSharedEdgesAndVerticesOfAGridAlwaysHit()
        {
            var vertices = new List<double>();
            var triangles = new List<int>();
            FlowTestScenes.Grid(4, 0, vertices, triangles);
            var bvh = TriangleBvh.Build(vertices.ToArray(), triangles.ToArray());
            // Straight down through every vertex, edge midpoint and cell diagonal of the grid (step 0.25): never between triangles.
            for (var i = -4; i <= 4; i++)
                for (var j = -4; j <= 4; j++)
                {
                    double x = i * 0.25, y = j * 0.25;
                    Assert.That(bvh.Intersect(x, y, 2, 0, 0, -1, 0, double.PositiveInfinity, out var hit), Is.True, x + ", " + y);
                    Assert.That(hit.T, Is.EqualTo(2).Within(1e-12));
                }
            // Just outside the grid: no hit; from below looking up at the back face: a hit (no culling).
            Assert.That(bvh.Intersect(1.0001, 0, 2, 0, 0, -1, 0, double.PositiveInfinity, out _), Is.False);
            Assert.That(bvh.Intersect(0.3, 0.2, -1, 0, 0, 1, 0, double.PositiveInfinity, out var below), Is.True);
            Assert.That(below.T, Is.EqualTo(1).Within(1e-12));
        }

        [Test]
        public void TheRangeExcludesHitsOutsideIt()
        {
            var vertices = new List<double>();
            var triangles = new List<int>();
            FlowTestScenes.Grid(2, 0, vertices, triangles);
            FlowTestScenes.Grid(2, 1, vertices, triangles);
            var bvh = TriangleBvh.Build(vertices.ToArray(), triangles.ToArray());
            Assert.That(bvh.Intersect(0.1, 0.1, 2, 0, 0, -1, 0, double.PositiveInfinity, out var first), Is.True);
            Assert.That(first.T, Is.EqualTo(1).Within(1e-12));
            Assert.That(bvh.Intersect(0.1, 0.1, 2, 0, 0, -1, 1.5, double.PositiveInfinity, out var second), Is.True);
            Assert.That(second.T, Is.EqualTo(2).Within(1e-12));
            Assert.That(bvh.Intersect(0.1, 0.1, 2, 0, 0, -1, 0, 0.999, out _), Is.False);
        }

        [Test]
        public void ATriangleNamingAMissingVertexIsRefused()
        {
            var e = Assert.Throws<ArgumentException>(() => TriangleBvh.Build(new double[9], new[] { 0, 1, 3 }));
            Assert.That(e.Message, Does.Contain("Triangle 0 names vertex 3 of 3"));
        }
    }
}
