using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class SettingsValidatorTests
    {
        static string[] FieldsOf(DatasetSettings s) => SettingsValidator.Validate(s).Select(p => p.Field).ToArray();

        [TestCase(-1)]
        [TestCase(100001)]
        public void CountOutOfRange(int count)
        {
            var s = new DatasetSettings();
            s.Train.Count = count;
            Assert.That(FieldsOf(s), Is.EqualTo(new[] { "splits.train.count" }));
        }

        [TestCase(0)]
        [TestCase(100000)]
        public void CountAtTheLimitsIsFineWhereNoLoaderNeedsTheSplit(int count)
        {
            var s = new DatasetSettings { Loaders = TargetLoaders.InstantNgp };
            s.Test.Count = count;
            Assert.That(FieldsOf(s), Is.Empty);
        }

        [TestCase(7, 800, "width")]
        [TestCase(8193, 800, "width")]
        [TestCase(800, 7, "height")]
        [TestCase(800, 8193, "height")]
        public void SizeOutOfRange(int width, int height, string field)
        {
            Assert.That(FieldsOf(new DatasetSettings { Width = width, Height = height }), Is.EqualTo(new[] { field }));
        }

        [TestCase(8, 8)]
        [TestCase(8192, 8192)]
        [TestCase(1600, 900)]
        public void SizeInRangeIsFine(int width, int height)
        {
            Assert.That(FieldsOf(new DatasetSettings { Width = width, Height = height }), Is.Empty);
        }

        [TestCase(0)]
        [TestCase(5)]
        public void SupersamplingOutOfRange(int k)
        {
            Assert.That(FieldsOf(new DatasetSettings { Supersampling = k }), Is.EqualTo(new[] { "supersampling" }));
        }

        [Test]
        public void TheLargestSupersamplingTheSettingsAllowIsOneTheWriterAccepts()
        {
            // One limit for the window, batch configs, the capture options and the writer: RawFrame's.
            var k = RawFrame.MaxSupersampling;
            Assert.That(FieldsOf(new DatasetSettings { Width = 8, Height = 8, Supersampling = k }), Is.Empty);
            Assert.That(new RawFrame(8 * k, 8 * k, k).Validate().Select(p => p.Field), Has.None.EqualTo("frame.Supersampling"));
            Assert.That(FieldsOf(new DatasetSettings { Width = 8, Height = 8, Supersampling = k + 1 }), Is.EqualTo(new[] { "supersampling" }));
        }

        [TestCase(8192, 2, false)]
        [TestCase(8192, 3, true)]
        [TestCase(4096, 4, false)]
        [TestCase(4097, 4, true)]
        public void SupersampledRenderMustFitATexture(int size, int k, bool problem)
        {
            var fields = FieldsOf(new DatasetSettings { Width = size, Height = 8, Supersampling = k });
            Assert.That(fields, problem ? Is.EqualTo(new[] { "supersampling" }) : Is.Empty);
        }

        [Test]
        public void DistanceMustBeBeyondTheNearClip()
        {
            var s = new DatasetSettings { Distance = 0.5 };
            s.Camera.NearClip = 0.5;
            var problems = SettingsValidator.Validate(s);
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "distance" }));
            Assert.That(problems[0].Reason, Does.Contain("near"));
            Assert.That(problems[0].Value, Is.EqualTo("0.5"));
        }

        [Test]
        public void NearMustBeBelowFar()
        {
            var s = new DatasetSettings();
            s.Camera.NearClip = 10;
            s.Camera.FarClip = 10;
            Assert.That(FieldsOf(s), Does.Contain("camera.farClip"));
        }

        [Test]
        public void NaNAndInfinityAreReportedEverywhere()
        {
            var s = new DatasetSettings { Distance = double.PositiveInfinity };
            s.Camera.VerticalFovDegrees = double.NaN;
            s.Camera.NearClip = double.NaN;
            s.Train.Formation.TopElevationDegrees = double.NaN;
            s.Test.Formation.Turns = double.NegativeInfinity;
            var fields = FieldsOf(s);
            Assert.That(fields, Is.SupersetOf(new[]
            {
                "distance", "camera.verticalFovDegrees", "camera.nearClip", "splits.train.formation.topElevationDegrees", "splits.test.formation.turns",
            }));
        }

        [Test]
        public void EveryProblemIsReportedAtOnce()
        {
            var s = new DatasetSettings { Name = "a/b", Width = 4, Supersampling = 9, Distance = -1 };
            s.Val.Count = -5;
            var problems = SettingsValidator.Validate(s);
            Assert.That(problems.Select(p => p.Field), Is.EquivalentTo(new[] { "name", "width", "supersampling", "distance", "splits.val.count" }));
            foreach (var p in problems)
            {
                Assert.That(p.Reason, Is.Not.Empty, p.Field);
                Assert.That(p.Fix, Is.Not.Empty, p.Field);
            }
        }

        [TestCase("lego/800", "path separator")]
        [TestCase("lego\\800", "path separator")]
        [TestCase("lego:800", "':'")]
        [TestCase("what?", "'?'")]
        [TestCase("", "empty")]
        [TestCase("  ", "empty")]
        [TestCase("..", "relative")]
        [TestCase("CON", "reserved")]
        [TestCase("nul.json", "reserved")]
        [TestCase("lego.", "ends with")]
        [TestCase("tab\there", "control")]
        public void BadDatasetNames(string name, string reason)
        {
            var problems = SettingsValidator.Validate(new DatasetSettings { Name = name });
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "name" }));
            Assert.That(problems[0].Reason, Does.Contain(reason));
        }

        [TestCase("lego")]
        [TestCase("lego_800-v2.1")]
        [TestCase("datasets~")]
        public void GoodDatasetNames(string name)
        {
            Assert.That(FieldsOf(new DatasetSettings { Name = name }), Is.Empty);
        }

        [Test]
        public void EmptyValIsAProblemForTheLoadersThatNeedIt()
        {
            var s = new DatasetSettings();
            s.Val.Count = 0;
            var problems = SettingsValidator.Validate(s);
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "splits.val.count" }));
            Assert.That(problems[0].Reason, Does.Contain("nerf, nerfstudio need it"));
            Assert.That(problems[0].Fix, Does.Contain("remove nerf, nerfstudio from loaders"));
        }

        [Test]
        public void EmptyValIsFineForInstantNgpAnd3dgs()
        {
            var s = new DatasetSettings { Loaders = TargetLoaders.InstantNgp | TargetLoaders.GaussianSplatting };
            s.Val.Count = 0;
            s.Test.Count = 0;
            Assert.That(FieldsOf(s), Is.Empty);
        }

        [Test]
        public void EmptyTrainIsAProblemForEveryLoader([Values(TargetLoaders.Nerf, TargetLoaders.InstantNgp, TargetLoaders.Nerfstudio, TargetLoaders.GaussianSplatting)] TargetLoaders loader)
        {
            var s = new DatasetSettings { Loaders = loader };
            s.Train.Count = 0;
            Assert.That(FieldsOf(s), Is.EqualTo(new[] { "splits.train.count" }));
        }

        [Test]
        public void NoLoaderAtAllIsAProblem()
        {
            Assert.That(FieldsOf(new DatasetSettings { Loaders = TargetLoaders.None }), Is.EqualTo(new[] { "loaders" }));
        }

        [Test]
        public void FormationProblemsCarryTheSplitPrefix()
        {
            var s = new DatasetSettings();
            s.Train.Formation.BottomElevationDegrees = 60;
            s.Train.Formation.TopElevationDegrees = 30;
            Assert.That(FieldsOf(s), Is.EqualTo(new[] { "splits.train.formation.bottomElevationDegrees" }));
        }

        [Test]
        public void AutoDistanceChecksItsMargin()
        {
            Assert.That(FieldsOf(new DatasetSettings { AutoDistance = true, AutoDistanceMargin = 0.5 }), Is.EqualTo(new[] { "autoDistanceMargin" }));
            Assert.That(FieldsOf(new DatasetSettings { AutoDistance = true, Distance = -1 }), Is.Empty, "the fixed distance is unused");
        }

        [Test]
        public void FieldOfViewMustBeBetween0And180()
        {
            var s = new DatasetSettings();
            s.Camera.VerticalFovDegrees = 180;
            Assert.That(FieldsOf(s), Is.EqualTo(new[] { "camera.verticalFovDegrees" }));
        }

        [Test]
        public void SolidBackgroundComponentsMustBeIn0To1()
        {
            var s = new DatasetSettings { Background = new BackgroundSettings { Transparent = false, R = 1.5, G = double.NaN, B = 0 } };
            Assert.That(FieldsOf(s), Is.EqualTo(new[] { "background.r", "background.g" }));
        }
    }
}
