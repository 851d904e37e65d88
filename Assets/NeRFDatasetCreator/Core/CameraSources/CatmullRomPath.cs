using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A smooth curve through ordered waypoints (Unity world), measured by arc length: a centripetal Catmull-Rom spline
    /// (α = ½, Barry–Goldman's pyramid), which passes through every waypoint and, unlike the uniform kind, makes no cusp
    /// or loop where waypoints are unevenly spaced. The ends get mirrored phantom points (P₋₁ = 2P₀ − P₁), so the curve
    /// starts and ends at the first and last waypoints heading along their chords. Arc length comes from
    /// <see cref="StepsPerSegment"/> chords per segment; <see cref="At"/> inverts it by linear interpolation.
    /// </summary>
    public sealed class CatmullRomPath
    {
        /// <summary>Chords per segment for the arc-length table: the length of a smooth segment is then good to ~1e-5.</summary>
        public const int StepsPerSegment = 256;

        readonly Vector3d[] points; // with the two phantom ends
        readonly double[] lengths;  // cumulative arc length at each table entry
        readonly Vector3d[] table;

        public CatmullRomPath(IReadOnlyList<Vector3d> waypoints)
        {
            if (waypoints == null) throw new ArgumentNullException(nameof(waypoints));
            var kept = new List<Vector3d>();
            foreach (var w in waypoints)
            {
                if (!w.IsFinite) throw new ArgumentException("A waypoint is not a finite position: " + w, nameof(waypoints));
                if (kept.Count == 0 || (w - kept[kept.Count - 1]).Length > 1e-12) kept.Add(w); // repeated points add nothing
            }
            if (kept.Count < 2) throw new ArgumentException("A path needs two waypoints at different places.", nameof(waypoints));
            Waypoints = kept;
            points = new Vector3d[kept.Count + 2];
            points[0] = 2 * kept[0] - kept[1];
            for (var i = 0; i < kept.Count; i++) points[i + 1] = kept[i];
            points[kept.Count + 1] = 2 * kept[kept.Count - 1] - kept[kept.Count - 2];

            var segments = kept.Count - 1;
            table = new Vector3d[segments * StepsPerSegment + 1];
            lengths = new double[table.Length];
            table[0] = kept[0];
            for (var s = 0; s < segments; s++)
                for (var k = 1; k <= StepsPerSegment; k++)
                {
                    var i = s * StepsPerSegment + k;
                    table[i] = Segment(s, (double)k / StepsPerSegment);
                    lengths[i] = lengths[i - 1] + (table[i] - table[i - 1]).Length;
                }
        }

        /// <summary>The waypoints the curve passes through, repeated neighbours merged.</summary>
        public IReadOnlyList<Vector3d> Waypoints { get; }

        public double Length => lengths[lengths.Length - 1];

        /// <summary>The point at arc length <paramref name="distance"/> from the start (clamped to [0, <see cref="Length"/>]).</summary>
        public Vector3d At(double distance)
        {
            var d = Math.Max(0, Math.Min(Length, distance));
            int lo = 0, hi = lengths.Length - 1;
            while (hi - lo > 1)
            {
                var mid = (lo + hi) / 2;
                if (lengths[mid] <= d) lo = mid;
                else hi = mid;
            }
            var span = lengths[hi] - lengths[lo];
            var t = span > 0 ? (d - lengths[lo]) / span : 0;
            return table[lo] + t * (table[hi] - table[lo]);
        }

        /// <summary>The unit direction of travel at arc length <paramref name="distance"/> (a central difference over one table step).</summary>
        public Vector3d TangentAt(double distance)
        {
            var h = Length / (table.Length - 1);
            var a = At(Math.Max(0, distance - h));
            var b = At(Math.Min(Length, distance + h));
            return (b - a).Normalized();
        }

        /// <summary>Segment <paramref name="s"/> (from waypoint s to s + 1) at parameter u in [0, 1].</summary>
        Vector3d Segment(int s, double u)
        {
            Vector3d p0 = points[s], p1 = points[s + 1], p2 = points[s + 2], p3 = points[s + 3];
            // Centripetal knots: t_{i+1} = t_i + |P_{i+1} − P_i|^½.
            var t0 = 0.0;
            var t1 = t0 + Math.Sqrt((p1 - p0).Length);
            var t2 = t1 + Math.Sqrt((p2 - p1).Length);
            var t3 = t2 + Math.Sqrt((p3 - p2).Length);
            var t = t1 + u * (t2 - t1);
            var a1 = Lerp(p0, p1, t0, t1, t);
            var a2 = Lerp(p1, p2, t1, t2, t);
            var a3 = Lerp(p2, p3, t2, t3, t);
            var b1 = Lerp(a1, a2, t0, t2, t);
            var b2 = Lerp(a2, a3, t1, t3, t);
            return Lerp(b1, b2, t1, t2, t);
        }

        static Vector3d Lerp(Vector3d a, Vector3d b, double ta, double tb, double t) =>
            tb - ta > 0 ? ((tb - t) / (tb - ta)) * a + ((t - ta) / (tb - ta)) * b : a;
    }

    /// <summary>
    /// Cameras along a <see cref="CatmullRomPath"/>: <c>count</c> positions evenly spaced by arc length, both ends
    /// included (one camera: the start), each looking forward along the path, tilted by up to
    /// <c>jitterDegrees</c> uniformly over that cone (as <see cref="VolumeSampling"/>'s forward look), world +Y up.
    /// Two random numbers per camera from one seeded stream, so the same inputs give the same cameras.
    /// </summary>
    public static class PathSampling
    {
        public static IReadOnlyList<UnityPose> Sample(CatmullRomPath path, int count, double jitterDegrees, long seed)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            if (count < 0) throw new ArgumentOutOfRangeException(nameof(count));
            var random = new SeededRandom(seed);
            var poses = new List<UnityPose>(count);
            for (var i = 0; i < count; i++)
            {
                var distance = count == 1 ? 0 : path.Length * i / (count - 1);
                double u = random.NextDouble(), v = random.NextDouble();
                var along = VolumeSampling.Rotation(path.TangentAt(distance));
                var look = VolumeSampling.Direction(VolumeLook.Forward, along, jitterDegrees, u, v);
                poses.Add(new UnityPose(path.At(distance), VolumeSampling.Rotation(look)));
            }
            return poses;
        }
    }
}
