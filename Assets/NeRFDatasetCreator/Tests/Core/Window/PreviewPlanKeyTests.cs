using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class PreviewPlanKeyTests
    {
        static readonly PlanTarget Target = new PlanTarget(new Vector3d(1, 2, 3), 0.5);

        [Test]
        public void EqualSettingsAndTargetGiveEqualKeys()
        {
            Assert.That(PreviewPlanKey.Of(new DatasetSettings(), Target), Is.EqualTo(PreviewPlanKey.Of(new DatasetSettings(), Target)));
        }

        [Test]
        public void EveryCameraShapingChangeChangesTheKey()
        {
            var baseline = PreviewPlanKey.Of(new DatasetSettings(), Target);
            var changes = new System.Action<DatasetSettings>[]
            {
                s => s.Distance = 4.000000001,
                s => s.Camera.VerticalFovDegrees = 50,
                s => s.Width = 801,
                s => s.Seed = 1,
                s => s.Val.Count = 99,
                s => s.Test.Formation.Turns = 3,
                s => s.Train.Formation.Kind = FormationKind.Sphere,
                s => s.AutoDistance = true,
            };
            foreach (var change in changes)
            {
                var settings = new DatasetSettings();
                change(settings);
                Assert.That(PreviewPlanKey.Of(settings, Target), Is.Not.EqualTo(baseline));
            }
        }

        [Test]
        public void MovingOrResizingTheTargetChangesTheKey()
        {
            var settings = new DatasetSettings();
            var baseline = PreviewPlanKey.Of(settings, Target);
            Assert.That(PreviewPlanKey.Of(settings, new PlanTarget(new Vector3d(1, 2, 3.0001), 0.5)), Is.Not.EqualTo(baseline));
            Assert.That(PreviewPlanKey.Of(settings, new PlanTarget(new Vector3d(1, 2, 3), 0.51)), Is.Not.EqualTo(baseline));
        }

        [Test]
        public void NamesFoldersAndOutputPassesDoNotRebuildThePreview()
        {
            var baseline = PreviewPlanKey.Of(new DatasetSettings(), Target);
            var settings = new DatasetSettings { Name = "other", OutputFolder = "/tmp/x", Overwrite = OverwritePolicy.Replace };
            settings.Train.Depth = ExtraOutput.Exr;
            settings.Val.Mask = true;
            Assert.That(PreviewPlanKey.Of(settings, Target), Is.EqualTo(baseline));
            Assert.That(PreviewPlanKey.Of(settings, Target).GetHashCode(), Is.EqualTo(baseline.GetHashCode()));
        }

        [Test]
        public void TheKeyDoesNotChangeTheSettings()
        {
            var settings = new DatasetSettings { Name = "lego" };
            settings.Train.Depth = ExtraOutput.Png;
            PreviewPlanKey.Of(settings, Target);
            Assert.That(settings.Name, Is.EqualTo("lego"));
            Assert.That(settings.Train.Depth, Is.EqualTo(ExtraOutput.Png));
        }
    }
}
