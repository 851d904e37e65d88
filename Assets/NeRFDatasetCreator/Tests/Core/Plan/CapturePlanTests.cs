using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class CapturePlanTests
    {
        static DatasetSettings Small()
        {
            var s = new DatasetSettings { Seed = 42 };
            s.Train.Count = 10;
            s.Val.Count = 6;
            s.Test.Count = 8;
            return s;
        }

        [Test]
        public void ViewsAreTrainThenValThenTestEachByIndex()
        {
            var plan = CapturePlan.Build(Small(), PlanTarget.AtOrigin);
            Assert.That(plan.Views, Has.Count.EqualTo(24));
            var expected = Enumerable.Range(0, 10).Select(i => "train/" + i)
                .Concat(Enumerable.Range(0, 6).Select(i => "val/" + i))
                .Concat(Enumerable.Range(0, 8).Select(i => "test/" + i));
            Assert.That(plan.Views.Select(v => DatasetSplits.Name(v.Split) + "/" + v.Index), Is.EqualTo(expected));
            Assert.That(plan.Views[12].FramePath, Is.EqualTo("./val/r_2"));
            Assert.That(plan.Views[12].Stem, Is.EqualTo("r_2"));
        }

        [Test]
        public void DefaultPlanHasNerfSyntheticCounts()
        {
            var plan = CapturePlan.Build(new DatasetSettings(), PlanTarget.AtOrigin);
            Assert.That(plan.ViewsOf(DatasetSplit.Train).Count(), Is.EqualTo(100));
            Assert.That(plan.ViewsOf(DatasetSplit.Val).Count(), Is.EqualTo(100));
            Assert.That(plan.ViewsOf(DatasetSplit.Test).Count(), Is.EqualTo(200));
        }

        [Test]
        public void EveryOutputCameraIsAtTheDistanceAndLooksAtTheOrigin()
        {
            var plan = CapturePlan.Build(new DatasetSettings(), PlanTarget.AtOrigin);
            foreach (var v in plan.Views)
            {
                var m = v.TransformMatrix;
                Assert.That(m.Translation.Length, Is.EqualTo(4.0).Within(1e-12));
                // NeRF's centre ray: direction c2w·(0, 0, −1) from the camera centre reaches the origin after 4 units.
                var centreRay = m.MultiplyVector(new Vector3d(0, 0, -1));
                Assert.That((m.Translation + 4 * centreRay).Length, Is.LessThan(1e-12));
                Assert.That(m.Determinant3x3, Is.EqualTo(1.0).Within(1e-12), "a proper rotation");
                // No roll: the camera's +X axis stays horizontal in the Z-up output world.
                Assert.That(m[2, 0], Is.EqualTo(0.0).Within(1e-12));
            }
        }

        [Test]
        public void TrainAndValAreOnTheUpperHemisphere()
        {
            var plan = CapturePlan.Build(new DatasetSettings(), PlanTarget.AtOrigin);
            foreach (var v in plan.Views.Where(v => v.Split != DatasetSplit.Test))
                Assert.That(v.TransformMatrix[2, 3], Is.GreaterThanOrEqualTo(0.0), v.FramePath);
        }

        [Test]
        public void FirstTrainCameraIsNearTheZenith()
        {
            // Golden semi-sphere 90°→0°: heights sin e = 1 − (i + ½)/N, so camera 0 of 100 sits at z = 4·0.995.
            var plan = CapturePlan.Build(new DatasetSettings(), PlanTarget.AtOrigin);
            Assert.That(plan.Views[0].TransformMatrix[2, 3], Is.EqualTo(4 * 0.995).Within(1e-12));
        }

        [Test]
        public void ValViewsComeFromTheSeedDerivedForTheSplitName()
        {
            var s = Small();
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            var expected = CameraRig.Place(new RandomFormation(SeededRandom.Derive(42, "val"), true), 6, Vector3d.Zero, 4);
            var val = plan.ViewsOf(DatasetSplit.Val).ToList();
            for (var i = 0; i < 6; i++)
            {
                Assert.That(val[i].Pose.Position, Is.EqualTo(expected[i].Position));
                Assert.That(val[i].Pose.Rotation, Is.EqualTo(expected[i].Rotation));
            }
        }

        [Test]
        public void SameSettingsAndSeedGiveTheSamePlanByteForByte()
        {
            var a = CapturePlanJson.Write(CapturePlan.Build(new DatasetSettings { Seed = 7 }, PlanTarget.AtOrigin));
            var b = CapturePlanJson.Write(CapturePlan.Build(new DatasetSettings { Seed = 7 }, PlanTarget.AtOrigin));
            Assert.That(b, Is.EqualTo(a));
            Assert.That(a.Length, Is.GreaterThan(100000), "the text holds every pose");
        }

        [Test]
        public void AnotherSeedChangesOnlyTheRandomSplits()
        {
            var a = CapturePlan.Build(new DatasetSettings { Seed = 1 }, PlanTarget.AtOrigin);
            var b = CapturePlan.Build(new DatasetSettings { Seed = 2 }, PlanTarget.AtOrigin);
            Assert.That(b.ViewsOf(DatasetSplit.Train).Select(v => v.TransformMatrix), Is.EqualTo(a.ViewsOf(DatasetSplit.Train).Select(v => v.TransformMatrix)));
            Assert.That(b.ViewsOf(DatasetSplit.Val).First().TransformMatrix, Is.Not.EqualTo(a.ViewsOf(DatasetSplit.Val).First().TransformMatrix));
        }

        [Test]
        public void OutputPosesAreRecentredOnTheTarget()
        {
            var centre = new Vector3d(10, 2, -3);
            var atOrigin = CapturePlan.Build(Small(), PlanTarget.AtOrigin);
            var moved = CapturePlan.Build(Small(), new PlanTarget(centre, 0.5));
            for (var i = 0; i < atOrigin.Views.Count; i++)
            {
                var expectedPosition = atOrigin.Views[i].Pose.Position + centre;
                Assert.That((moved.Views[i].Pose.Position - expectedPosition).Length, Is.LessThan(1e-12));
                var a = atOrigin.Views[i].TransformMatrix;
                var b = moved.Views[i].TransformMatrix;
                for (var r = 0; r < 4; r++)
                    for (var c = 0; c < 4; c++)
                        Assert.That(b[r, c], Is.EqualTo(a[r, c]).Within(1e-12));
            }
        }

        [Test]
        public void OutputMatrixIsTheBlenderConversionOfTheRecentredUnityPose()
        {
            var plan = CapturePlan.Build(Small(), PlanTarget.AtOrigin);
            foreach (var v in plan.Views)
                Assert.That(v.TransformMatrix, Is.EqualTo(BlenderConvention.CameraToWorld(v.Pose)));
        }

        [Test]
        public void ViewsListTheFilesTheirSplitWrites()
        {
            var s = Small();
            s.Test.Depth = ExtraOutput.PngAndExr;
            s.Test.Normal = ExtraOutput.Png;
            s.Test.Mask = true;
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            Assert.That(plan.Views[0].Files.Select(f => f.RelativePath), Is.EqualTo(new[] { "train/r_0.png" }));
            var test7 = plan.ViewsOf(DatasetSplit.Test).Last();
            Assert.That(test7.Files.Select(f => f.RelativePath), Is.EqualTo(new[]
            {
                "test/r_7.png", "test/r_7_depth_0000.png", "test/r_7_depth_0000.exr", "test/r_7_normal_0000.png", "test/r_7_mask_0000.png",
            }));
        }

        [Test]
        public void AutoDistanceUsesTheTargetBounds()
        {
            var s = Small();
            s.AutoDistance = true;
            var plan = CapturePlan.Build(s, new PlanTarget(Vector3d.Zero, 1.0));
            var expected = AutoDistanceRule.Distance(1.0, s.Camera.VerticalFovDegrees, 800, 800, AutoDistanceRule.DefaultMargin);
            Assert.That(plan.Distance, Is.EqualTo(expected));
            Assert.That(plan.Views[0].TransformMatrix.Translation.Length, Is.EqualTo(expected).Within(1e-12));
        }

        [Test]
        public void AutoDistanceWithoutBoundsIsAProblem()
        {
            var s = Small();
            s.AutoDistance = true;
            var e = Assert.Throws<InvalidParameterException>(() => CapturePlan.Build(s, PlanTarget.AtOrigin));
            Assert.That(e.Problems.Select(p => p.Field), Is.EqualTo(new[] { "distance" }));
        }

        [Test]
        public void ClipPlanesThatCutTheTargetAreProblems()
        {
            var s = Small();
            s.Camera.NearClip = 1;
            s.Camera.FarClip = 6;
            var problems = CapturePlan.Check(s, new PlanTarget(Vector3d.Zero, 3.5));
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "camera.nearClip", "camera.farClip" }));
            Assert.That(CapturePlan.Check(s, new PlanTarget(Vector3d.Zero, 1.5)), Is.Empty);
        }

        [Test]
        public void CamerasInsideTheTargetAreAProblem()
        {
            var problems = CapturePlan.Check(Small(), new PlanTarget(Vector3d.Zero, 5));
            Assert.That(problems.Select(p => p.Field), Does.Contain("distance"));
        }

        [Test]
        public void InvalidSettingsThrowWithEveryProblem()
        {
            var s = Small();
            s.Width = 1;
            s.Train.Count = -1;
            var e = Assert.Throws<InvalidParameterException>(() => CapturePlan.Build(s, PlanTarget.AtOrigin));
            Assert.That(e.Problems.Select(p => p.Field), Is.EquivalentTo(new[] { "width", "splits.train.count" }));
        }

        [Test]
        public void ThePlanKeepsItsOwnCopyOfTheSettings()
        {
            var s = Small();
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            s.Train.Count = 99;
            Assert.That(plan.Settings.Train.Count, Is.EqualTo(10));
        }

        [Test]
        public void RotationKeyIsTheFormationsAzimuthStep()
        {
            var s = Small();
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            // Golden ratio: 2π·φ = 10.16641 (the original plugin's value, reference §1.3).
            Assert.That(plan.RotationOf(DatasetSplit.Train), Is.EqualTo(2 * Math.PI * (1 + Math.Sqrt(5)) / 2).Within(1e-12));
            Assert.That(plan.RotationOf(DatasetSplit.Train), Is.EqualTo(10.16641).Within(1e-5));
            Assert.That(plan.RotationOf(DatasetSplit.Val), Is.EqualTo(0.0), "random has no step");
            Assert.That(plan.RotationOf(DatasetSplit.Test), Is.EqualTo(2 * Math.PI * 2 / 8).Within(1e-15), "orbit: 2 turns over 8 views");
            s.Train.Formation = new FormationSettings { Kind = FormationKind.Halo };
            Assert.That(CapturePlan.Build(s, PlanTarget.AtOrigin).RotationOf(DatasetSplit.Train), Is.EqualTo(2 * Math.PI / 10).Within(1e-15));
        }
    }
}
