using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class PathSamplingTests
    {
        // Uneven waypoints on the x axis: gaps 1, 2, 3.
        static readonly Vector3d[] Line = { Vector3d.Zero, new Vector3d(1, 0, 0), new Vector3d(3, 0, 0), new Vector3d(6, 0, 0) };

        static Vector3d[] Circle(int n, double radius, double y = 1) =>
            Enumerable.Range(0, n).Select(i => new Vector3d(radius * Math.Cos(2 * Math.PI * i / n), y, radius * Math.Sin(2 * Math.PI * i / n))).ToArray();

        static double Degrees(Vector3d a, Vector3d b) => Vector3d.AngleBetween(a, b) * 180 / Math.PI;

        [Test]
        public void CollinearWaypointsGiveTheSegmentMeasuredByArcLength()
        {
            var path = new CatmullRomPath(Line);
            Assert.That(path.Length, Is.EqualTo(6).Within(1e-9), "no overshoot between unevenly spaced points");
            foreach (var d in new[] { 0, 0.5, 1, 2.25, 4, 6 })
                Assert.That((path.At(d) - new Vector3d(d, 0, 0)).Length, Is.LessThan(1e-9), "at " + d);
        }

        [Test]
        public void ThePathGoesThroughEveryWaypointAndHugsACircleThroughThem()
        {
            // Eight waypoints on a circle of radius 5: the open path covers 7/8 of it, 2π·5·7/8 = 27.489.
            var waypoints = Circle(8, 5);
            var path = new CatmullRomPath(waypoints);
            Assert.That(path.Length, Is.EqualTo(2 * Math.PI * 5 * 7 / 8).Within(0.01 * 27.489));
            var samples = Enumerable.Range(0, 2001).Select(k => path.At(path.Length * k / 2000)).ToList();
            foreach (var w in waypoints)
                Assert.That(samples.Min(p => (p - w).Length), Is.LessThan(path.Length / 2000 + 1e-9), "passes " + w);
            Assert.That(samples.Select(p => p.Y), Has.All.EqualTo(1).Within(1e-12), "stays in the waypoints' plane");
            // Between the second and the second-to-last waypoints (the ends head along their chords, see below).
            foreach (var p in samples.Skip(2000 / 7).Take(2000 * 5 / 7))
                Assert.That(Math.Sqrt(p.X * p.X + p.Z * p.Z), Is.EqualTo(5).Within(0.05), "within 1 % of the circle at " + p);
        }

        [Test]
        public void TheEndsHeadAlongTheirChords()
        {
            // Mirrored phantom ends: the start leaves along P0→P1 and the end arrives along P(n−2)→P(n−1).
            var waypoints = Circle(6, 3);
            var path = new CatmullRomPath(waypoints);
            Assert.That(Degrees(path.TangentAt(0), waypoints[1] - waypoints[0]), Is.LessThan(0.5));
            Assert.That(Degrees(path.TangentAt(path.Length), waypoints[5] - waypoints[4]), Is.LessThan(0.5));
        }

        [Test]
        public void CamerasAreEvenlySpacedByArcLengthAndLookAlongThePath()
        {
            var poses = PathSampling.Sample(new CatmullRomPath(Line), 7, 0, 1);
            Assert.That(poses.Select(p => p.Position.X), Is.EqualTo(new double[] { 0, 1, 2, 3, 4, 5, 6 }).Within(1e-9), "ends included, whatever the waypoint gaps");
            foreach (var p in poses)
            {
                Assert.That(Degrees(p.Rotation.Forward, Vector3d.UnitX), Is.LessThan(1e-6));
                Assert.That(Degrees(p.Rotation.Up, Vector3d.UnitY), Is.LessThan(1e-6), "no roll: world up");
            }
            Assert.That(PathSampling.Sample(new CatmullRomPath(Line), 1, 0, 1).Single().Position, Is.EqualTo(Vector3d.Zero), "one camera: the start");
        }

        [Test]
        public void OnACircleTheCamerasLookAlongTheTangent()
        {
            // 12 waypoints, 33 cameras: 3 per segment; the first and last segments (chord-headed ends) are left out.
            foreach (var pose in PathSampling.Sample(new CatmullRomPath(Circle(12, 4, 0)), 34, 0, 2).Skip(3).Take(28))
            {
                var radial = new Vector3d(pose.Position.X, 0, pose.Position.Z).Normalized();
                var tangent = Vector3d.Cross(Vector3d.UnitY, radial); // either direction of travel: |dot| below
                Assert.That(Math.Abs(Vector3d.Dot(pose.Rotation.Forward, radial)), Is.LessThan(Math.Sin(1.5 * Math.PI / 180)), "perpendicular to the radius at " + pose.Position);
                Assert.That(Math.Abs(Vector3d.Dot(pose.Rotation.Forward, tangent)), Is.GreaterThan(Math.Cos(1.5 * Math.PI / 180)));
            }
        }

        [Test]
        public void JitterTiltsWithinItsConeAndIsSeeded()
        {
            var path = new CatmullRomPath(Line);
            var poses = PathSampling.Sample(path, 200, 10, 5);
            var tilts = poses.Select(p => Degrees(p.Rotation.Forward, Vector3d.UnitX)).ToList();
            Assert.That(tilts, Has.All.LessThanOrEqualTo(10 + 1e-9));
            Assert.That(tilts.Max(), Is.GreaterThan(9), "the cone is used to its edge");
            // Uniform over the cap: cos of the tilt uniform in [cos 10°, 1], so half the cameras tilt less than acos((1 + cos 10°)/2) = 7.07°.
            Assert.That(tilts.Count(t => t < 7.07), Is.EqualTo(100).Within(5 * Math.Sqrt(50)));
            Assert.That(PathSampling.Sample(path, 200, 10, 5).Select(p => p.Rotation), Is.EqualTo(poses.Select(p => p.Rotation)));
            Assert.That(PathSampling.Sample(path, 200, 10, 6).Select(p => p.Rotation), Is.Not.EqualTo(poses.Select(p => p.Rotation)));
        }

        [Test]
        public void APathNeedsTwoDistinctWaypoints()
        {
            Assert.Throws<ArgumentException>(() => new CatmullRomPath(new[] { Vector3d.UnitX }));
            Assert.Throws<ArgumentException>(() => new CatmullRomPath(new[] { Vector3d.UnitX, Vector3d.UnitX }));
            Assert.Throws<ArgumentException>(() => new CatmullRomPath(new[] { Vector3d.Zero, new Vector3d(double.NaN, 0, 0) }));
            Assert.That(new CatmullRomPath(new[] { Vector3d.Zero, Vector3d.Zero, new Vector3d(0, 0, 2) }).Length, Is.EqualTo(2).Within(1e-9), "repeats merged");
        }
    }
}
