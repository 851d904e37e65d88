using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class BlurLengthWarningTests
    {
        [Test]
        public void ASidewaysSlideOfTheCameraBlursByFocalTimesDistanceOverDepth()
        {
            // A camera 4 units in front of the target slides 0.4 units sideways over the shutter: every point at depth 4
            // moves f·0.4/4 = 0.1·f pixels (by hand; f = 1111.1 px at nerf_synthetic's 800×800 field of view).
            var settings = new DatasetSettings();
            settings.MotionBlur.Enabled = true;
            var k = settings.Intrinsics();
            var pose = LookAt.FromPositions(new Vector3d(0, 0, -4), Vector3d.Zero);
            var motion = ShutterMotion.Centred(pose, new Vector3d(0.4, 0, 0), Vector3d.Zero, SceneNormalisation.Identity, null, null);
            var view = new PlannedView(DatasetSplit.Train, 3, pose, SceneNormalisation.Identity.CameraToWorld(pose), new[] { DatasetFileKind.Color }, null, motion);
            var target = new PlanTarget(Vector3d.Zero, 1, 0);
            Assert.That(BlurLengthWarning.Length(view, target, k), Is.EqualTo(0.1 * k.FlX).Within(1e-9));

            settings.MotionBlur.SubFrames = 16;
            var warning = BlurLengthWarning.For(settings, target, k, new[] { view }).Single();
            Assert.That(warning.Field, Is.EqualTo("motionBlur.subFrames"));
            Assert.That(warning.Reason, Does.Contain("./train/r_3"));
            Assert.That(warning.Fix, Does.Contain("to " + (int)System.Math.Ceiling(0.1 * k.FlX)));
            settings.MotionBlur.SubFrames = 128;
            Assert.That(BlurLengthWarning.For(settings, target, k, new[] { view }), Is.Empty);
        }

        /// <summary>
        /// A blur longer than 256 px (the most sub-frames there are) gets advice that can be followed (issue 33: "Raise
        /// subFrames to 722"): a shutter short enough for 256 sub-frames, and for a random formation a neighbour formation.
        /// </summary>
        [TestCase(FormationKind.Random, true)]
        [TestCase(FormationKind.Orbit, false)]
        public void ABlurLongerThanTheMostSubFramesAsksForAShorterShutterAndNamesTheSplit(FormationKind kind, bool random)
        {
            var settings = new DatasetSettings();
            settings.MotionBlur.Enabled = true;
            settings.Val.Formation.Kind = kind;
            var k = settings.Intrinsics();
            var pose = LookAt.FromPositions(new Vector3d(0, 0, -4), Vector3d.Zero);
            // A slide of 1.6 units at depth 4: 0.4·f = 444.4 px (f = 1111.1 px), over the 256 sub-frames there can be.
            var motion = ShutterMotion.Centred(pose, new Vector3d(1.6, 0, 0), Vector3d.Zero, SceneNormalisation.Identity, null, null);
            var views = Enumerable.Range(0, 3).Select(i => new PlannedView(DatasetSplit.Val, i, pose, SceneNormalisation.Identity.CameraToWorld(pose), new[] { DatasetFileKind.Color }, null, motion)).ToList();
            var target = new PlanTarget(Vector3d.Zero, 1, 0);
            Assert.That(BlurLengthWarning.Length(views[0], target, k), Is.EqualTo(0.4 * k.FlX).Within(1e-9));

            var warning = BlurLengthWarning.For(settings, target, k, views).Single();
            Assert.That(warning.Reason, Does.StartWith("is fewer than the blur's length in pixels in 3 of 3 val views (longest 444.4 px, ./val/r_0)"));
            Assert.That(warning.Fix, Does.Not.Contain("Raise motionBlur.subFrames"));
            // Shutter 0.5 × 256 / 444.4 = 0.288 (by hand), rounded down so that the advice is enough.
            Assert.That(warning.Fix, Does.Contain("set motionBlur.shutter to 0.288 or less with subFrames 256"));
            Assert.That(warning.Fix.Contains("Give splits.val a formation whose views are neighbours"), Is.EqualTo(random));
        }

        [Test]
        public void AShakeLongerThanTheMostSubFramesAsksForAShorterShake()
        {
            var settings = new DatasetSettings();
            settings.MotionBlur.Enabled = true;
            settings.MotionBlur.Camera = ShutterCameraMotion.Shake;
            settings.MotionBlur.ShakeDistance = 2;
            settings.MotionBlur.ShakeDegrees = 4;
            var k = settings.Intrinsics();
            var pose = LookAt.FromPositions(new Vector3d(0, 0, -4), Vector3d.Zero);
            var motion = ShutterMotion.Centred(pose, new Vector3d(1.6, 0, 0), Vector3d.Zero, SceneNormalisation.Identity, null, null);
            var view = new PlannedView(DatasetSplit.Train, 0, pose, SceneNormalisation.Identity.CameraToWorld(pose), new[] { DatasetFileKind.Color }, null, motion);
            var warning = BlurLengthWarning.For(settings, new PlanTarget(Vector3d.Zero, 1, 0), k, new[] { view }).Single();
            // 256 / 444.4 = 0.576: shakeDistance 2 → 1.152, shakeDegrees 4 → 2.304 (by hand, rounded down).
            Assert.That(warning.Fix, Does.Contain("shorten the shake to 0.576 × its length (motionBlur.shakeDistance 1.152, shakeDegrees 2.304 or less)"));
        }
    }
}
