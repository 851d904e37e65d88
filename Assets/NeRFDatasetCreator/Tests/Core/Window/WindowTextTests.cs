using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class WindowTextTests
    {
        [TestCase(0.8660254, "0.866")]
        [TestCase(12.3456, "12.3")]
        [TestCase(1250.4, "1250")]
        [TestCase(4.0, "4")]
        [TestCase(0.0, "0")]
        public void LengthsShowThreeSignificantDigits(double value, string expected)
        {
            Assert.That(WindowText.Length(value), Is.EqualTo(expected));
        }

        [Test]
        public void TheSuggestedDistanceIsTheAutoDistanceRule()
        {
            // nerf_synthetic: square 800×800, camera_angle_x 0.6911 rad; a unit sphere at margin 1.2 needs
            // R = 1.2 / sin(0.6911/2) = 3.5266 (hand-derived: sin(0.34556) = 0.33866).
            var settings = new DatasetSettings();
            var target = new PlanTarget(Vector3d.Zero, 1);
            Assert.That(WindowText.SuggestedDistance(target, settings).Value, Is.EqualTo(1.2 / 0.338656).Within(1e-3));
            Assert.That(WindowText.TargetSummary(target, settings),
                Is.EqualTo("Bounding sphere radius 1 (diameter 2); suggested distance 3.54."));
        }

        [Test]
        public void NoDistanceIsSuggestedWithoutBoundsOrWithABrokenCamera()
        {
            var settings = new DatasetSettings();
            Assert.That(WindowText.SuggestedDistance(new PlanTarget(Vector3d.Zero, 0), settings), Is.Null);
            Assert.That(WindowText.TargetSummary(new PlanTarget(Vector3d.Zero, 0), settings), Does.StartWith("No renderer bounds"));
            settings.Camera.VerticalFovDegrees = 180;
            Assert.That(WindowText.SuggestedDistance(new PlanTarget(Vector3d.Zero, 1), settings), Is.Null);
            Assert.That(WindowText.TargetSummary(new PlanTarget(Vector3d.Zero, 1), settings), Does.Contain("fix the field of view"));
        }

        [Test]
        public void AnInvalidMarginStillSuggestsWithTheDefaultOne()
        {
            var settings = new DatasetSettings { AutoDistanceMargin = 0 };
            var expected = AutoDistanceRule.Distance(2, settings.Camera.VerticalFovDegrees, 800, 800, AutoDistanceRule.DefaultMargin);
            Assert.That(WindowText.SuggestedDistance(new PlanTarget(Vector3d.Zero, 2), settings), Is.EqualTo(expected));
        }

        [Test]
        public void TheRunSummaryCountsEverySplit()
        {
            Assert.That(WindowText.RunSummary(new DatasetSettings()), Is.EqualTo("400 views (train 100 · val 100 · test 200), 800 × 800."));
            var settings = new DatasetSettings { Width = 400, Height = 300, Supersampling = 2 };
            settings.Train.Count = 1;
            settings.Val.Count = 0;
            settings.Test.Count = 0;
            Assert.That(WindowText.RunSummary(settings), Is.EqualTo("1 view (train 1 · val 0 · test 0), 400 × 300, supersampling 2×."));
        }

        [Test]
        public void AProblemReadsAsValueReasonFix()
        {
            var problem = new ValidationProblem("width", "4", "is outside the valid range [8, 8192].", "Use a whole number from 8 to 8192.");
            Assert.That(WindowText.Problem(problem), Is.EqualTo("4 is outside the valid range [8, 8192]. Use a whole number from 8 to 8192."));
            Assert.That(WindowText.ProblemWithField(problem), Does.StartWith("width: 4 is outside"));
        }

        [Test]
        public void AConfigErrorNamesLineColumnAndFile()
        {
            SettingsFormatException error = null;
            try
            {
                DatasetSettingsJson.Read("{\n  \"width\": \"wide\"\n}", "/tmp/lego.json");
            }
            catch (SettingsFormatException e)
            {
                error = e;
            }
            Assert.That(error, Is.Not.Null);
            var text = WindowText.ConfigError(error);
            Assert.That(text, Does.StartWith("Not loaded (line 2, column "));
            Assert.That(text, Does.Contain("of lego.json): width: must be a whole number"));
            Assert.That(text, Does.EndWith("The window's settings are unchanged."));
        }

        [Test]
        public void ProgressShowsDoneTotalAndRate()
        {
            Assert.That(WindowText.Progress(12, 400, 0), Is.EqualTo("12 / 400 views"));
            Assert.That(WindowText.Progress(12, 400, 7.25), Is.EqualTo("12 / 400 views, 7.3 views/s").Or.EqualTo("12 / 400 views, 7.2 views/s"));
        }

        [Test]
        public void ThePopupsListEveryKindInEnumOrder()
        {
            Assert.That(WindowText.FormationLabels().Length, Is.EqualTo(FormationKinds.All.Count));
            for (var i = 0; i < FormationKinds.All.Count; i++) Assert.That((int)FormationKinds.All[i], Is.EqualTo(i));
            Assert.That(WindowText.FormationLabels()[(int)FormationKind.SemiSphere], Does.StartWith("Semi-sphere"));
            Assert.That(WindowText.ExtraOutputLabels.Length, Is.EqualTo(System.Enum.GetValues(typeof(ExtraOutput)).Length));
            Assert.That(WindowText.ExtraOutputLabels[(int)ExtraOutput.PngAndExr], Is.EqualTo("PNG + EXR"));
            Assert.That(WindowText.TimeModeLabels.Length, Is.EqualTo(TimeModes.All.Count));
            for (var i = 0; i < TimeModes.All.Count; i++) Assert.That((int)TimeModes.All[i], Is.EqualTo(i));
            Assert.That(WindowText.TimeModeLabels[(int)TimeMode.MultiView], Does.StartWith("Multi-view"));
        }

        [Test]
        public void TheTimeSourceMaskBitsAreTheSourceFlags()
        {
            // EditorGUILayout.MaskField sets bit i for option i: option i must be the flag 1 << i.
            Assert.That(WindowText.TimeSourceLabels.Length, Is.EqualTo(4));
            Assert.That((int)TimeSources.Timeline, Is.EqualTo(1 << 0));
            Assert.That((int)TimeSources.Animator, Is.EqualTo(1 << 1));
            Assert.That((int)TimeSources.Animation, Is.EqualTo(1 << 2));
            Assert.That((int)TimeSources.Particles, Is.EqualTo(1 << 3));
            Assert.That(WindowText.TimeSourceLabels[2], Does.StartWith("Animation"));
        }
    }
}
