using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class SphereSurfaceSamplerTests
    {
        // A ground plane 2 km across (two triangles) at Unity y = 0, centred on the origin.
        static SurfaceMesh Ground(double half = 1000) => new SurfaceMesh(
            new[] { new Vector3d(-half, 0, -half), new Vector3d(half, 0, -half), new Vector3d(half, 0, half), new Vector3d(-half, 0, half) },
            new[] { 0, 2, 1, 0, 3, 2 });

        static SurfaceMesh Square(Vector3d corner, double side) => new SurfaceMesh(
            new[] { corner, corner + new Vector3d(side, 0, 0), corner + new Vector3d(side, 0, side), corner + new Vector3d(0, 0, side) },
            new[] { 0, 2, 1, 0, 3, 2 });

        static double Sigma(int n, double p) => Math.Sqrt(n * p * (1 - p));

        [Test]
        public void AHugePlaneGivesExactlyTheCountInsideTheSphereUniformOverTheDisc()
        {
            const int n = 20000;
            var sample = SphereSurfaceSampler.Sample(new[] { Ground() }, n, 7, Vector3d.Zero, 10);
            Assert.That(sample.Points, Has.Count.EqualTo(n), "exactly the count asked for");
            Assert.That(sample.Points.Select(p => p.Position.Length), Has.All.LessThanOrEqualTo(10 + 1e-9));
            // The plane through the centre cuts a disc of radius 10; the disc of radius 5 holds a quarter of its area.
            var inner = sample.Points.Count(p => p.Position.Length <= 5);
            Assert.That(inner, Is.EqualTo(n / 4).Within(5 * Sigma(n, 0.25)));
            // Half-plane x > 0 holds half.
            Assert.That(sample.Points.Count(p => p.Position.X > 0), Is.EqualTo(n / 2).Within(5 * Sigma(n, 0.5)));
            // Cut to the sphere first: the pieces kept are a ring of edge ≤ 10/8 around the disc, so few draws miss.
            // The disc (π·100 ≈ 314) against the plane's 4·10⁶ would need ~12 700 draws per point without the cut.
            Assert.That(sample.Drawn, Is.LessThan(1.5 * n));
        }

        [Test]
        public void SurfacesShareThePointsByTheirAreaInsideAndFarOnesGetNone()
        {
            const int n = 8000;
            var small = Square(new Vector3d(0, 1, 0), 1);      // area 1, inside a radius-5 sphere
            var large = Square(new Vector3d(-2, -1, -2), 1.5); // area 2.25
            var far = Square(new Vector3d(50, 0, 50), 10);    // area 100, far outside
            var sample = SphereSurfaceSampler.Sample(new[] { small, large, far }, n, 3, Vector3d.Zero, 5);
            Assert.That(sample.Points, Has.Count.EqualTo(n));
            Assert.That(sample.Points.Count(p => p.Position.X > 40), Is.EqualTo(0), "the far square is outside");
            // Both near squares lie wholly inside (farthest corner √(1+4+1) ≈ 2.45 and √(4+1+4) = 3): area 1 to 2.25.
            var onSmall = sample.Points.Count(p => Math.Abs(p.Position.Y - 1) < 1e-9);
            Assert.That(onSmall, Is.EqualTo(n / 3.25).Within(5 * Sigma(n, 1 / 3.25)));
        }

        [Test]
        public void ColoursAndNormalsAreThoseOfThePointOnItsWholeTriangle()
        {
            // One triangle with red, green and blue corners straddling the sphere: a piece's weights must map back to
            // the triangle's, so each point's colour is its own barycentric blend of the corners.
            var a = new Vector3d(-4, 0, -4);
            var b = new Vector3d(12, 0, -4);
            var c = new Vector3d(-4, 0, 12);
            var mesh = new SurfaceMesh(new[] { a, b, c }, new[] { 0, 1, 2 },
                vertexNormals: new[] { Vector3d.UnitY, Vector3d.UnitY, Vector3d.UnitY },
                vertexColors: new[] { new Vector3d(1, 0, 0), new Vector3d(0, 1, 0), new Vector3d(0, 0, 1) });
            var sample = SphereSurfaceSampler.Sample(new[] { mesh }, 500, 5, Vector3d.Zero, 3);
            Assert.That(sample.Points, Has.Count.EqualTo(500));
            foreach (var p in sample.Points)
            {
                // Barycentric weights of the position: wb along x, wc along z (right triangle of legs 16).
                var wb = (p.Position.X + 4) / 16;
                var wc = (p.Position.Z + 4) / 16;
                var wa = 1 - wb - wc;
                Assert.That(new[] { (int)p.Red, p.Green, p.Blue }, Is.EqualTo(new[] { CloudPoint.ToByte(wa), CloudPoint.ToByte(wb), CloudPoint.ToByte(wc) }).Within(1), "at " + p.Position);
                Assert.That(p.Normal, Is.EqualTo(Vector3d.UnitY));
                Assert.That(p.Position.Length, Is.LessThanOrEqualTo(3 + 1e-9));
            }
        }

        [Test]
        public void TheSameSeedGivesTheSamePoints()
        {
            var one = SphereSurfaceSampler.Sample(new[] { Ground() }, 100, 42, new Vector3d(3, 0, 1), 6).Points.Select(p => p.Position);
            var two = SphereSurfaceSampler.Sample(new[] { Ground() }, 100, 42, new Vector3d(3, 0, 1), 6).Points.Select(p => p.Position);
            Assert.That(one, Is.EqualTo(two));
        }

        [Test]
        public void NoSurfaceWithinTheRadiusIsAnErrorNamingIt()
        {
            var error = Assert.Throws<InvalidParameterException>(() =>
                SphereSurfaceSampler.Sample(new[] { Square(new Vector3d(50, 0, 50), 10) }, 10, 1, Vector3d.Zero, 5));
            Assert.That(error.Message, Does.Contain("pointCloudRadius"));
        }

        // Unity room 10 × 2 × 10 at y = 1: half-diagonal √(100 + 4 + 100) / 2.
        static readonly OrientedBox Room = OrientedBox.AxisAligned("Room", new Vector3d(0, 1, 0), new Vector3d(10, 2, 10));

        static CapturePlan EnvironmentPlan(double radius = 0, int points = 1000)
        {
            var s = new DatasetSettings { Normalisation = NormalisationMode.None, Width = 64, Height = 64, Seed = 9, PointCloudPoints = points, PointCloudRadius = radius };
            s.Train.Count = 4;
            s.Train.Source = new CameraSourceSettings { Kind = CameraSourceKind.Volume, ObjectPath = "Room", Volume = new VolumeScene(Room, null) };
            s.Val.Count = 1;
            s.Val.Source = new CameraSourceSettings { Kind = CameraSourceKind.Volume, ObjectPath = "Room", Volume = new VolumeScene(Room, null) };
            s.Test.Count = 1;
            s.Test.Source = new CameraSourceSettings { Kind = CameraSourceKind.Volume, ObjectPath = "Room", Volume = new VolumeScene(Room, null) };
            return CapturePlan.Build(s, PlanTarget.AtOrigin);
        }

        [Test]
        public void AnEnvironmentsRegionIsFourHalfDiagonalsOfItsBoxesUnlessARadiusIsGiven()
        {
            var region = TargetPointCloud.Region(EnvironmentPlan());
            Assert.That(region.Centre, Is.EqualTo(new Vector3d(0, 1, 0)));
            Assert.That(region.Radius, Is.EqualTo(4 * Math.Sqrt(204) / 2).Within(1e-12));
            Assert.That(region.Automatic, Is.True);
            var given = TargetPointCloud.Region(EnvironmentPlan(radius: 12));
            Assert.That(given.Radius, Is.EqualTo(12));
            Assert.That(given.Automatic, Is.False);
            var objectPlan = CapturePlan.Build(new DatasetSettings { PointCloudPoints = 10 }, PlanTarget.AtOrigin);
            Assert.That(TargetPointCloud.Region(objectPlan), Is.Null, "an object capture samples its target's whole surface");
        }

        [Test]
        public void AnEnvironmentsCloudKeepsOnlyTheSurfaceNearItsVolume()
        {
            var plan = EnvironmentPlan(radius: 20);
            var cloud = TargetPointCloud.Sample(plan, new[] { Ground() });
            Assert.That(cloud, Has.Count.EqualTo(1000));
            // Output = (x, z, y)_Unity with normalisation none: the ground is Z = 0, the sphere's centre (0, 0, 1).
            Assert.That(cloud.Select(p => (p.Position - new Vector3d(0, 0, 1)).Length), Has.All.LessThanOrEqualTo(20 + 1e-9));
            Assert.That(cloud.Select(p => p.Position.Z), Has.All.EqualTo(0).Within(1e-9));
            Assert.That(TargetPointCloud.Check(plan, new[] { Ground() }), Is.Empty);
            var problems = TargetPointCloud.Check(plan, new[] { Square(new Vector3d(500, 0, 500), 10) });
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "pointCloudRadius" }));
        }

        [Test]
        public void TheRadiusIsASettingReadWrittenAndChecked()
        {
            var s = new DatasetSettings { PointCloudRadius = 25.5 };
            var json = DatasetSettingsJson.Write(s);
            Assert.That(json, Does.Contain("\"pointCloudRadius\": 25.5"));
            Assert.That(DatasetSettingsJson.Read(json).Settings.PointCloudRadius, Is.EqualTo(25.5));
            s.PointCloudRadius = -1;
            Assert.That(SettingsValidator.Validate(s).Select(p => p.Field), Has.Member("pointCloudRadius"));
        }
    }
}
