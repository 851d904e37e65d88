using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>nerfstudio_dataparser.py:185–191 asserts depth and mask paths on all frames or none; a plan says so up front.</summary>
    public class SplitExtrasCheckTests
    {
        static DatasetSettings Settings()
        {
            var s = new DatasetSettings { Name = "x", Distance = 4 };
            s.Train.Count = 2; s.Val.Count = 2; s.Test.Count = 2;
            return s;
        }

        static string[] Fields(DatasetSettings s) =>
            CapturePlan.Build(s, new PlanTarget(new Vector3d(0, 0, 0), 1)).Warnings.Select(w => w.Field).Where(f => f.StartsWith("splits.")).ToArray();

        [Test]
        public void DepthInTrainAndTestButNotVal_IsAWarningNamingVal()
        {
            var s = Settings();
            s.Train.Depth = ExtraOutput.Png;
            s.Test.Depth = ExtraOutput.PngAndExr;
            Assert.That(Fields(s), Is.EqualTo(new[] { "splits.val.depth" }));
            var warning = CapturePlan.Build(s, new PlanTarget(new Vector3d(0, 0, 0), 1)).Warnings.Single(w => w.Field == "splits.val.depth");
            Assert.That(warning.Reason, Does.Contain("train and test").And.Contain("nerfstudio"));
        }

        [Test]
        public void MasksInOneSplitOnly_IsAWarning()
        {
            var s = Settings();
            s.Test.Mask = true;
            Assert.That(Fields(s), Is.EqualTo(new[] { "splits.train.mask" }));
        }

        [Test]
        public void AnEmptySplitDoesNotCount_AndSameExtrasEverywhereIsQuiet()
        {
            var s = Settings();
            s.Test.Count = 0;
            s.Loaders = TargetLoaders.Nerfstudio;
            s.Train.Depth = ExtraOutput.Png;
            s.Val.Depth = ExtraOutput.Png;
            Assert.That(Fields(s), Is.Empty);
        }

        [Test]
        public void WithoutNerfstudioInLoaders_NothingIsSaid()
        {
            var s = Settings();
            s.Train.Depth = ExtraOutput.Png;
            s.Loaders = TargetLoaders.Nerf | TargetLoaders.GaussianSplatting;
            Assert.That(Fields(s), Is.Empty);
        }
    }
}
