using System;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class PlanNormalisationTests
    {
        static readonly Vector3d Centre = new Vector3d(10, 2, -3);

        static DatasetSettings Small(NormalisationMode mode, double distance = 4)
        {
            var s = new DatasetSettings { Seed = 42, Normalisation = mode, Distance = distance };
            s.Train.Count = 10;
            s.Val.Count = 6;
            s.Test.Count = 8;
            return s;
        }

        [Test]
        public void RecentreGivesTheMatricesOfThePoseMinusTheCentreBitForBit()
        {
            // The matrices written before normalisation existed: the Blender conversion of the pose moved by −centre.
            var plan = CapturePlan.Build(Small(NormalisationMode.Recentre), new PlanTarget(Centre, 0.5));
            foreach (var v in plan.Views)
            {
                var old = BlenderConvention.CameraToWorld(new UnityPose(v.Pose.Position - Centre, v.Pose.Rotation));
                for (var r = 0; r < 4; r++)
                    for (var c = 0; c < 4; c++)
                        Assert.That(BitConverter.DoubleToInt64Bits(v.TransformMatrix[r, c]), Is.EqualTo(BitConverter.DoubleToInt64Bits(old[r, c])), v.FramePath);
            }
            Assert.That(plan.Normalisation.Scale, Is.EqualTo(1.0));
            Assert.That(plan.Normalisation.Centre, Is.EqualTo(new Vector3d(10, -3, 2)), "P·A: Unity (x, y, z) → (x, z, y)");
        }

        [Test]
        public void NoneKeepsTheUnityWorldOnlyRelabelled()
        {
            var plan = CapturePlan.Build(Small(NormalisationMode.None), new PlanTarget(Centre, 0.5));
            foreach (var v in plan.Views)
                Assert.That(v.TransformMatrix, Is.EqualTo(BlenderConvention.CameraToWorld(v.Pose)));
        }

        [Test]
        public void NerfSyntheticScalePutsEveryCameraAtRadiusFour()
        {
            var plan = CapturePlan.Build(Small(NormalisationMode.NerfSyntheticScale, distance: 10), new PlanTarget(Centre, 1));
            Assert.That(plan.Normalisation.Scale, Is.EqualTo(0.4).Within(1e-15));
            foreach (var v in plan.Views)
            {
                Assert.That(v.TransformMatrix.Translation.Length, Is.EqualTo(4.0).Within(1e-12), v.FramePath);
                Assert.That(v.TransformMatrix.Determinant3x3, Is.EqualTo(1.0).Within(1e-12), "rotations are untouched");
            }
        }

        [Test]
        public void FitRadiusScalesTheBoundingSphereToTheChosenRadius()
        {
            var s = Small(NormalisationMode.FitTargetRadius, distance: 8);
            s.NormalisedTargetRadius = 1;
            var plan = CapturePlan.Build(s, new PlanTarget(Centre, 2));
            Assert.That(plan.Normalisation.Scale, Is.EqualTo(0.5));
            Assert.That(plan.TargetReach, Is.EqualTo(1.0).Within(1e-12));
            Assert.That(plan.Views[0].TransformMatrix.Translation.Length, Is.EqualTo(4.0).Within(1e-12), "8 Unity units × 0.5");
        }

        [Test]
        public void FitRadiusWithoutTargetBoundsIsAProblem()
        {
            var problems = CapturePlan.Check(Small(NormalisationMode.FitTargetRadius), PlanTarget.AtOrigin);
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "normalisation" }));
            Assert.That(problems[0].Value, Is.EqualTo("\"fit-radius\""));
        }

        [TestCase(NormalisationMode.None)]
        [TestCase(NormalisationMode.NerfSyntheticScale)]
        [TestCase(NormalisationMode.FitTargetRadius)]
        public void EveryCameraSeesTheTargetAsBefore(NormalisationMode mode)
        {
            // A scene point that projects to pixel (i, j) in the recentred dataset lies, after normalisation, on NeRF's
            // own ray through the same pixel of the normalised dataset (bmild/nerf get_rays, written independently).
            var target = new PlanTarget(Centre, 1);
            var reference = CapturePlan.Build(Small(NormalisationMode.Recentre, 6), target);
            var normalised = CapturePlan.Build(Small(mode, 6), target);
            var n = normalised.Normalisation;
            int w = reference.Intrinsics.Width, h = reference.Intrinsics.Height;
            var angle = reference.Intrinsics.CameraAngleX;
            var unityPoints = new[] { Centre, Centre + new Vector3d(0.7, -0.2, 0.3), Centre + new Vector3d(-0.5, 0.6, -0.4) };
            for (var k = 0; k < reference.Views.Count; k++)
            {
                var m = reference.Views[k].TransformMatrix;
                foreach (var u in unityPoints)
                {
                    var p = BlenderConvention.FromUnity(u - Centre); // the point in the recentred output world
                    Pixel(m, p, w, h, angle, out var i, out var j);
                    NerfRays.Ray(normalised.Views[k].TransformMatrix.ToRows(), angle, w, h, i, j, out var origin, out var direction);
                    var q = n.ApplyToUnityPoint(u);
                    var distance = NerfRays.DistanceToRay(origin, direction, new[] { q.X, q.Y, q.Z }, out var t);
                    Assert.That(distance, Is.LessThan(1e-9), normalised.Views[k].FramePath);
                    Assert.That(t, Is.GreaterThan(0), "in front of the camera");
                }
            }
        }

        /// <summary>The pixel (column i, row j from the top) of output point <paramref name="p"/> in the OpenGL camera of c2w <paramref name="m"/>.</summary>
        static void Pixel(Matrix4x4d m, Vector3d p, int width, int height, double angleX, out double i, out double j)
        {
            var d = p - m.Translation;
            var x = Vector3d.Dot(m.Column(0), d);
            var y = Vector3d.Dot(m.Column(1), d);
            var z = Vector3d.Dot(m.Column(2), d);
            var focal = 0.5 * width / Math.Tan(0.5 * angleX);
            i = width * 0.5 + focal * x / -z;
            j = height * 0.5 - focal * y / -z;
        }

        [Test]
        public void TheDefaultPlanHasNoWarnings()
        {
            Assert.That(CapturePlan.Build(new DatasetSettings(), PlanTarget.AtOrigin).Warnings, Is.Empty);
            Assert.That(CapturePlan.Build(new DatasetSettings(), new PlanTarget(Centre, 1)).Warnings, Is.Empty);
        }

        [Test]
        public void FarCamerasWarnForNerfAndThePresetClearsIt()
        {
            var recentred = CapturePlan.Build(Small(NormalisationMode.Recentre, 10), new PlanTarget(Centre, 1));
            // The warning names the setting that fixes it, with its value: a key the config really has (issue 23).
            Assert.That(recentred.Warnings.Select(w => w.Field + " = " + w.Value), Is.EqualTo(new[] { "normalisation = \"recentre\"" }));
            Assert.That(recentred.Warnings[0].Reason, Does.Contain("beyond NeRF's fixed far distance 6"));
            Assert.That(recentred.Warnings[0].Fix, Does.Contain("nerf_synthetic scale preset"));

            var preset = CapturePlan.Build(Small(NormalisationMode.NerfSyntheticScale, 10), new PlanTarget(Centre, 1));
            Assert.That(preset.Warnings, Is.Empty, "cameras at 4, target radius 0.4: near 3.6, far 4.4");

            var ngpOnly = Small(NormalisationMode.Recentre, 10);
            ngpOnly.Loaders = TargetLoaders.InstantNgp;
            Assert.That(CapturePlan.Build(ngpOnly, new PlanTarget(Centre, 1)).Warnings, Is.Empty, "near/far concern NeRF only");
        }

        [Test]
        public void ALargeTargetWarnsFor3dgsUnlessAPointCloudIsWritten()
        {
            var s = Small(NormalisationMode.Recentre, 5);
            s.Loaders = TargetLoaders.GaussianSplatting;
            Assert.That(CapturePlan.Build(s, new PlanTarget(Centre, 1.4)).Warnings.Select(w => w.Field), Is.EqualTo(new[] { "normalisation" }));
            Assert.That(CapturePlan.Build(s, new PlanTarget(Centre, 1.4)).Warnings[0].Reason, Does.Contain("3DGS's random initial cloud"));
            s.PointCloudPoints = 1000;
            Assert.That(CapturePlan.Build(s, new PlanTarget(Centre, 1.4)).Warnings, Is.Empty);
        }

        [Test]
        public void AShardsPlanKeepsTheWholeNormalisationAndWarnings()
        {
            var plan = CapturePlan.Build(Small(NormalisationMode.Recentre, 10), new PlanTarget(Centre, 1));
            var shard = plan.Only(v => v.Split == DatasetSplit.Test);
            Assert.That(shard.Normalisation, Is.SameAs(plan.Normalisation));
            Assert.That(shard.Warnings, Is.SameAs(plan.Warnings));
        }

        // aabb_scale = 2^ceil(log2(0.66·reach)), at least 1: reach 1 → 0.66 → 1; 1.6 → 1.056 → 2; 3.1 → 2.046 → 4.
        [TestCase(1.0, 1)]
        [TestCase(1.6, 2)]
        [TestCase(3.1, 4)]
        public void AabbScaleHoldsTheRecentredTarget(double radius, int expected)
        {
            var plan = CapturePlan.Build(Small(NormalisationMode.Recentre, 12), new PlanTarget(Centre, radius));
            Assert.That(plan.AabbScale, Is.EqualTo(expected));
            var train = JObject.Parse(BlenderTransformsWriter.Write(plan, DatasetSplit.Train));
            Assert.That((int)train["aabb_scale"], Is.EqualTo(expected));
        }

        [Test]
        public void AnOffOriginTargetWithoutRecentringNeedsALargerCube()
        {
            // Not recentred: the target (radius 1) sits |(10, -3, 2)| = 10.63 from the origin: reach 11.63 → 0.66·11.63 = 7.7 → 8.
            var plan = CapturePlan.Build(Small(NormalisationMode.None, 12), new PlanTarget(Centre, 1));
            Assert.That(plan.AabbScale, Is.EqualTo(8));
        }

        [Test]
        public void TheFilesRecordTheNormalisation()
        {
            var plan = CapturePlan.Build(Small(NormalisationMode.NerfSyntheticScale, 10), new PlanTarget(Centre, 1));
            foreach (var split in DatasetSplits.All)
            {
                var json = JObject.Parse(BlenderTransformsWriter.Write(plan, split));
                var read = SceneNormalisation.FromJson(json["scene_normalisation"]);
                Assert.That(read.Scale, Is.EqualTo(0.4).Within(1e-15));
                Assert.That(read.Centre, Is.EqualTo(new Vector3d(10, -3, 2)));
                Assert.That(json.Properties().Last().Name, Is.EqualTo("frames"), "frames stays last, as in nerf_synthetic");
            }
            var config = JObject.Parse(DatasetConfig.Write(plan, new Provenance(new DateTime(2026, 1, 1, 0, 0, 0, DateTimeKind.Utc))));
            var fromConfig = SceneNormalisation.FromJson(config["scene_normalisation"]);
            Assert.That(fromConfig.Scale, Is.EqualTo(plan.Normalisation.Scale));
            Assert.That(fromConfig.Centre, Is.EqualTo(plan.Normalisation.Centre));
            // x_out = M·x: the recorded matrix maps the Unity target centre to the origin and a camera to its c2w translation.
            var m = Matrix4x4d.FromRows(config["scene_normalisation"]["transform"].ToObject<double[][]>());
            Assert.That(m.MultiplyPoint(BlenderConvention.FromUnity(Centre)).Length, Is.LessThan(1e-12));
            var v = plan.Views[3];
            Assert.That((m.MultiplyPoint(BlenderConvention.FromUnity(v.Pose.Position)) - v.TransformMatrix.Translation).Length, Is.LessThan(1e-12));
            Assert.That((string)config["settings"]["normalisation"], Is.EqualTo("nerf-synthetic"));
        }
    }
}
