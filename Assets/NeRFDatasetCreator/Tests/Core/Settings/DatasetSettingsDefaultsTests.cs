using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class DatasetSettingsDefaultsTests
    {
        [Test]
        public void DefaultsMirrorNerfSynthetic()
        {
            var s = new DatasetSettings();
            Assert.That(s.Width, Is.EqualTo(800));
            Assert.That(s.Height, Is.EqualTo(800));
            Assert.That(s.Train.Count, Is.EqualTo(100));
            Assert.That(s.Val.Count, Is.EqualTo(100));
            Assert.That(s.Test.Count, Is.EqualTo(200));
            Assert.That(s.Distance, Is.EqualTo(4.0));
            Assert.That(s.AutoDistance, Is.False);
            Assert.That(s.Supersampling, Is.EqualTo(1));
            Assert.That(s.Background.Transparent, Is.True);
            Assert.That(s.Overwrite, Is.EqualTo(OverwritePolicy.Never));
            Assert.That(s.Loaders, Is.EqualTo(TargetLoaders.All));
        }

        [Test]
        public void DefaultFormationsAreUpperHemisphereForTrainAndValAndAnOrbitForTest()
        {
            var s = new DatasetSettings();
            Assert.That(s.Train.Formation.Kind, Is.EqualTo(FormationKind.SemiSphere));
            Assert.That(s.Train.Formation.TopElevationDegrees, Is.EqualTo(90.0));
            Assert.That(s.Train.Formation.BottomElevationDegrees, Is.EqualTo(0.0));
            Assert.That(s.Train.Formation.SpiralRatio, Is.EqualTo(0.0), "0 = golden ratio");
            Assert.That(s.Val.Formation.Kind, Is.EqualTo(FormationKind.Random));
            Assert.That(s.Val.Formation.UpperHemisphereOnly, Is.True);
            Assert.That(s.Test.Formation.Kind, Is.EqualTo(FormationKind.Orbit));
        }

        [Test]
        public void DefaultFieldOfViewGivesLegoCameraAngleX()
        {
            // nerf_synthetic lego: "camera_angle_x": 0.6911112070083618 (≈ 2·atan(36/100), a 50 mm lens on 36 mm film).
            var intrinsics = new DatasetSettings().Intrinsics();
            Assert.That(intrinsics.CameraAngleX, Is.EqualTo(0.6911112070083618).Within(1e-15));
            Assert.That(intrinsics.CameraAngleX, Is.EqualTo(2 * Math.Atan(0.36)).Within(1e-7));
            // NeRF's focal: 0.5·W / tan(0.5·camera_angle_x) = 400 / 0.36 (to float precision).
            Assert.That(intrinsics.FlX, Is.EqualTo(400 / 0.36).Within(1e-3));
        }

        [Test]
        public void DefaultsAreValid()
        {
            Assert.That(SettingsValidator.Validate(new DatasetSettings()), Is.Empty);
        }

        [Test]
        public void CloneIsDeep()
        {
            var s = new DatasetSettings();
            var copy = s.Clone();
            copy.Train.Formation.Turns = 7;
            copy.Camera.NearClip = 2;
            copy.Background.R = 0;
            Assert.That(s.Train.Formation.Turns, Is.EqualTo(2.0));
            Assert.That(s.Camera.NearClip, Is.EqualTo(0.1));
            Assert.That(s.Background.R, Is.EqualTo(1.0));
        }

        [TestCase("transparent", true, 1.0, 1.0, 1.0)]
        [TestCase("#ff8000", false, 1.0, 128 / 255.0, 0.0)]
        [TestCase("#000000", false, 0.0, 0.0, 0.0)]
        public void BackgroundParses(string text, bool transparent, double r, double g, double b)
        {
            var bg = BackgroundSettings.Parse(text);
            Assert.That(bg.Transparent, Is.EqualTo(transparent));
            Assert.That(bg.Sky, Is.False);
            Assert.That(bg.R, Is.EqualTo(r).Within(1e-12));
            Assert.That(bg.G, Is.EqualTo(g).Within(1e-12));
            Assert.That(bg.B, Is.EqualTo(b).Within(1e-12));
            Assert.That(bg.ToConfigString(), Is.EqualTo(text));
        }

        [Test]
        public void SkyIsAnOpaqueBackgroundOfItsOwn()
        {
            var bg = BackgroundSettings.Parse("Sky");
            Assert.That(new[] { bg.Sky, bg.Transparent }, Is.EqualTo(new[] { true, false }));
            Assert.That(bg.ToConfigString(), Is.EqualTo("sky"));
            Assert.That(bg.Clone().Sky, Is.True);
        }

        [TestCase("white")]
        [TestCase("#fff")]
        [TestCase("#gg0000")]
        [TestCase("")]
        public void BadBackgroundIsRejected(string text)
        {
            Assert.That(BackgroundSettings.Parse(text), Is.Null);
        }

        [Test]
        public void AutoDistanceFitsTheBoundingSphereInTheNarrowerFieldOfView()
        {
            // 90° vertical FOV, 2:1 image: the vertical angle (90°) is the narrower one. With margin 1 the sphere is
            // tangent to the top and bottom frustum planes: R·sin(45°) = b.
            var tangent = AutoDistanceRule.Distance(1.0, 90, 200, 100, 1.0);
            Assert.That(tangent, Is.EqualTo(Math.Sqrt(2)).Within(1e-12));
            var withMargin = AutoDistanceRule.Distance(0.5, 90, 200, 100, 1.2);
            Assert.That(withMargin, Is.EqualTo(1.2 * 0.5 * Math.Sqrt(2)).Within(1e-12));
            // Portrait 1:2: the horizontal angle is narrower, 2·atan(tan 45° · 1/2).
            var portrait = AutoDistanceRule.Distance(1.0, 90, 100, 200, 1.0);
            Assert.That(portrait, Is.EqualTo(1 / Math.Sin(Math.Atan(0.5))).Within(1e-12));
        }

        [Test]
        public void AutoDistanceRefusesUnknownBounds()
        {
            Assert.Throws<InvalidParameterException>(() => AutoDistanceRule.Distance(0, 40, 800, 800, 1.2));
        }
    }
}
