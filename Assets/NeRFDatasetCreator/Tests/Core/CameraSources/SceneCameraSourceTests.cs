using System;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class SceneCameraSourceTests
    {
        // Quaternion of a 90° turn about Unity's +Y: the camera then looks along Unity +X.
        static readonly Quaterniond TurnRight = new Quaterniond(0, Math.Sqrt(0.5), 0, Math.Sqrt(0.5));

        static DatasetSettings WithShots(params SceneCamera[] cameras)
        {
            var s = new DatasetSettings { Normalisation = NormalisationMode.None, Width = 200, Height = 100 };
            s.Train.Count = 4;
            s.Val.Count = 1;
            s.Test.Source = new CameraSourceSettings { Kind = CameraSourceKind.SceneCameras, ObjectPath = "Set/Shots", SceneCameras = cameras };
            s.Camera.VerticalFovDegrees = 30;
            return s;
        }

        static SceneCamera Shot(string name, double x, double y, double z, double fov, Quaterniond? rotation = null) =>
            new SceneCamera(name, new UnityPose(new Vector3d(x, y, z), rotation ?? Quaterniond.Identity), fov);

        [Test]
        public void EachSceneCameraIsOneViewWrittenThroughTheOutputConvention()
        {
            var plan = CapturePlan.Build(WithShots(Shot("Set/Shots/A", 1, 2, 3, 40), Shot("Set/Shots/B", -4, 0.5, 0, 40, TurnRight)), PlanTarget.AtOrigin);
            var test = plan.ViewsOf(DatasetSplit.Test).ToList();
            Assert.That(test, Has.Count.EqualTo(2), "one view per camera, whatever the split's count");
            Assert.That(plan.ViewsOf(DatasetSplit.Train).Count(), Is.EqualTo(4));
            // A: Unity (1, 2, 3) → Blender (1, 3, 2); looking along Unity +Z = Blender +Y, so the −Z column is +Y.
            Assert.That(test[0].TransformMatrix.ToRows(), Is.EqualTo(new[]
            {
                new double[] { 1, 0, 0, 1 },
                new double[] { 0, 0, -1, 3 },
                new double[] { 0, 1, 0, 2 },
                new double[] { 0, 0, 0, 1 },
            }));
            // B looks along Unity +X = Blender +X: its back (+Z column) is −X, its right is Unity −Z = Blender −Y.
            var b = test[1].TransformMatrix;
            Assert.That(new[] { b[0, 2], b[1, 2], b[2, 2] }, Is.EqualTo(new[] { -1.0, 0, 0 }).Within(1e-12));
            Assert.That(new[] { b[0, 0], b[1, 0], b[2, 0] }, Is.EqualTo(new[] { 0.0, -1, 0 }).Within(1e-12));
            Assert.That(b.Translation, Is.EqualTo(new Vector3d(-4, 0, 0.5)));
            Assert.That(test[1].Pose.Position, Is.EqualTo(new Vector3d(-4, 0.5, 0)), "the Unity camera goes where the scene camera is");
            // Their own field of view (useCameraIntrinsics defaults to true): 40° vertical at 200 × 100.
            Assert.That(plan.Intrinsics.CameraAngleX, Is.EqualTo(2 * Math.Atan(Math.Tan(20 * Math.PI / 180) * 2)).Within(1e-12));
            Assert.That(plan.Settings.Camera.VerticalFovDegrees, Is.EqualTo(40).Within(1e-9));
            Assert.That(plan.RotationOf(DatasetSplit.Test), Is.EqualTo(0.0));
        }

        [Test]
        public void TheEditorsNotesOnASceneSourceAreWarningsUnderTheirOwnField()
        {
            var s = WithShots(Shot("A", 1, 2, 3, 30));
            s.Test.Source.Kind = CameraSourceKind.AnimatedCamera;
            s.Test.Source.SceneWarnings = new[] { new ValidationProblem("splits.test.source.camera", "CM Close", "has damping.", "Set it to 0.") };
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            var note = plan.Warnings.Single(w => w.Reason == "has damping.");
            Assert.That(note.Field, Is.EqualTo("splits.test.source.camera"), "not wrapped as a problem inside a file");
            Assert.That(note.Value, Is.EqualTo("CM Close"));
        }

        [Test]
        public void TheDatasetsNormalisationAppliesToSceneCamerasAsToAFormation()
        {
            var s = WithShots(Shot("A", 1, 2, 3, 40));
            s.Normalisation = NormalisationMode.Recentre;
            var plan = CapturePlan.Build(s, new PlanTarget(new Vector3d(1, 1, 1), 0));
            // Recentred on the target (Unity (1, 1, 1) = Blender (1, 1, 1)): Blender (1, 3, 2) − (1, 1, 1).
            Assert.That(plan.ViewsOf(DatasetSplit.Test).Single().TransformMatrix.Translation, Is.EqualTo(new Vector3d(0, 2, 1)));
        }

        [Test]
        public void DifferentFieldsOfViewInASplitAreRefusedWhenTheCamerasIntrinsicsAreUsed()
        {
            var s = WithShots(Shot("Set/Shots/A", 0, 0, -5, 40), Shot("Set/Shots/B", 0, 0, -6, 55));
            var problem = CapturePlan.Check(s, PlanTarget.AtOrigin).Single();
            Assert.That(problem.Field, Is.EqualTo("splits.test.source.useCameraIntrinsics"));
            Assert.That(problem.Reason, Does.Contain("Set/Shots/A").And.Contain("Set/Shots/B").And.Contain("one camera_angle_x per split"));
            s.Test.Source.UseCameraIntrinsics = false;
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            Assert.That(plan.Settings.Camera.VerticalFovDegrees, Is.EqualTo(30), "the Camera step's");
            Assert.That(plan.Warnings.Single(w => w.Field == "splits.test.source").Reason, Does.Contain("different intrinsics"));
        }

        [Test]
        public void AnotherFieldOfViewWithoutTheCamerasIntrinsicsIsAWarning()
        {
            var s = WithShots(Shot("A", 0, 0, -5, 40));
            s.Test.Source.UseCameraIntrinsics = false;
            var warning = CapturePlan.Build(s, PlanTarget.AtOrigin).Warnings.Single(w => w.Field == "splits.test.source");
            Assert.That(warning.Reason, Does.Contain("same poses, other pictures"));
            Assert.That(warning.Fix, Does.Contain("useCameraIntrinsics"));
        }

        [Test]
        public void WithoutTheSceneTheSourceIsRefusedByName()
        {
            var s = WithShots();
            s.Test.Source.SceneCameras = null; // as in nerf-dataset plan
            var problem = CapturePlan.Check(s, PlanTarget.AtOrigin).Single();
            Assert.That(problem.Field, Is.EqualTo("splits.test.source.kind"));
            Assert.That(problem.Reason, Does.Contain("only the Unity editor"));
            s.Test.Source.SceneCameras = new SceneCamera[0];
            Assert.That(CapturePlan.Check(s, PlanTarget.AtOrigin).Single().Field, Is.EqualTo("splits.test.source.parent"));
            s.Test.Source.ObjectPath = " ";
            Assert.That(CapturePlan.Check(s, PlanTarget.AtOrigin).Single().Reason, Does.Contain("is empty"));
        }

        [Test]
        public void SceneAndAnimatedSourcesRoundTripThroughTheConfigFile()
        {
            var s = WithShots(Shot("A", 0, 0, -5, 40));
            s.Test.Source.UseCameraIntrinsics = false;
            s.Val.Source = new CameraSourceSettings
            {
                Kind = CameraSourceKind.AnimatedCamera, ObjectPath = "Flythrough/Camera", Samples = 30, FrameStep = 5, FrameRate = 24, Start = 0.5, End = 7.25,
            };
            var text = DatasetSettingsJson.Write(s);
            var json = JObject.Parse(text);
            Assert.That(json["splits"]["test"]["source"].ToString(Newtonsoft.Json.Formatting.None),
                Is.EqualTo("{\"kind\":\"sceneCameras\",\"parent\":\"Set/Shots\",\"useCameraIntrinsics\":false}"));
            Assert.That(text, Does.Not.Contain("Set/Shots/A"), "what the editor read from the scene is not saved");
            var read = DatasetSettingsJson.Read(text).Settings;
            Assert.That(new object[] { read.Test.Source.Kind, read.Test.Source.ObjectPath, read.Test.Source.UseCameraIntrinsics, read.Test.Source.SceneCameras },
                Is.EqualTo(new object[] { CameraSourceKind.SceneCameras, "Set/Shots", false, null }));
            var v = read.Val.Source;
            Assert.That(new object[] { v.Kind, v.ObjectPath, v.UseCameraIntrinsics, v.Samples, v.FrameStep, v.FrameRate, v.Start, v.End },
                Is.EqualTo(new object[] { CameraSourceKind.AnimatedCamera, "Flythrough/Camera", true, 30, 5, 24.0, 0.5, 7.25 }));
            var bad = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{\"splits\": {\"test\": {\"source\": {\"kind\": \"spline\"}}}}"));
            Assert.That(bad.Message, Does.Contain("\"animatedCamera\" or \"volume\""));
        }

        [Test]
        public void MovingASceneCameraChangesThePreviewKey()
        {
            var a = WithShots(Shot("A", 0, 0, -5, 40));
            var b = WithShots(Shot("A", 0, 0, -5.001, 40));
            Assert.That(PreviewPlanKey.Of(a, PlanTarget.AtOrigin), Is.Not.EqualTo(PreviewPlanKey.Of(b, PlanTarget.AtOrigin)));
            Assert.That(PreviewPlanKey.Of(a, PlanTarget.AtOrigin), Is.EqualTo(PreviewPlanKey.Of(WithShots(Shot("A", 0, 0, -5, 40)), PlanTarget.AtOrigin)));
        }
    }
}
