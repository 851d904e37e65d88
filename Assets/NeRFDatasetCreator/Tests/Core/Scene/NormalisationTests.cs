using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Recentring and scaling must not change what any camera sees: a point of the target projects to the same
    /// pixel before and after. Pixels come from inverting NeRF's ray formula (checked against NerfRays itself).
    /// </summary>
    public class NormalisationTests
    {
        const int Width = 640;
        const int Height = 480;
        const double VerticalFov = 50;

        static readonly Vector3d TargetUnity = new Vector3d(12.5, 3.25, -7.75); // deliberately far from the origin
        const double TargetRadius = 0.8;
        const double CameraDistance = 3.6;

        static IReadOnlyList<UnityPose> Rig() => CameraRig.Place(new RandomFormation(7, upperHemisphereOnly: false), 40, TargetUnity, CameraDistance);

        static IEnumerable<Vector3d> TargetSamples()
        {
            var random = new SeededRandom(3);
            for (var i = 0; i < 25; i++)
            {
                var d = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
                yield return TargetUnity + d.Normalized() * (TargetRadius * random.NextDouble());
            }
        }

        [TestCase(NormalisationMode.None)]
        [TestCase(NormalisationMode.Recentre)]
        [TestCase(NormalisationMode.NerfSyntheticScale)]
        [TestCase(NormalisationMode.FitTargetRadius)]
        public void EveryCameraSeesTheTargetAtTheSamePixels(NormalisationMode mode)
        {
            var n = SceneNormalisation.ForTarget(mode, TargetUnity, TargetRadius, CameraDistance);
            var intrinsics = CameraIntrinsics.FromVerticalFov(VerticalFov, Width, Height);
            var compared = 0;
            foreach (var pose in Rig())
            {
                var raw = BlenderConvention.CameraToWorld(pose);
                var normalised = n.ApplyToCameraToWorld(raw);
                Assert.That(normalised.Determinant3x3, Is.EqualTo(1.0).Within(1e-12));
                foreach (var point in TargetSamples())
                {
                    var before = Project(raw.ToRows(), intrinsics.CameraAngleX, BlenderConvention.FromUnity(point));
                    var after = Project(normalised.ToRows(), intrinsics.CameraAngleX, n.ApplyToUnityPoint(point));
                    Assert.That(after[0], Is.EqualTo(before[0]).Within(1e-8), "column");
                    Assert.That(after[1], Is.EqualTo(before[1]).Within(1e-8), "row");
                    // Depth is a length: it scales by s and nothing else (the documented depth rule).
                    Assert.That(after[2], Is.EqualTo(n.ApplyToDepth(before[2])).Within(1e-9), "z-depth");
                    // And NeRF itself agrees: its ray through the pixel where the raw camera saw the point passes
                    // through the normalised point, at the normalised depth.
                    var q = n.ApplyToUnityPoint(point);
                    NerfRays.Ray(normalised.ToRows(), intrinsics.CameraAngleX, Width, Height, before[0], before[1], out var o, out var dir);
                    Assert.That(NerfRays.DistanceToRay(o, dir, new[] { q.X, q.Y, q.Z }, out var t), Is.LessThan(1e-9 * Math.Max(1, n.Scale)));
                    Assert.That(t, Is.EqualTo(after[2]).Within(1e-9));
                    compared++;
                }
            }
            Assert.That(compared, Is.EqualTo(40 * 25));
        }

        [Test]
        public void Projection_IsTheInverseOfNerfsRayFormula()
        {
            var pose = BlenderConvention.CameraToWorld(Rig()[5]).ToRows();
            var angle = CameraIntrinsics.FromVerticalFov(VerticalFov, Width, Height).CameraAngleX;
            var point = BlenderConvention.FromUnity(TargetSamples().First());
            var pixel = Project(pose, angle, point);

            NerfRays.Ray(pose, angle, Width, Height, pixel[0], pixel[1], out var origin, out var direction);
            var distance = NerfRays.DistanceToRay(origin, direction, new[] { point.X, point.Y, point.Z }, out var t);

            Assert.That(distance, Is.LessThan(1e-9));
            Assert.That(t, Is.EqualTo(pixel[2]).Within(1e-9), "NeRF's direction has unit −z, so t is the z-depth");
        }

        [Test]
        public void Recentre_PutsTheTargetAtTheOriginAndKeepsUnits()
        {
            var n = SceneNormalisation.ForTarget(NormalisationMode.Recentre, TargetUnity, TargetRadius, CameraDistance);

            var centre = n.ApplyToUnityPoint(TargetUnity);
            Assert.That(centre.Length, Is.EqualTo(0.0).Within(1e-12));
            Assert.That(n.Scale, Is.EqualTo(1.0));
            // Blender axes: (x, z, y) of Unity.
            Assert.That(n.Centre, Is.EqualTo(new Vector3d(12.5, -7.75, 3.25)));
            foreach (var pose in Rig())
                Assert.That(n.ApplyToCameraToWorld(BlenderConvention.CameraToWorld(pose)).Translation.Length, Is.EqualTo(CameraDistance).Within(1e-12));
        }

        [Test]
        public void NerfSyntheticPreset_PutsCamerasAtRadiusFour()
        {
            var n = SceneNormalisation.ForTarget(NormalisationMode.NerfSyntheticScale, TargetUnity, TargetRadius, CameraDistance);

            Assert.That(n.Scale, Is.EqualTo(4 / 3.6).Within(1e-15));
            foreach (var pose in Rig())
                Assert.That(n.ApplyToCameraToWorld(BlenderConvention.CameraToWorld(pose)).Translation.Length, Is.EqualTo(4.0).Within(1e-12));
        }

        [Test]
        public void FitTargetRadius_GivesTheChosenRadius()
        {
            var n = SceneNormalisation.ForTarget(NormalisationMode.FitTargetRadius, TargetUnity, TargetRadius, CameraDistance, chosenRadius: 1.3);

            Assert.That(n.Scale * TargetRadius, Is.EqualTo(1.3).Within(1e-15));
        }

        [Test]
        public void Matrix_MapsPointsLikeApplyToPoint()
        {
            var n = new SceneNormalisation(new Vector3d(1, -2, 3), 0.25);
            var p = new Vector3d(5, 6, -7);

            Assert.That(n.Matrix.MultiplyPoint(p), Is.EqualTo(n.ApplyToPoint(p)));
            Assert.That(n.ApplyToPoint(p), Is.EqualTo(new Vector3d(1, 2, -2.5)));
        }

        [Test]
        public void Record_RoundTripsThroughJson()
        {
            var n = new SceneNormalisation(new Vector3d(0.1, -0.2, 1.0 / 3), 4 / 3.6);

            var back = SceneNormalisation.FromJson(Newtonsoft.Json.Linq.JToken.Parse(ExportJson.Serialise(n.ToJson())));

            Assert.That(back.Scale, Is.EqualTo(n.Scale));
            Assert.That(back.Centre, Is.EqualTo(n.Centre));
        }

        [Test]
        public void BadInput_NamesTheField()
        {
            var e = Assert.Throws<InvalidParameterException>(() =>
                SceneNormalisation.ForTarget(NormalisationMode.FitTargetRadius, TargetUnity, 0, CameraDistance));
            Assert.That(e.Problems[0].Field, Is.EqualTo("normalisation.targetRadius"));

            e = Assert.Throws<InvalidParameterException>(() => new SceneNormalisation(Vector3d.Zero, double.NaN));
            Assert.That(e.Problems[0].Field, Is.EqualTo("normalisation.scale"));
        }

        /// <summary>Column, row (from the top) and z-depth of a world point: NeRF's ray formula solved for the pixel.</summary>
        static double[] Project(double[][] c2w, double cameraAngleX, Vector3d p)
        {
            var focal = 0.5 * Width / Math.Tan(0.5 * cameraAngleX);
            var d = new[] { p.X - c2w[0][3], p.Y - c2w[1][3], p.Z - c2w[2][3] };
            var cam = new double[3];
            for (var k = 0; k < 3; k++) cam[k] = c2w[0][k] * d[0] + c2w[1][k] * d[1] + c2w[2][k] * d[2]; // Rᵀ·d
            var z = -cam[2];
            Assert.That(z, Is.GreaterThan(0), "the target is in front of every camera");
            return new[] { Width * 0.5 + focal * cam[0] / z, Height * 0.5 - focal * cam[1] / z, z };
        }
    }
}
