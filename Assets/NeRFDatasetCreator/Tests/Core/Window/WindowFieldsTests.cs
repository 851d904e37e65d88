using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Every problem Core reports lands next to a control of the window, in the step that fixes it.</summary>
    [TestFixture]
    public class WindowFieldsTests
    {
        static IEnumerable<TestCaseData> BrokenSettings()
        {
            yield return Case("fov", s => s.Camera.VerticalFovDegrees = 0, "camera.verticalFovDegrees", WindowStep.Camera);
            yield return Case("near", s => s.Camera.NearClip = -1, "camera.nearClip", WindowStep.Camera);
            yield return Case("far", s => s.Camera.FarClip = double.PositiveInfinity, "camera.farClip", WindowStep.Camera);
            yield return Case("distance", s => s.Distance = double.NaN, "distance", WindowStep.Target);
            yield return Case("margin", s => { s.AutoDistance = true; s.AutoDistanceMargin = 0.5; }, "autoDistanceMargin", WindowStep.Target);
            yield return Case("width", s => s.Width = 4, "width", WindowStep.Camera);
            yield return Case("height", s => s.Height = 9000, "height", WindowStep.Camera);
            yield return Case("supersampling", s => s.Supersampling = 5, "supersampling", WindowStep.Camera);
            yield return Case("background", s => s.Background = new BackgroundSettings { Transparent = false, R = 2 }, "background.r", WindowStep.Camera);
            yield return Case("name", s => s.Name = "a/b", "name", WindowStep.OutputFolder);
            yield return Case("loaders", s => s.Loaders = TargetLoaders.None, "loaders", WindowStep.OutputFolder);
            yield return Case("count", s => s.Val.Count = -1, "splits.val.count", WindowStep.Rig);
            yield return Case("empty val for nerfstudio", s => s.Val.Count = 0, "splits.val.count", WindowStep.Rig);
            yield return Case("orbit turns", s => s.Test.Formation.Turns = 0, "splits.test.formation.turns", WindowStep.Rig);
            yield return Case("semisphere bottom", s => s.Train.Formation.BottomElevationDegrees = 95, "splits.train.formation.bottomElevationDegrees", WindowStep.Rig);
            yield return Case("normalised radius", s => s.NormalisedTargetRadius = double.NaN, "normalisedTargetRadius", WindowStep.Outputs);
            yield return Case("point cloud", s => s.PointCloudPoints = -5, "pointCloudPoints", WindowStep.Outputs);
            yield return Case("sparse views", s => s.SparseViews = new[] { 0 }, "sparseViews", WindowStep.Outputs);
            yield return Case("time steps", s =>
            {
                s.Time.Mode = TimeMode.MultiView;
                s.Time.Steps = 1;
            }, "time.steps", WindowStep.Time);
            yield return Case("time sources", s =>
            {
                s.Time.Mode = TimeMode.Monocular;
                s.Time.Sources = TimeSources.None;
            }, "time.sources", WindowStep.Time);
            yield return Case("time end", s =>
            {
                s.Time.Mode = TimeMode.Monocular;
                s.Time.StartSeconds = 3;
                s.Time.EndSeconds = 2;
            }, "time.end", WindowStep.Time);
            yield return Case("labels by name without rules", s =>
            {
                s.Labels.Enabled = true;
                s.Labels.ClassFrom = ClassSource.Name;
            }, "labels.classes", WindowStep.Outputs);
            yield return Case("labels rule without a class", s =>
            {
                s.Labels.Enabled = true;
                s.Labels.Classes.Add(new ClassRule("Car*", ""));
            }, "labels.classes[0].class", WindowStep.Outputs);
            yield return Case("exposure list entry", s =>
            {
                s.Exposure.Mode = ExposureMode.List;
                s.Exposure.Values.Add(new ViewExposure(11, 1, 1, 1));
            }, "exposure.values[0].ev", WindowStep.Outputs);
            yield return Case("lens coefficient of another model", s =>
            {
                s.Lens.Model = "opencv_fisheye";
                s.Lens.P1 = 0.001;
            }, "lens.p1", WindowStep.Outputs);
            yield return Case("lens with a rolling shutter", s =>
            {
                s.Lens.Model = "opencv";
                s.Lens.K1 = -0.1;
                s.MotionBlur.Enabled = true;
                s.MotionBlur.Camera = ShutterCameraMotion.Shake;
                s.MotionBlur.ShakeDegrees = 2;
                s.MotionBlur.Readout = 0.5;
            }, "lens", WindowStep.Outputs);
            yield return Case("motion blur shutter", s =>
            {
                s.MotionBlur.Enabled = true;
                s.MotionBlur.Shutter = 1.5;
            }, "motionBlur.shutter", WindowStep.Outputs);
            yield return Case("motion blur still in a static capture", s =>
            {
                s.MotionBlur.Enabled = true;
                s.MotionBlur.Camera = ShutterCameraMotion.Still;
            }, "motionBlur.camera", WindowStep.Outputs);
            yield return Case("hdr without splits", s =>
            {
                s.Hdr.On = true;
                s.Hdr.Train = s.Hdr.Val = s.Hdr.Test = false;
            }, "hdr.splits", WindowStep.Outputs);
            yield return Case("halo elevation", s =>
            {
                s.Train.Formation.Kind = FormationKind.Halo;
                s.Train.Formation.ElevationDegrees = 120;
            }, "splits.train.formation.elevationDegrees", WindowStep.Rig);
        }

        static TestCaseData Case(string name, System.Action<DatasetSettings> breakIt, string field, WindowStep step) =>
            new TestCaseData(breakIt, field, step).SetName("ProblemIsShownByItsControl(" + name + ")");

        [TestCaseSource(nameof(BrokenSettings))]
        public void ProblemIsShownByItsControl(System.Action<DatasetSettings> breakIt, string field, WindowStep step)
        {
            var settings = new DatasetSettings();
            breakIt(settings);
            var problems = SettingsValidator.Validate(settings);

            Assert.That(problems.Select(p => p.Field), Has.Member(field), "the validator's field name changed");
            var fieldProblems = new FieldProblems(problems, null);
            Assert.That(fieldProblems.NotCoveredBy(WindowFields.All(settings)), Is.Empty, "a problem without a control in the window");
            Assert.That(fieldProblems.FirstIncompleteStep(), Is.EqualTo(step));
            Assert.That(WindowFields.StepOf(field), Is.EqualTo(step));
        }

        [Test]
        public void PlanProblemsAboutTheTargetAreShownToo()
        {
            var settings = new DatasetSettings { Distance = 0.5 };
            var problems = CapturePlan.Check(settings, new PlanTarget(Vector3d.Zero, 1));
            Assert.That(problems.Select(p => p.Field), Has.Member("distance"));
            Assert.That(new FieldProblems(problems, null).NotCoveredBy(WindowFields.All(settings)), Is.Empty);
        }

        [Test]
        public void AProblemOfTheCaptureEnvironmentFallsToTheCreateStep()
        {
            var environment = new ValidationProblem("graphicsDevice", "Null", "cannot render.", "Start Unity without -nographics.");
            var problems = new FieldProblems(new[] { environment }, null);
            Assert.That(problems.NotCoveredBy(WindowFields.All(new DatasetSettings())), Is.EqualTo(new[] { environment }));
            Assert.That(problems.FirstIncompleteStep(), Is.EqualTo(WindowStep.Create));
        }

        [TestCase("background", "background.r", true)]
        [TestCase("background", "background", true)]
        [TestCase("background", "backgroundColor", false)]
        [TestCase("splits.train.count", "splits.train.countx", false)]
        [TestCase("loaders", "loaders[2]", true)]
        [TestCase("splits.train.formation", "splits.train.formation.turns", true)]
        public void ACoversItsOwnPartsOnly(string control, string problem, bool expected)
        {
            Assert.That(WindowFields.Covers(control, problem), Is.EqualTo(expected));
        }

        [Test]
        public void OutputProblemsBelongToTheOutputsStep()
        {
            Assert.That(WindowFields.StepOf("splits.val.depth"), Is.EqualTo(WindowStep.Outputs));
            Assert.That(WindowFields.StepOf("splits.test.mask"), Is.EqualTo(WindowStep.Outputs));
            Assert.That(WindowFields.StepOf("splits.test.formation"), Is.EqualTo(WindowStep.Rig));
            Assert.That(WindowFields.StepOf("overwrite"), Is.EqualTo(WindowStep.OutputFolder));
        }

        [Test]
        public void TheFirstIncompleteStepFollowsTheWindowsOrder()
        {
            var settings = new DatasetSettings { Name = "", Supersampling = 9 };
            var problems = new FieldProblems(SettingsValidator.Validate(settings), null);
            Assert.That(problems.FirstIncompleteStep(), Is.EqualTo(WindowStep.Camera));
            Assert.That(problems.StepHasErrors(WindowStep.OutputFolder), Is.True);
            Assert.That(problems.StepHasErrors(WindowStep.Rig), Is.False);
            Assert.That(new FieldProblems(SettingsValidator.Validate(new DatasetSettings()), null).FirstIncompleteStep(), Is.Null);
        }

        [Test]
        public void ASectionsEndListsOnlyWhatItsFieldsDoNotShow()
        {
            var wide = new ValidationProblem("lens", "opencv", "needs a wide render.", "Use a milder lens.");
            var k1 = new ValidationProblem("lens.k1", "NaN", "is not a finite number.", "Write a number.");
            var k4 = new ValidationProblem("lens.k4", "0.1", "is not a coefficient.", "Remove k4.");
            var other = new ValidationProblem("lensFlare", "1", "is unknown.", "");
            var problems = new FieldProblems(new[] { wide, k1, k4, other }, new[] { k1 });
            var drawn = new[] { "lens.model", "lens.k1", "lens.k2" };
            Assert.That(problems.ErrorsFor("lens", drawn), Is.EqualTo(new[] { wide, k4 }));
            Assert.That(problems.WarningsFor("lens", drawn), Is.Empty);
            Assert.That(problems.WarningsFor("lens", new string[0]), Is.EqualTo(new[] { k1 }));
        }

        [Test]
        public void WarningsAreFoundByTheirControlButDoNotBlock()
        {
            var warning = new ValidationProblem("splits.train.count", "3", "is few.", "Use more.");
            var problems = new FieldProblems(null, new[] { warning });
            Assert.That(problems.HasErrors, Is.False);
            Assert.That(problems.WarningsFor("splits.train.count"), Is.EqualTo(new[] { warning }));
            Assert.That(problems.ErrorsFor("splits.train.count"), Is.Empty);
            Assert.That(problems.FirstIncompleteStep(), Is.Null);
        }

        [Test]
        public void TheFoldedParametersOfASemiSphereCanBeAskedForTogether()
        {
            var settings = new DatasetSettings();
            settings.Train.Formation.TopElevationDegrees = 200;
            var problems = new FieldProblems(SettingsValidator.Validate(settings), null);
            var folded = FormationSettings.ParameterNames(FormationKind.SemiSphere).Select(p => WindowFields.FormationField(DatasetSplit.Train, p));
            Assert.That(problems.ErrorsForAny(folded).Count, Is.GreaterThan(0));
            var valFolded = FormationSettings.ParameterNames(FormationKind.SemiSphere).Select(p => WindowFields.FormationField(DatasetSplit.Val, p));
            Assert.That(problems.ErrorsForAny(valFolded), Is.Empty);
        }
    }
}
