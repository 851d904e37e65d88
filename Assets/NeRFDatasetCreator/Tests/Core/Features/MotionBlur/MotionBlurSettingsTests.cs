using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class MotionBlurSettingsTests
    {
        static DatasetSettings Blurred()
        {
            var s = new DatasetSettings();
            s.MotionBlur.Enabled = true;
            return s;
        }

        [Test]
        public void TheSectionRoundTripsAndIsAbsentWhenOff()
        {
            Assert.That(DatasetSettingsJson.Write(new DatasetSettings()), Does.Not.Contain("motionBlur"));
            var s = Blurred();
            s.MotionBlur.Camera = ShutterCameraMotion.Shake;
            s.MotionBlur.Shutter = 0.25;
            s.MotionBlur.SubFrames = 24;
            s.MotionBlur.ShakeDistance = 0.01;
            s.MotionBlur.ShakeDegrees = 0.5;
            s.MotionBlur.Readout = 0.3;
            var back = DatasetSettingsJson.Read(DatasetSettingsJson.Write(s)).Settings.MotionBlur;
            Assert.That(back.Enabled, Is.True);
            Assert.That(back.Camera, Is.EqualTo(ShutterCameraMotion.Shake));
            Assert.That(new[] { back.Shutter, back.ShakeDistance, back.ShakeDegrees, back.Readout }, Is.EqualTo(new[] { 0.25, 0.01, 0.5, 0.3 }));
            Assert.That(back.SubFrames, Is.EqualTo(24));
            var defaults = DatasetSettingsJson.Read("{ \"motionBlur\": {} }").Settings.MotionBlur;
            Assert.That(defaults.Enabled && defaults.Camera == ShutterCameraMotion.Path && defaults.Shutter == 0.5 && defaults.SubFrames == 16, Is.True, "a section asks for blur, with the defaults");
        }

        [Test]
        public void AWrongCameraNameIsAnErrorNamingTheKey()
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"motionBlur\": { \"camera\": \"shaky\" } }"));
            Assert.That(e.Message, Does.Contain("motionBlur.camera"));
        }

        static string[] Fields(DatasetSettings s) => SettingsValidator.Validate(s).Select(p => p.Field).ToArray();

        [Test]
        public void OutOfRangeValuesNameTheirKeys()
        {
            var s = Blurred();
            s.MotionBlur.Shutter = 0;
            s.MotionBlur.SubFrames = 1;
            s.MotionBlur.Readout = 1;
            Assert.That(Fields(s), Is.SupersetOf(new[] { "motionBlur.shutter", "motionBlur.subFrames", "motionBlur.readout" }));
            s = Blurred();
            s.MotionBlur.Camera = ShutterCameraMotion.Shake;
            Assert.That(Fields(s), Does.Contain("motionBlur.shakeDistance"), "a shake of nothing in a static capture");
            s.MotionBlur.ShakeDegrees = 90;
            Assert.That(Fields(s), Does.Contain("motionBlur.shakeDegrees"));
            s = Blurred();
            s.MotionBlur.Camera = ShutterCameraMotion.Still;
            Assert.That(Fields(s), Does.Contain("motionBlur.camera"), "nothing moves");
            Assert.That(Fields(Blurred()), Is.Empty, "the defaults are valid");
        }

        [Test]
        public void MultiViewRigsCannotMoveAlongTheirPathAndTheShutterMayNotOpenBeforeContentTimeZero()
        {
            var s = Blurred();
            s.Time.Mode = TimeMode.MultiView;
            s.Time.Steps = 11; // 0.1 s apart over 0 … 1 s
            Assert.That(Fields(s), Does.Contain("motionBlur.camera"));
            s.MotionBlur.Camera = ShutterCameraMotion.Still;
            Assert.That(Fields(s), Is.Empty);
            var problems = CapturePlan.Check(s, PlanTarget.Headless);
            var start = problems.Single(p => p.Field == "time.start");
            Assert.That(start.Fix, Does.Contain("0.025"), "half of 0.5 × 0.1 s");
            s.Time.StartSeconds = 0.025;
            s.Time.EndSeconds = 1.025;
            Assert.That(CapturePlan.Check(s, PlanTarget.Headless), Is.Empty);
        }

        [Test]
        public void InADynamicCaptureTheContentMovesOverTheShutterAndTheSubFramesAtTheirOwnTimes()
        {
            // Monocular, 11 train views over 0.5 … 1.5 s: time step 0.1 s; shutter 0.5 opens 0.025 s before each view's
            // time and closes 0.025 s after; sub-frame k of 4 is at open + (k + ½)/4 × 0.05 s.
            var s = Blurred();
            s.Train.Count = 11;
            s.Time.Mode = TimeMode.Monocular;
            s.Time.StartSeconds = 0.5;
            s.Time.EndSeconds = 1.5;
            var plan = CapturePlan.Build(s, PlanTarget.Headless);
            var view = plan.Views.First(v => v.Split == DatasetSplit.Train && v.Index == 4);
            Assert.That(view.Time.Value.Seconds, Is.EqualTo(0.9).Within(1e-12));
            Assert.That(view.Motion.OpenSeconds.Value, Is.EqualTo(0.875).Within(1e-12));
            Assert.That(view.Motion.CloseSeconds.Value, Is.EqualTo(0.925).Within(1e-12));
            var subs = SubFrameSchedule.For(view.Motion, 4);
            Assert.That(subs.Select(f => f.Seconds.Value), Is.EqualTo(new[] { 0.88125, 0.89375, 0.90625, 0.91875 }).Within(1e-12));
            var text = BlenderTransformsWriter.Write(plan, DatasetSplit.Train);
            var frame = Newtonsoft.Json.Linq.JObject.Parse(text)["frames"][4];
            Assert.That((double)frame["shutter_open_seconds"], Is.EqualTo(0.875).Within(1e-12));
            Assert.That((double)frame["shutter_close_seconds"], Is.EqualTo(0.925).Within(1e-12));
        }

        [Test]
        public void APathShutterOnAnOrbitTurnsByTheShutterTimesTheStepAngle()
        {
            // An orbit of N views over 2 turns steps 4π/N about the target; the central difference of a uniform orbit
            // is that step exactly, so the camera turns (and its centre moves along the chord direction) by shutter × step.
            var s = Blurred();
            s.Test.Count = 40;
            s.Test.Formation.LowElevationDegrees = s.Test.Formation.HighElevationDegrees = 30; // one circle, no elevation sweep
            s.MotionBlur.Shutter = 0.5;
            var plan = CapturePlan.Build(s, PlanTarget.Headless);
            var step = 2 * 2 * Math.PI / 40;
            foreach (var view in plan.Views.Where(v => v.Split == DatasetSplit.Test && v.Index > 0 && v.Index < 39))
            {
                // Orbit neighbours differ by a pure yaw of one step about the world's up: the rotation from start to end is half of it.
                var turned = PoseInterpolation.ToRotationVector(view.Motion.End.Rotation * PoseInterpolation.Inverse(view.Motion.Start.Rotation)).Length;
                Assert.That(turned, Is.EqualTo(0.5 * step).Within(1e-9), "view " + view.Index);
                // The centre moves along the chord between its neighbours, 2ρ·sin(step) long for a circle of radius ρ
                // (the horizontal distance from the target, at the origin here), halved by the central difference.
                var p = view.Pose.Position;
                var rho = Math.Sqrt(p.X * p.X + p.Z * p.Z);
                Assert.That(Vector3d.Distance(view.Motion.Start.Position, view.Motion.End.Position), Is.EqualTo(0.5 * rho * Math.Sin(step)).Within(1e-9));
                Assert.That(Vector3d.Distance(view.Motion.At(0.5).Position, p), Is.LessThan(1e-12));
            }
            var train = plan.Views.Where(v => v.Split == DatasetSplit.Train).ToList();
            Assert.That(train.All(v => v.Writes(DatasetFileKind.SharpPng)), Is.True);
        }
    }
}
