using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class FormationTests
    {
        static readonly Vector3d Target = new Vector3d(1.5, -0.25, 3);

        static IEnumerable<TestCaseData> AllFormations()
        {
            yield return new TestCaseData(new HaloFormation(20, 10)).SetName("halo");
            yield return new TestCaseData(new SphereFormation()).SetName("sphere");
            yield return new TestCaseData(new SemiSphereFormation()).SetName("semisphere");
            yield return new TestCaseData(new SemiSphereFormation(80, -30, 0.25)).SetName("semisphere columns");
            yield return new TestCaseData(new RandomFormation(42, true)).SetName("random upper");
            yield return new TestCaseData(new RandomFormation(42, false)).SetName("random sphere");
            yield return new TestCaseData(new OrbitFormation()).SetName("orbit");
        }

        [TestCaseSource(nameof(AllFormations))]
        public void CamerasAreAtTheExactDistanceLookingAtTheTarget(ICameraFormation formation)
        {
            foreach (var count in new[] { 1, 2, 7, 100, 1000 })
            {
                var poses = CameraRig.Place(formation, count, Target, 4.25);
                Assert.That(poses, Has.Count.EqualTo(count));
                foreach (var pose in poses)
                {
                    Assert.That(Vector3d.Distance(pose.Position, Target), Is.EqualTo(4.25).Within(1e-12));
                    var toTarget = (Target - pose.Position).Normalized();
                    Assert.That(Vector3d.Distance(pose.Rotation.Forward, toTarget), Is.LessThan(1e-12));
                    Assert.That(pose.Rotation.Norm, Is.EqualTo(1).Within(1e-12));
                }
            }
        }

        [TestCaseSource(nameof(AllFormations))]
        public void NoTwoCamerasStandOnTheSameSpot(ICameraFormation formation)
        {
            foreach (var count in new[] { 2, 3, 64, 200, 400 })
            {
                var directions = formation.Directions(count).Select(d => d.ToUnityVector()).ToList();
                Assert.That(SmallestAngularGap(directions), Is.GreaterThan(1e-6), $"{count} views");
            }
        }

        [TestCaseSource(nameof(AllFormations))]
        public void ZeroViewsIsAnEmptySplit(ICameraFormation formation)
        {
            Assert.That(formation.Directions(0), Is.Empty);
        }

        [TestCase(10)]
        [TestCase(100)]
        [TestCase(500)]
        public void TheSphereCoversEvenly(int count)
        {
            // Golden-ratio sampling keeps every pair at least ~0.87·√(4π/N) apart; random sampling shrinks like 1/N.
            var directions = new SphereFormation().Directions(count).Select(d => d.ToUnityVector()).ToList();
            Assert.That(SmallestAngularGap(directions), Is.GreaterThan(0.8 * Math.Sqrt(4 * Math.PI / count)));
            Assert.That(directions.Count(d => d.Y > 0), Is.EqualTo(count / 2).Within(1), "as many above as below");
        }

        [TestCase(10)]
        [TestCase(100)]
        [TestCase(500)]
        public void TheUpperHemisphereCoversEvenly(int count)
        {
            var directions = new SemiSphereFormation().Directions(count).Select(d => d.ToUnityVector()).ToList();
            Assert.That(SmallestAngularGap(directions), Is.GreaterThan(0.8 * Math.Sqrt(2 * Math.PI / count)));
        }

        [Test]
        public void RandomSamplingIsNotEvenEnoughForTheCoverageBound()
        {
            // Shows the coverage bound above can fail: seeded random directions break it.
            var directions = new RandomFormation(1, false).Directions(500).Select(d => d.ToUnityVector()).ToList();
            Assert.That(SmallestAngularGap(directions), Is.LessThan(0.8 * Math.Sqrt(4 * Math.PI / 500)));
        }

        [Test]
        public void UpperFormationsStayAboveTheTarget()
        {
            foreach (var formation in new ICameraFormation[] { new SemiSphereFormation(), new RandomFormation(5, true), new OrbitFormation(2, 0, 60) })
                foreach (var pose in CameraRig.Place(formation, 300, Target, 2))
                    Assert.That(pose.Position.Y, Is.GreaterThanOrEqualTo(Target.Y), formation.Kind);
        }

        [Test]
        public void TheSphereReachesBothHemispheresButNeverAPole()
        {
            var elevations = new SphereFormation().Directions(101).Select(d => d.ElevationRadians * 180 / Math.PI).ToList();
            Assert.That(elevations.Max(), Is.LessThan(90).And.GreaterThan(80));
            Assert.That(elevations.Min(), Is.GreaterThan(-90).And.LessThan(-80));
            Assert.That(elevations[50], Is.EqualTo(0).Within(1e-12), "the middle sample of an odd count is on the equator");
        }

        [Test]
        public void HaloCamerasAreEvenlySpacedOnOneRing()
        {
            var directions = new HaloFormation(30, 45).Directions(8);
            for (var i = 0; i < 8; i++)
            {
                Assert.That(directions[i].ElevationRadians, Is.EqualTo(Math.PI / 6).Within(1e-15));
                Assert.That(directions[i].AzimuthRadians, Is.EqualTo((45 + 45 * i) % 360 * Math.PI / 180).Within(1e-12));
            }
        }

        [Test]
        public void TheSemiSphereBandHasTheRequestedEdges()
        {
            var elevations = new SemiSphereFormation(60, 10).Directions(1000).Select(d => d.ElevationRadians * 180 / Math.PI).ToList();
            Assert.That(elevations.Max(), Is.LessThan(60).And.GreaterThan(59.5));
            Assert.That(elevations.Min(), Is.GreaterThan(10).And.LessThan(10.5));
        }

        [Test]
        public void AFractionalSpiralRatioStacksCamerasInColumns()
        {
            // Ratio 1/4: azimuths 0°, 90°, 180°, 270° only — "column stacked" in the original plugin's paper.
            var azimuths = new SemiSphereFormation(90, 0, 0.25).Directions(40)
                .Select(d => Math.Round(d.AzimuthRadians * 180 / Math.PI, 9) % 360).Distinct().OrderBy(a => a).ToList();
            Assert.That(azimuths, Is.EqualTo(new[] { 0.0, 90, 180, 270 }));
        }

        [Test]
        public void LegacyParametersBecomeElevations()
        {
            // The original's defaults (top 1, span 1) ran from the zenith down to the horizon.
            var legacy = SemiSphereFormation.FromLegacy(1, 1, 0);
            Assert.That(legacy.TopElevationDegrees, Is.EqualTo(90).Within(1e-12));
            Assert.That(legacy.BottomElevationDegrees, Is.EqualTo(0).Within(1e-12));
            var topless = SemiSphereFormation.FromLegacy(0.7, 0.7, 0);
            Assert.That(topless.TopElevationDegrees, Is.EqualTo(Math.Asin(0.7) * 180 / Math.PI).Within(1e-12));
            Assert.That(() => SemiSphereFormation.FromLegacy(0.5, 2, 0), Throws.TypeOf<InvalidParameterException>().With.Message.Contains("span"));
        }

        [Test]
        public void OrbitSwingsBetweenItsElevationsOverItsTurns()
        {
            var directions = new OrbitFormation(2, 10, 50).Directions(200);
            var elevations = directions.Select(d => d.ElevationRadians * 180 / Math.PI).ToList();
            Assert.That(elevations.Max(), Is.LessThanOrEqualTo(50).And.GreaterThan(49.9));
            Assert.That(elevations.Min(), Is.GreaterThanOrEqualTo(10).And.LessThan(10.1));
            // Two turns: the azimuth of view 100 is back where view 0 started.
            Assert.That(directions[100].AzimuthRadians, Is.EqualTo(directions[0].AzimuthRadians).Within(1e-9));
        }

        [Test]
        public void RandomFormationsAreDeterministicForASeed()
        {
            var a = new RandomFormation(99).Directions(50);
            var b = new RandomFormation(99).Directions(50);
            var c = new RandomFormation(100).Directions(50);
            Assert.That(a.Select(d => d.AzimuthRadians), Is.EqualTo(b.Select(d => d.AzimuthRadians)));
            Assert.That(a.Select(d => d.ElevationRadians), Is.EqualTo(b.Select(d => d.ElevationRadians)));
            Assert.That(a.Select(d => d.AzimuthRadians), Is.Not.EqualTo(c.Select(d => d.AzimuthRadians)));
        }

        [Test]
        public void SeededRandomFollowsSplitMix64()
        {
            // Reference values of SplitMix64 for seed 1234567 (Vigna's splitmix64.c; also java.util.SplittableRandom).
            var random = new SeededRandom(1234567);
            Assert.That(random.NextUInt64(), Is.EqualTo(6457827717110365317UL));
            Assert.That(random.NextUInt64(), Is.EqualTo(3203168211198807973UL));
            Assert.That(random.NextUInt64(), Is.EqualTo(9817491932198370423UL));
        }

        [Test]
        public void EveryValueIsFiniteOverTheWholeParameterRange()
        {
            for (var top = -90.0; top <= 90; top += 7.5)
                for (var bottom = -90.0; bottom <= top; bottom += 7.5)
                    foreach (var ratio in new[] { 0, 1e-9, 0.5, 1, 1.000001, 3.7, 1000 })
                    {
                        var formation = new SemiSphereFormation(top, bottom, ratio);
                        if (formation.Validate("").Count > 0) continue; // the collapsed pole band, refused by validation
                        AssertFinite(CameraRig.Place(formation, 37, Target, 1e-3));
                    }
            for (var elevation = -89.999; elevation < 90; elevation += 4.5)
                AssertFinite(CameraRig.Place(new HaloFormation(elevation, -360), 13, Target, 1e3));
            foreach (var turns in new[] { 1e-6, 0.5, 1, 2, 100 })
                AssertFinite(CameraRig.Place(new OrbitFormation(turns, -89.9, 89.9, 360), 50, Target, 5));
        }

        static IEnumerable<TestCaseData> InvalidFormations()
        {
            yield return new TestCaseData(new HaloFormation(90), "halo.elevationDegrees").SetName("halo on the pole");
            yield return new TestCaseData(new HaloFormation(double.NaN), "halo.elevationDegrees").SetName("halo NaN");
            yield return new TestCaseData(new HaloFormation(0, 400), "halo.startAzimuthDegrees").SetName("halo azimuth");
            yield return new TestCaseData(new SemiSphereFormation(100), "semisphere.topElevationDegrees").SetName("semisphere top");
            yield return new TestCaseData(new SemiSphereFormation(30, 40), "semisphere.bottomElevationDegrees").SetName("semisphere inverted band");
            yield return new TestCaseData(new SemiSphereFormation(90, 90), "semisphere.bottomElevationDegrees").SetName("semisphere collapsed on the pole");
            yield return new TestCaseData(new SemiSphereFormation(90, 0, -1), "semisphere.spiralRatio").SetName("semisphere ratio");
            yield return new TestCaseData(new SemiSphereFormation(90, 0, double.PositiveInfinity), "semisphere.spiralRatio").SetName("semisphere ratio infinite");
            yield return new TestCaseData(new OrbitFormation(0), "orbit.turns").SetName("orbit no turn");
            yield return new TestCaseData(new OrbitFormation(1, 50, 10), "orbit.lowElevationDegrees").SetName("orbit inverted");
        }

        [TestCaseSource(nameof(InvalidFormations))]
        public void OutOfRangeParametersRaiseAnErrorNamingTheParameter(ICameraFormation formation, string field)
        {
            var error = Assert.Throws<InvalidParameterException>(() => formation.Directions(10));
            Assert.That(error.Problems.Select(p => p.Field), Does.Contain(field));
            Assert.That(error.Message, Does.Contain(field));
        }

        [TestCase(-1)]
        [TestCase(100001)]
        public void AnOutOfRangeCountIsAnError(int count)
        {
            var error = Assert.Throws<InvalidParameterException>(() => new SphereFormation().Directions(count));
            Assert.That(error.Message, Does.Contain("count").And.Contain("100000"));
        }

        [Test]
        public void ANonPositiveDistanceIsAnError()
        {
            var error = Assert.Throws<InvalidParameterException>(() => CameraRig.Place(new SphereFormation(), 3, Target, 0));
            Assert.That(error.Problems[0].Field, Is.EqualTo("distance"));
        }

        static double SmallestAngularGap(IReadOnlyList<Vector3d> directions)
        {
            var smallest = double.MaxValue;
            for (var i = 0; i < directions.Count; i++)
                for (var j = i + 1; j < directions.Count; j++)
                    smallest = Math.Min(smallest, Vector3d.AngleBetween(directions[i], directions[j]));
            return smallest;
        }

        static void AssertFinite(IReadOnlyList<UnityPose> poses)
        {
            foreach (var pose in poses)
            {
                Assert.That(pose.Position.IsFinite, Is.True);
                Assert.That(BlenderConvention.CameraToWorld(pose).IsFinite, Is.True);
            }
        }
    }
}
