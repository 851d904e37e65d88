using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The window's Motion blur section: the popup follows the enum, and every problem lands under a drawn field.</summary>
    [TestFixture]
    public class MotionBlurChoicesTests
    {
        [Test]
        public void EachCameraLabelStartsWithItsConfigName()
        {
            var motions = (ShutterCameraMotion[])Enum.GetValues(typeof(ShutterCameraMotion));
            Assert.That(MotionBlurChoices.CameraLabels, Has.Length.EqualTo(motions.Length));
            Assert.That(MotionBlurChoices.CameraTooltips, Has.Length.EqualTo(motions.Length));
            foreach (var motion in motions)
                Assert.That(MotionBlurChoices.CameraLabels[(int)motion].ToLowerInvariant(), Does.StartWith(MotionBlurSettings.CameraName(motion) + " "));
        }

        [Test]
        public void ShakeFieldsAreDrawnForAShakeOnly()
        {
            var blur = new MotionBlurSettings();
            Assert.That(MotionBlurChoices.Shown(blur), Is.Empty, "off: only the toggle");
            blur.Enabled = true;
            Assert.That(MotionBlurChoices.Shown(blur), Is.EqualTo(new[] { "motionBlur.camera", "motionBlur.shutter", "motionBlur.subFrames", "motionBlur.readout" }));
            blur.Camera = ShutterCameraMotion.Shake;
            Assert.That(MotionBlurChoices.Shown(blur), Has.Member("motionBlur.shakeDistance").And.Member("motionBlur.shakeDegrees"));
        }

        [Test]
        public void EveryProblemOfBrokenBlurIsUnderADrawnField()
        {
            var settings = new DatasetSettings();
            var m = settings.MotionBlur;
            m.Enabled = true;
            m.Camera = ShutterCameraMotion.Shake;
            m.Shutter = 0;
            m.SubFrames = 1;
            m.Readout = 0.99;
            m.ShakeDistance = -1;
            m.ShakeDegrees = 90;
            var problems = MotionBlurSettingsValidator.Validate(settings);
            Assert.That(problems, Has.Count.EqualTo(5));
            var shown = MotionBlurChoices.Shown(m);
            Assert.That(problems.Where(p => !shown.Any(f => WindowFields.Covers(f, p.Field))), Is.Empty);
        }
    }
}
