using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class VolumeSamplingTests
    {
        // A 10 × 2 × 10 room around the origin, and a wall across it: x in [−0.5, 0.5], the whole height and depth.
        static readonly OrientedBox Room = OrientedBox.AxisAligned("Room", Vector3d.Zero, new Vector3d(10, 2, 10));
        static readonly OrientedBox Wall = OrientedBox.AxisAligned("Wall", Vector3d.Zero, new Vector3d(1, 4, 12));

        // A quarter turn about +Y: the box's +Z becomes Unity +X (Unity's left-handed rotation of +Z about +Y).
        static readonly Quaterniond QuarterTurn = Quaterniond.AngleAxis(90, Vector3d.UnitY);

        [Test]
        public void NoCameraIsInsideTheWallOrItsClearance()
        {
            var sample = VolumeSampling.Sample(Room, new[] { Wall }, 0.25, 400, VolumeLook.Ring, 0, 7);
            Assert.That(sample.Poses, Has.Count.EqualTo(400));
            Assert.That(sample.Poses.Select(p => Math.Abs(p.Position.X)), Has.All.GreaterThan(0.75), "wall half-width 0.5 plus clearance 0.25");
            Assert.That(sample.Poses.Select(p => p.Position), Has.All.Matches<Vector3d>(p => Math.Abs(p.X) <= 5 && Math.Abs(p.Y) <= 1 && Math.Abs(p.Z) <= 5), "inside the room");
            // Every draw either kept or rejected; the wall with its clearance is 1.5 of the room's 10 units of x:
            // 15% of uniform draws, so with ~470 draws the count of rejections is 70 ± 3σ (σ = √(470·0.15·0.85) ≈ 7.7).
            Assert.That(sample.Drawn, Is.EqualTo(400 + sample.Rejected));
            Assert.That(sample.Rejected, Is.InRange(47, 95));
            Assert.That(sample.RejectedBy.Keys, Is.EqualTo(new[] { "Wall" }));
            Assert.That(sample.RejectedBy["Wall"], Is.EqualTo(sample.Rejected));
        }

        [Test]
        public void WithoutObstaclesNothingIsRejectedAndEachDrawIsKept()
        {
            var sample = VolumeSampling.Sample(Room, Array.Empty<OrientedBox>(), 0.25, 50, VolumeLook.Sphere, 0, 1);
            Assert.That(sample.Poses, Has.Count.EqualTo(50));
            Assert.That(sample.Drawn, Is.EqualTo(50));
            Assert.That(sample.Rejected, Is.EqualTo(0));
        }

        [Test]
        public void AnOrientedObstacleRejectsByItsOwnAxes()
        {
            // A 2 × 2 × 2 box turned 45° about +Y: the point (1.2, 0, 0) is outside its axis-aligned size (half-width 1)
            // along x but inside the turned box (its extent along world x is √2 ≈ 1.414); (1.2, 0, 1.2) is outside it.
            var turned = new OrientedBox("Turned", Vector3d.Zero, Quaterniond.AngleAxis(45, Vector3d.UnitY), new Vector3d(2, 2, 2));
            Assert.That(turned.Contains(new Vector3d(1.2, 0, 0)), Is.True);
            Assert.That(turned.Contains(new Vector3d(1.2, 0, 1.2)), Is.False);
            Assert.That(turned.Contains(new Vector3d(0.8, 0, 0.8)), Is.False, "|x'| = 0.8·√2 ≈ 1.131 > 1 along its own x or z");
            Assert.That(turned.Contains(new Vector3d(0.8, 0, 0.8), 0.2), Is.True, "with a 0.2 clearance: 1.131 < 1.2");
        }

        [Test]
        public void SameSeedSameCamerasOtherSeedOtherCameras()
        {
            var a = VolumeSampling.Sample(Room, new[] { Wall }, 0.25, 30, VolumeLook.Sphere, 0, 42);
            var b = VolumeSampling.Sample(Room, new[] { Wall }, 0.25, 30, VolumeLook.Sphere, 0, 42);
            var c = VolumeSampling.Sample(Room, new[] { Wall }, 0.25, 30, VolumeLook.Sphere, 0, 43);
            Assert.That(b.Poses, Is.EqualTo(a.Poses));
            Assert.That(c.Poses.First().Position, Is.Not.EqualTo(a.Poses.First().Position));
        }

        [Test]
        public void ARejectionDoesNotShiftTheStreamOfLaterKeptCameras()
        {
            // Every draw takes five numbers, so the cameras kept with a wall are exactly the draws without one that lie outside it.
            var free = VolumeSampling.Sample(Room, null, 0, 200, VolumeLook.Sphere, 0, 5);
            var walled = VolumeSampling.Sample(Room, new[] { Wall }, 0, 100, VolumeLook.Sphere, 0, 5);
            var expected = free.Poses.Where(p => Math.Abs(p.Position.X) > 0.5).Take(100).ToList();
            Assert.That(walled.Poses, Is.EqualTo(expected));
        }

        [Test]
        public void TooSmallARoomKeepsFewerCamerasAndSaysHowManyWereDrawn()
        {
            var filling = OrientedBox.AxisAligned("Filling", Vector3d.Zero, new Vector3d(20, 20, 20));
            var sample = VolumeSampling.Sample(Room, new[] { filling }, 0, 10, VolumeLook.Ring, 0, 3);
            Assert.That(sample.Poses, Is.Empty);
            Assert.That(sample.Drawn, Is.EqualTo(10 * VolumeSampling.MaxDrawsPerView));
            Assert.That(sample.Rejected, Is.EqualTo(sample.Drawn));
        }

        [Test]
        public void RingCamerasLookLevelWithUnityUpAsUp()
        {
            var sample = VolumeSampling.Sample(Room, null, 0, 100, VolumeLook.Ring, 0, 9);
            foreach (var p in sample.Poses)
            {
                Assert.That(p.Rotation.Forward.Y, Is.EqualTo(0).Within(1e-12));
                Assert.That(p.Rotation.Up.Y, Is.EqualTo(1).Within(1e-12));
                Assert.That(p.Rotation.Forward.Length, Is.EqualTo(1).Within(1e-12));
            }
            // Headings cover the circle: some camera looks into each quadrant.
            var quadrants = sample.Poses.Select(p => (int)Math.Floor((Math.Atan2(p.Rotation.Forward.X, p.Rotation.Forward.Z) + Math.PI) / (Math.PI / 2))).Distinct().Count();
            Assert.That(quadrants, Is.EqualTo(4));
        }

        [Test]
        public void SphereDirectionsFollowArchimedesAndKeepAnUprightRoll()
        {
            // u = 0.25 → heading 90° (Unity +X), v = 0.25 → height 1 − 2·0.25 = 0.5.
            var d = VolumeSampling.Direction(VolumeLook.Sphere, Quaterniond.Identity, 0, 0.25, 0.25);
            Assert.That(new[] { d.X, d.Y, d.Z }, Is.EqualTo(new[] { Math.Sqrt(0.75), 0.5, 0 }).Within(1e-12));
            var sample = VolumeSampling.Sample(Room, null, 0, 2000, VolumeLook.Sphere, 0, 11);
            var meanY = sample.Poses.Average(p => p.Rotation.Forward.Y);
            Assert.That(meanY, Is.EqualTo(0).Within(0.05), "uniform heights in [−1, 1]: mean 0, σ of the mean ≈ 0.013");
            Assert.That(sample.Poses.Count(p => p.Rotation.Forward.Y > 0.5), Is.InRange(400, 600), "a quarter of the sphere lies above height 0.5");
            Assert.That(sample.Poses.Select(p => p.Rotation.Right.Y), Has.All.EqualTo(0).Within(1e-12), "no roll: the right vector stays level");
        }

        [Test]
        public void ForwardCamerasStayWithinTheJitterConeOfTheBoxesForward()
        {
            var box = new OrientedBox("Corridor", new Vector3d(0, 1, 0), QuarterTurn, new Vector3d(2, 2, 20));
            var sample = VolumeSampling.Sample(box, null, 0, 300, VolumeLook.Forward, 10, 4);
            var angles = sample.Poses.Select(p => Vector3d.AngleBetween(p.Rotation.Forward, Vector3d.UnitX) * 180 / Math.PI).ToList();
            Assert.That(angles, Has.All.LessThanOrEqualTo(10 + 1e-9), "the box's +Z is Unity +X after a quarter turn");
            Assert.That(angles.Max(), Is.GreaterThan(8), "the cone is used, not only its axis");
            // And along the box's long axis: x spans ±10, z only ±1.
            Assert.That(sample.Poses.Max(p => Math.Abs(p.Position.X)), Is.GreaterThan(8));
            Assert.That(sample.Poses.Max(p => Math.Abs(p.Position.Z)), Is.LessThanOrEqualTo(1 + 1e-12));
            // No jitter: exactly the box's forward.
            var straight = VolumeSampling.Direction(VolumeLook.Forward, QuarterTurn, 0, 0.3, 0.7);
            Assert.That(new[] { straight.X, straight.Y, straight.Z }, Is.EqualTo(new[] { 1.0, 0, 0 }).Within(1e-12));
        }

        [Test]
        public void StraightUpHasADefinedRoll()
        {
            var q = VolumeSampling.Rotation(Vector3d.UnitY);
            Assert.That(q.Forward.Y, Is.EqualTo(1).Within(1e-12));
            Assert.That(q.Up.Z, Is.EqualTo(1).Within(1e-12));
        }
    }
}
