using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The "lens" setting: its config form, its validation under its own keys, and its plan warnings.</summary>
    [TestFixture]
    public class LensSettingsTests
    {
        static DatasetSettings With(LensSettings lens, TargetLoaders loaders = TargetLoaders.All) =>
            new DatasetSettings { Lens = lens, Loaders = loaders };

        static string[] Fields(DatasetSettings settings) => SettingsValidator.Validate(settings).Select(p => p.Field).ToArray();

        [Test]
        public void APinholeConfigHasNoLensKey()
        {
            Assert.That(DatasetSettingsJson.Write(new DatasetSettings()), Does.Not.Contain("\"lens\""));
            Assert.That(new DatasetSettings().Lens.ToDistortion(), Is.Null);
        }

        [Test]
        public void ALensRoundTripsThroughTheConfig()
        {
            var settings = With(new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.03, P1 = 0.001, P2 = -0.0005, K3 = 0.004 });
            var text = DatasetSettingsJson.Write(settings);
            Assert.That(text, Does.Contain("\"lens\": {"));
            var read = DatasetSettingsJson.Read(text);
            Assert.That(read.Warnings, Is.Empty);
            Assert.That(TransformsLens.Same(read.Settings.Lens.ToDistortion(), LensDistortion.OpenCv(-0.12, 0.03, 0.001, -0.0005, 0.004)), Is.True);
            Assert.That(DatasetSettingsJson.Write(read.Settings), Is.EqualTo(text));
        }

        [Test]
        public void ALensComposesWithAGlobalShutterButNotYetWithARollingOne()
        {
            var settings = With(new LensSettings { Model = "opencv", K1 = -0.1 });
            settings.MotionBlur = new MotionBlurSettings { Enabled = true, Camera = ShutterCameraMotion.Shake, ShakeDistance = 0.01 };
            Assert.That(Fields(settings), Does.Not.Contain("lens"));
            settings.MotionBlur.Readout = 0.3;
            var problem = SettingsValidator.Validate(settings).Single(p => p.Field == "lens");
            Assert.That(problem.ToString(), Does.Contain("rolling shutter (motionBlur.readout 0.3)").And.Contain("Set motionBlur.readout to 0"));
        }

        [Test]
        public void AFisheyeIsReadFromItsConfigName()
        {
            var read = DatasetSettingsJson.Read("{ \"lens\": { \"model\": \"OpenCV_Fisheye\", \"k1\": 0.05, \"k4\": -0.001 } }");
            var lens = read.Settings.Lens.ToDistortion();
            Assert.That(lens.Model, Is.EqualTo(LensModel.OpenCvFisheye));
            Assert.That(lens.K1, Is.EqualTo(0.05));
            Assert.That(lens.K4, Is.EqualTo(-0.001));
        }

        [Test]
        public void AnUnknownModelInAConfigNamesTheKey()
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"lens\": { \"model\": \"opencv-fisheye\" } }"));
            Assert.That(e.Message, Does.Contain("lens.model"));
            Assert.That(e.Message, Does.Contain("opencv_fisheye"));
        }

        [Test]
        public void AnUnknownLensKeyIsWarnedAbout()
        {
            var read = DatasetSettingsJson.Read("{ \"lens\": { \"model\": \"opencv\", \"k5\": 0.1 } }");
            Assert.That(read.Warnings.Select(w => w.Field), Is.EqualTo(new[] { "lens.k5" }));
        }

        [Test]
        public void CoefficientsTheModelDoesNotHaveAreRefusedUnderTheirKeys()
        {
            Assert.That(Fields(With(new LensSettings { Model = "opencv", K1 = -0.1, K4 = 0.01 })), Is.EqualTo(new[] { "lens.k4" }));
            Assert.That(Fields(With(new LensSettings { Model = "opencv_fisheye", K1 = 0.01, P1 = 0.001, P2 = 0.002 })), Is.EqualTo(new[] { "lens.p1", "lens.p2" }));
            Assert.That(Fields(With(new LensSettings { Model = "opencv", K1 = double.NaN })), Is.EqualTo(new[] { "lens.k1" }));
        }

        [Test]
        public void CoefficientsWithoutAModelAreRefused()
        {
            var problems = SettingsValidator.Validate(With(new LensSettings { K1 = -0.1 }));
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "lens.model" }));
            Assert.That(problems[0].Fix, Does.Contain("opencv"));
        }

        [Test]
        public void LensesInstantNgpWouldMisreadAreRefusedWhileItIsALoader()
        {
            // instant-ngp stores p1 over k3 (nerf_loader.cu read_lens), and an all-zero fisheye reads as a pinhole there.
            var k3 = new LensSettings { Model = "opencv", K1 = -0.1, K3 = 0.01 };
            var problems = SettingsValidator.Validate(With(k3));
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "lens.k3" }));
            Assert.That(problems[0].Fix, Does.Contain("instant-ngp"));
            Assert.That(Fields(With(k3, TargetLoaders.Nerfstudio)), Is.Empty);
            Assert.That(Fields(With(new LensSettings { Model = "opencv_fisheye" })), Is.EqualTo(new[] { "lens.model" }));
            Assert.That(Fields(With(new LensSettings { Model = "opencv_fisheye" }, TargetLoaders.Nerfstudio)), Is.Empty);
        }

        [Test]
        public void ALensThatFoldsInsideTheFrameIsRefused()
        {
            // Strong barrel on a 60° frame: the radial factor turns back before the corner.
            var settings = With(new LensSettings { Model = "opencv", K1 = -0.9 });
            settings.Camera.VerticalFovDegrees = 60;
            var problems = SettingsValidator.Validate(settings);
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "lens" }));
            Assert.That(problems[0].Reason, Does.Contain("folds over"));
        }

        [Test]
        public void AWideRenderBeyondTheTextureLimitIsRefusedNamingTheSize()
        {
            // 8192 wide at supersampling 2 is already 16384; the lens widens the render beyond it.
            var settings = With(new LensSettings { Model = "opencv", K1 = -0.1 });
            settings.Width = 8000;
            settings.Height = 4000;
            settings.Supersampling = 2;
            var problems = SettingsValidator.Validate(settings);
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "lens" }));
            Assert.That(problems[0].Reason, Does.Contain("16384"));
            var wide = LensCapture.WideRender(settings.Lens.ToDistortion(), settings.Intrinsics());
            Assert.That(problems[0].Reason, Does.Contain(wide.Width + " × " + wide.Height));
        }

        [Test]
        public void TheLoadersThatIgnoreDistortionAreWarnedAbout()
        {
            var plan = CapturePlan.Build(With(new LensSettings { Model = "opencv", K1 = -0.1 }), PlanTarget.AtOrigin);
            var lensWarnings = plan.Warnings.Where(w => w.Field == "lens").ToList();
            Assert.That(lensWarnings.Count, Is.EqualTo(2));
            Assert.That(lensWarnings[0].Reason, Does.Contain("original NeRF"));
            Assert.That(lensWarnings[1].Reason, Does.Contain("3DGS's Blender reader"));
            var ngpOnly = CapturePlan.Build(With(new LensSettings { Model = "opencv", K1 = -0.1 }, TargetLoaders.InstantNgp | TargetLoaders.Nerfstudio), PlanTarget.AtOrigin);
            Assert.That(ngpOnly.Warnings.Where(w => w.Field == "lens"), Is.Empty);
        }

        [Test]
        public void TheCloneDoesNotShareTheLens()
        {
            var settings = With(new LensSettings { Model = "opencv", K1 = -0.1 });
            var copy = settings.Clone();
            copy.Lens.K1 = 0.2;
            Assert.That(settings.Lens.K1, Is.EqualTo(-0.1));
        }
    }
}
