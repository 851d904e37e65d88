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
    }
}
