using System;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class VolumeSourcePlanTests
    {
        static readonly OrientedBox Room = OrientedBox.AxisAligned("CaptureVolume", new Vector3d(0, 1, 0), new Vector3d(10, 2, 10));
        static readonly OrientedBox Wall = OrientedBox.AxisAligned("Walls/Middle", new Vector3d(0, 1, 0), new Vector3d(1, 4, 12));

        static DatasetSettings WithVolume(params OrientedBox[] obstacles)
        {
            var s = new DatasetSettings { Normalisation = NormalisationMode.None, Width = 200, Height = 100, Seed = 17 };
            s.Train.Count = 60;
            s.Train.Source = new CameraSourceSettings { Kind = CameraSourceKind.Volume, ObjectPath = "CaptureVolume", Volume = new VolumeScene(Room, obstacles) };
            s.Val.Count = 1;
            s.Test.Count = 5;
            s.Test.Source = new CameraSourceSettings { Kind = CameraSourceKind.Volume, ObjectPath = "CaptureVolume", Look = VolumeLook.Sphere, Volume = new VolumeScene(Room, obstacles) };
            return s;
        }

        [Test]
        public void EachSplitGetsItsCountOfSampledCamerasWrittenThroughTheOutputConvention()
        {
            var plan = CapturePlan.Build(WithVolume(Wall), PlanTarget.AtOrigin);
            var train = plan.ViewsOf(DatasetSplit.Train).ToList();
            Assert.That(train, Has.Count.EqualTo(60));
            Assert.That(plan.ViewsOf(DatasetSplit.Test).Count(), Is.EqualTo(5));
            Assert.That(train.Select(v => Math.Abs(v.Pose.Position.X)), Has.All.GreaterThan(0.75), "the wall and its default clearance 0.25");
            // Output = Blender world: (x, y, z)_out = (x, z, y)_Unity, and the camera's −Z column is its Unity forward.
            foreach (var v in train)
            {
                var m = v.TransformMatrix;
                Assert.That(m.Translation, Is.EqualTo(new Vector3d(v.Pose.Position.X, v.Pose.Position.Z, v.Pose.Position.Y)));
                var f = v.Pose.Rotation.Forward;
                Assert.That(new[] { -m[0, 2], -m[1, 2], -m[2, 2] }, Is.EqualTo(new[] { f.X, f.Z, f.Y }).Within(1e-12));
                Assert.That(m[2, 2], Is.EqualTo(0).Within(1e-12), "ring: level cameras, the back vector has no height");
            }
            Assert.That(plan.Intrinsics.CameraAngleX, Is.EqualTo(new DatasetSettings { Width = 200, Height = 100 }.Intrinsics().CameraAngleX), "the Camera step's lens");
        }

        [Test]
        public void RejectionsAreAWarningThatCountsThemAndNamesTheObstacle()
        {
            var plan = CapturePlan.Build(WithVolume(Wall), PlanTarget.AtOrigin);
            var warning = plan.Warnings.Single(w => w.Field == "splits.train.source.box");
            Assert.That(warning.Reason, Does.Match(@"^rejected \d+ of \d+ positions drawn .*Walls/Middle \d+\); 60 cameras kept\.$"));
            Assert.That(CapturePlan.Build(WithVolume(), PlanTarget.AtOrigin).Warnings.Where(w => w.Field.EndsWith(".box")), Is.Empty);
        }

        [Test]
        public void NerfBlenderLoadersGetOnePlainWarningInsteadOfTargetNearFar()
        {
            var s = WithVolume();
            s.Loaders = TargetLoaders.All;
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            var warnings = plan.Warnings;
            Assume.That(LoaderRangeCheck.ClassifiedForCapture(plan.Views.Select(v => v.Pose), plan.Normalisation, Vector3d.Zero, 0, null).Select(p => p.Range),
                Does.Contain(LoaderRangeCheck.Range.Near), "measured from the target, these cameras break NeRF's near 2");
            var plain = warnings.Single(w => w.Field == "splits.train.source");
            Assert.That(plain.Reason, Does.Contain("between 2 and 6 units"));
            Assert.That(plain.Fix, Does.StartWith("Train with the other exports: nerfstudio"));
            Assert.That(warnings.Where(w => w.Reason.Contains("NeRF's fixed")), Is.Empty);
            s.Loaders = TargetLoaders.All & ~TargetLoaders.Nerf;
            Assert.That(CapturePlan.Build(s, PlanTarget.AtOrigin).Warnings.Where(w => w.Field == "splits.train.source"), Is.Empty);
        }

        [Test]
        public void ABoxFullOfObstaclesStopsThePlanWithTheCounts()
        {
            var block = OrientedBox.AxisAligned("Block", new Vector3d(0, 1, 0), new Vector3d(11, 3, 11));
            var problems = CapturePlan.Check(WithVolume(block), PlanTarget.AtOrigin);
            var train = problems.Single(p => p.Field == "splits.train.source.box");
            Assert.That(train.Reason, Is.EqualTo("has room for only 0 of the 60 cameras: 3000 of 3000 positions drawn were inside an obstacle or nearer than the clearance (0.25) to one (Block 3000)."));
        }

        [Test]
        public void SameSettingsSamePlanAndTheSplitsDrawIndependently()
        {
            var a = CapturePlan.Build(WithVolume(Wall), PlanTarget.AtOrigin);
            var b = CapturePlan.Build(WithVolume(Wall), PlanTarget.AtOrigin);
            Assert.That(b.Views.Select(v => v.Pose), Is.EqualTo(a.Views.Select(v => v.Pose)));
            var other = WithVolume(Wall);
            other.Seed = 18;
            Assert.That(CapturePlan.Build(other, PlanTarget.AtOrigin).Views[0].Pose, Is.Not.EqualTo(a.Views[0].Pose));
            Assert.That(a.ViewsOf(DatasetSplit.Test).First().Pose.Position, Is.Not.EqualTo(a.ViewsOf(DatasetSplit.Train).First().Pose.Position));
        }

        [Test]
        public void DensityTimesTheBoxVolumeIsTheCount()
        {
            var s = WithVolume();
            s.Train.Source.Density = 0.25; // 10 × 2 × 10 = 200 cubic units → 50 cameras
            s.Test.Source.Density = 0.101; // 20.2 → 21, rounded up
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            Assert.That(plan.ViewsOf(DatasetSplit.Train).Count(), Is.EqualTo(50));
            Assert.That(plan.ViewsOf(DatasetSplit.Test).Count(), Is.EqualTo(21));
            s.Train.Source.Density = 1000;
            Assert.That(CapturePlan.Check(s, PlanTarget.AtOrigin).Single().Field, Is.EqualTo("splits.train.source.density"));
        }

        [Test]
        public void NoTargetDistanceChecksApplyWhenEverySplitIsAVolume()
        {
            // A target whose bounds would hold every camera of a formation at distance 1.
            var s = WithVolume();
            s.Val.Source = new CameraSourceSettings { Kind = CameraSourceKind.Volume, ObjectPath = "CaptureVolume", Volume = new VolumeScene(Room, null) };
            s.Distance = 1;
            Assert.That(CapturePlan.Check(s, new PlanTarget(Vector3d.Zero, 50)), Is.Empty);
        }

        [Test]
        public void TheHeadlessToolRefusesAVolumeByName()
        {
            var s = WithVolume();
            s.Train.Source.Volume = null;
            var problem = CapturePlan.Check(s, PlanTarget.AtOrigin).Single();
            Assert.That(problem.Field, Is.EqualTo("splits.train.source.kind"));
            Assert.That(problem.Reason, Does.Contain("only the Unity editor can read"));
        }

        [Test]
        public void SettingsProblemsNameTheirField()
        {
            var s = new CameraSourceSettings { Kind = CameraSourceKind.Volume, ObjectPath = " ", Density = -1, JitterDegrees = 200, Clearance = double.NaN };
            Assert.That(s.Validate("splits.test.source").Select(p => p.Field), Is.EqualTo(new[]
            {
                "splits.test.source.box", "splits.test.source.density", "splits.test.source.jitterDegrees", "splits.test.source.clearance",
            }));
        }

        [Test]
        public void MovingTheBoxOrAnObstacleChangesThePreviewKey()
        {
            var a = WithVolume(Wall);
            var moved = WithVolume(OrientedBox.AxisAligned("Walls/Middle", new Vector3d(0.001, 1, 0), new Vector3d(1, 4, 12)));
            Assert.That(PreviewPlanKey.Of(a, PlanTarget.AtOrigin), Is.Not.EqualTo(PreviewPlanKey.Of(moved, PlanTarget.AtOrigin)));
            Assert.That(PreviewPlanKey.Of(a, PlanTarget.AtOrigin), Is.EqualTo(PreviewPlanKey.Of(WithVolume(Wall), PlanTarget.AtOrigin)));
        }

        [Test]
        public void AVolumeRoundTripsThroughTheConfigFile()
        {
            var s = WithVolume(Wall);
            s.Test.Source.Look = VolumeLook.Forward;
            s.Test.Source.JitterDegrees = 12.5;
            s.Test.Source.Density = 0.5;
            s.Test.Source.Clearance = 0.4;
            var text = DatasetSettingsJson.Write(s);
            Assert.That(JObject.Parse(text)["splits"]["test"]["source"].ToString(Newtonsoft.Json.Formatting.None),
                Is.EqualTo("{\"kind\":\"volume\",\"box\":\"CaptureVolume\",\"look\":\"forward\",\"density\":0.5,\"jitterDegrees\":12.5,\"clearance\":0.4}"));
            Assert.That(text, Does.Not.Contain("Walls/Middle"), "what the editor read from the scene is not saved");
            var read = DatasetSettingsJson.Read(text).Settings.Test.Source;
            Assert.That(new object[] { read.Kind, read.ObjectPath, read.Look, read.Density, read.JitterDegrees, read.Clearance, read.Volume },
                Is.EqualTo(new object[] { CameraSourceKind.Volume, "CaptureVolume", VolumeLook.Forward, 0.5, 12.5, 0.4, null }));
            var bad = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{\"splits\": {\"test\": {\"source\": {\"kind\": \"volume\", \"look\": \"up\"}}}}"));
            Assert.That(bad.Message, Does.Contain("\"ring\", \"sphere\", \"forward\" or \"path\""));
        }

        // A path through the room at Unity height 1: along x from −4 to 4, waypoints unevenly spaced.
        static readonly Vector3d[] Waypoints = { new Vector3d(-4, 1, 0), new Vector3d(-3, 1, 0), new Vector3d(1, 1, 0), new Vector3d(4, 1, 0) };

        static DatasetSettings WithPath(Vector3d[] waypoints, params OrientedBox[] obstacles)
        {
            var s = WithVolume();
            s.Train.Count = 9;
            s.Train.Source = new CameraSourceSettings
            {
                Kind = CameraSourceKind.Volume, ObjectPath = "CaptureVolume", Look = VolumeLook.Path, PathObject = "Flythrough", JitterDegrees = 0,
                Volume = new VolumeScene(Room, obstacles, waypoints),
            };
            return s;
        }

        [Test]
        public void APathSplitsCamerasGoEvenlyAlongTheWaypointsLookingForward()
        {
            var plan = CapturePlan.Build(WithPath(Waypoints), PlanTarget.AtOrigin);
            var train = plan.ViewsOf(DatasetSplit.Train).ToList();
            Assert.That(train.Select(v => v.Pose.Position.X), Is.EqualTo(new[] { -4.0, -3, -2, -1, 0, 1, 2, 3, 4 }).Within(1e-9));
            foreach (var v in train)
            {
                // Output camera looks along −Z of its matrix: Unity +X is output +X.
                Assert.That(new[] { -v.TransformMatrix[0, 2], -v.TransformMatrix[1, 2], -v.TransformMatrix[2, 2] }, Is.EqualTo(new[] { 1.0, 0, 0 }).Within(1e-9));
                Assert.That(v.TransformMatrix.Translation, Is.EqualTo(new Vector3d(v.Pose.Position.X, 0, 1)).Within(1e-9));
            }
            Assert.That(plan.Warnings.Where(w => w.Field.StartsWith("splits.train.source.")), Is.Empty, "no obstacle on this path");
        }

        [Test]
        public void APathThroughAnObstacleKeepsItsCamerasAndSaysWhere()
        {
            var crate = OrientedBox.AxisAligned("Props/Crate", new Vector3d(0, 1, 0), new Vector3d(1, 1, 1));
            var plan = CapturePlan.Build(WithPath(Waypoints, crate), PlanTarget.AtOrigin);
            Assert.That(plan.ViewsOf(DatasetSplit.Train).Count(), Is.EqualTo(9));
            // Crate ±0.5 grown by the clearance 0.25: x = 0 only (±1 are outside ±0.75).
            var warning = plan.Warnings.Single(w => w.Field == "splits.train.source.waypoints");
            Assert.That(warning.Reason, Does.Contain("puts 1 of 9 cameras").And.Contain("Props/Crate 1"));
        }

        [Test]
        public void APathNeedsItsWaypointsAndUsesTheCount()
        {
            Assert.That(CapturePlan.Check(WithPath(new[] { Waypoints[0] }), PlanTarget.AtOrigin).Select(p => p.Field), Has.Member("splits.train.source.waypoints"));
            var s = WithPath(Waypoints);
            s.Train.Source.Density = 2;
            Assert.That(CapturePlan.Check(s, PlanTarget.AtOrigin).Select(p => p.Field), Has.Member("splits.train.source.density"));
            s.Train.Source.Density = 0;
            s.Train.Source.PathObject = " ";
            Assert.That(CapturePlan.Check(s, PlanTarget.AtOrigin).Select(p => p.Field), Has.Member("splits.train.source.waypoints"));
        }

        [Test]
        public void APathRoundTripsThroughTheConfigFile()
        {
            var text = DatasetSettingsJson.Write(WithPath(Waypoints));
            Assert.That(JObject.Parse(text)["splits"]["train"]["source"].ToString(Newtonsoft.Json.Formatting.None),
                Is.EqualTo("{\"kind\":\"volume\",\"box\":\"CaptureVolume\",\"look\":\"path\",\"density\":0.0,\"jitterDegrees\":0.0,\"clearance\":0.25,\"waypoints\":\"Flythrough\"}"));
            var read = DatasetSettingsJson.Read(text).Settings.Train.Source;
            Assert.That(new object[] { read.Look, read.PathObject }, Is.EqualTo(new object[] { VolumeLook.Path, "Flythrough" }));
        }
    }
}
