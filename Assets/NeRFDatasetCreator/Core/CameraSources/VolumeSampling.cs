using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>Where the cameras of an inside-out volume look.</summary>
    public enum VolumeLook
    {
        /// <summary>Level with the horizon (world +Y up), at a random heading: a panorama's ring.</summary>
        Ring,

        /// <summary>Any direction, uniform over the sphere (world +Y up for the roll).</summary>
        Sphere,

        /// <summary>Along the box's +Z, tilted by up to the jitter angle, uniform over that cone.</summary>
        Forward,

        /// <summary>
        /// Not in the box: along a spline through the children of a waypoint object (<see cref="PathSampling"/>), evenly
        /// by arc length, looking forward along it with the jitter.
        /// </summary>
        Path,
    }

    /// <summary>The cameras <see cref="VolumeSampling.Sample"/> kept and how many positions it threw away.</summary>
    public sealed class VolumeSample
    {
        public VolumeSample(IReadOnlyList<UnityPose> poses, int drawn, int rejected, IReadOnlyDictionary<string, int> rejectedBy)
        {
            Poses = poses;
            Drawn = drawn;
            Rejected = rejected;
            RejectedBy = rejectedBy;
        }

        public IReadOnlyList<UnityPose> Poses { get; }

        /// <summary>Positions drawn in the box, kept or not.</summary>
        public int Drawn { get; }

        /// <summary>Positions inside (or within the clearance of) an obstacle.</summary>
        public int Rejected { get; }

        /// <summary>Rejections per obstacle name (the first obstacle that contained the position).</summary>
        public IReadOnlyDictionary<string, int> RejectedBy { get; }
    }

    /// <summary>
    /// Inside-out camera positions: uniform in a box, never inside an obstacle box grown by a clearance, each looking
    /// outwards (<see cref="VolumeLook"/>). One <see cref="SeededRandom"/> stream gives positions and directions in a
    /// fixed order, so the same inputs give the same cameras on every machine. Positions are drawn until
    /// <c>count</c> are kept or <see cref="MaxDrawsPerView"/> × count were drawn.
    /// </summary>
    public static class VolumeSampling
    {
        /// <summary>How many positions may be drawn per wanted camera before giving up (the box is then ≥ 98% obstacles).</summary>
        public const int MaxDrawsPerView = 50;

        public static VolumeSample Sample(OrientedBox box, IReadOnlyList<OrientedBox> obstacles, double clearance, int count,
            VolumeLook look, double jitterDegrees, long seed)
        {
            if (box == null) throw new ArgumentNullException(nameof(box));
            if (count < 0) throw new ArgumentOutOfRangeException(nameof(count));
            var random = new SeededRandom(seed);
            var poses = new List<UnityPose>(count);
            var rejectedBy = new Dictionary<string, int>();
            int drawn = 0, rejected = 0;
            var maxDraws = (long)count * MaxDrawsPerView;
            while (poses.Count < count && drawn < maxDraws)
            {
                // Every draw takes the same number of random numbers (3 for the position, 2 for the direction), so a
                // rejection shifts no later camera onto another stream position than an accepted one would.
                var position = box.PointAt(new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5));
                double u = random.NextDouble(), v = random.NextDouble();
                drawn++;
                var hit = FirstContaining(obstacles, position, clearance);
                if (hit != null)
                {
                    rejected++;
                    rejectedBy.TryGetValue(hit.Name, out var n);
                    rejectedBy[hit.Name] = n + 1;
                    continue;
                }
                poses.Add(new UnityPose(position, Rotation(Direction(look, box.Rotation, jitterDegrees, u, v))));
            }
            return new VolumeSample(poses, drawn, rejected, rejectedBy);
        }

        static OrientedBox FirstContaining(IReadOnlyList<OrientedBox> obstacles, Vector3d position, double clearance)
        {
            if (obstacles == null) return null;
            foreach (var o in obstacles)
                if (o.Contains(position, clearance)) return o;
            return null;
        }

        /// <summary>The Unity-world viewing direction for two uniform numbers in [0, 1).</summary>
        public static Vector3d Direction(VolumeLook look, Quaterniond boxRotation, double jitterDegrees, double u, double v)
        {
            var heading = 2 * Math.PI * u;
            switch (look)
            {
                case VolumeLook.Ring:
                    return new Vector3d(Math.Sin(heading), 0, Math.Cos(heading));
                case VolumeLook.Sphere:
                {
                    // Archimedes: the height is uniform in [−1, 1] for directions uniform over the sphere.
                    var y = 1 - 2 * v;
                    var r = Math.Sqrt(Math.Max(0, 1 - y * y));
                    return new Vector3d(r * Math.Sin(heading), y, r * Math.Cos(heading));
                }
                default:
                {
                    // Uniform over the spherical cap of half-angle θ around the box's +Z: cos of the tilt uniform in [cos θ, 1].
                    var cosMax = Math.Cos(Math.Min(180, Math.Max(0, jitterDegrees)) * Math.PI / 180);
                    var cosTilt = 1 - v * (1 - cosMax);
                    var sinTilt = Math.Sqrt(Math.Max(0, 1 - cosTilt * cosTilt));
                    var local = new Vector3d(sinTilt * Math.Cos(heading), sinTilt * Math.Sin(heading), cosTilt);
                    return boxRotation.Rotate(local);
                }
            }
        }

        /// <summary>
        /// A camera rotation looking along <paramref name="forward"/> with world +Y up, as Unity's
        /// <c>Quaternion.LookRotation(forward, Vector3.up)</c>; straight up or down (where that is undefined) the
        /// camera's up is world +Z.
        /// </summary>
        public static Quaterniond Rotation(Vector3d forward)
        {
            var f = forward.Normalized();
            var up = Math.Abs(f.Y) > 1 - 1e-12 ? Vector3d.UnitZ : Vector3d.UnitY;
            return Quaterniond.LookRotation(f, up);
        }
    }
}
