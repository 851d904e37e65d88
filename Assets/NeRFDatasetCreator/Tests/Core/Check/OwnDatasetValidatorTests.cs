using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The validator on datasets written from our own plans, with the extra files.</summary>
    [TestFixture]
    public class OwnDatasetValidatorTests
    {
        TempFolder _temp;

        [SetUp]
        public void SetUp() => _temp = new TempFolder();

        [TearDown]
        public void TearDown() => _temp.Dispose();

        static string[] Lines(string folder) => DatasetValidator.Validate(folder).Problems.Select(p => p.ToString()).ToArray();

        [Test]
        public void OurOwnDatasetWithEveryExtraIsValid()
        {
            var s = new DatasetSettings { Width = 64, Height = 48 };
            s.Train.Count = 4;
            s.Val.Count = 2;
            s.Test.Count = 3;
            s.Train.Mask = true;
            s.Test.Depth = ExtraOutput.PngAndExr;
            s.Test.Normal = ExtraOutput.PngAndExr;
            s.Test.Mask = true;
            var folder = _temp.Combine("ours");
            TestDatasets.FromPlan(folder, CapturePlan.Build(s, PlanTarget.AtOrigin));
            var report = DatasetValidator.Validate(folder);
            Assert.That(report.Problems.Select(p => p.ToString()), Is.Empty);
            Assert.That(report.Warnings, Is.Empty);
            Assert.That(report.ImagesChecked, Is.EqualTo(9));
            // test: depth_path and depth_file_path (the same file, counted once), normal_path, mask_path per frame; train: mask_path.
            Assert.That(report.ExtraFilesChecked, Is.EqualTo(3 * 3 + 4));
        }

        [Test]
        public void DeclaredSizeThatIsNotTheImagesSize()
        {
            var s = new DatasetSettings { Width = 64, Height = 48 };
            s.Train.Count = 2;
            s.Val.Count = 1;
            s.Test.Count = 1;
            var folder = _temp.Combine("ours");
            TestDatasets.FromPlan(folder, CapturePlan.Build(s, PlanTarget.AtOrigin));
            var train = Path.Combine(folder, "transforms_train.json");
            File.WriteAllText(train, File.ReadAllText(train).Replace("\"w\": 64,", "\"w\": 800,"));
            Assert.That(Lines(folder), Is.EqualTo(new[]
            {
                "transforms_train.json: w × h = 800×48 but the images are 64×48; instant-ngp and nerfstudio take the intrinsics from w and h (write the images' size).",
            }));
        }

        [Test]
        public void ExtraFileInTheWrongFormat()
        {
            var s = new DatasetSettings { Width = 32, Height = 32 };
            s.Train.Count = 2;
            s.Val.Count = 1;
            s.Test.Count = 1;
            s.Test.Depth = ExtraOutput.Png;
            var folder = _temp.Combine("ours");
            TestDatasets.FromPlan(folder, CapturePlan.Build(s, PlanTarget.AtOrigin));
            TestPng.Write(Path.Combine(folder, "test", "r_0_depth_0000.png"), 32, 32, 8, PngInfo.ColorTypeGray);
            var lines = Lines(folder);
            Assert.That(lines, Has.Length.EqualTo(1), "depth_path and depth_file_path name the same file: one problem, not two");
            Assert.That(lines[0], Is.EqualTo("transforms_test.json frame 0 (./test/r_0): depth_path ./test/r_0_depth_0000.png is 8-bit grey, expected 16-bit grey (Documentation~/output-format.md)."));
        }

        [Test]
        public void MissingExtraFile()
        {
            var s = new DatasetSettings { Width = 32, Height = 32 };
            s.Train.Count = 2;
            s.Train.Mask = true;
            s.Val.Count = 1;
            s.Test.Count = 1;
            var folder = _temp.Combine("ours");
            TestDatasets.FromPlan(folder, CapturePlan.Build(s, PlanTarget.AtOrigin));
            File.Delete(Path.Combine(folder, "train", "r_1_mask_0000.png"));
            Assert.That(Lines(folder), Is.EqualTo(new[] { "transforms_train.json frame 1 (./train/r_1): mask_path ./train/r_1_mask_0000.png is missing." }));
        }

        [Test]
        public void AnEmptySplitIsAWarningNotAProblem()
        {
            var s = new DatasetSettings { Width = 16, Height = 16, Loaders = TargetLoaders.InstantNgp };
            s.Train.Count = 2;
            s.Val.Count = 0;
            s.Test.Count = 0;
            var folder = _temp.Combine("ours");
            TestDatasets.FromPlan(folder, CapturePlan.Build(s, PlanTarget.AtOrigin));
            var report = DatasetValidator.Validate(folder);
            Assert.That(report.IsValid, Is.True);
            Assert.That(report.Warnings.Select(w => w.File), Is.EqualTo(new[] { "transforms_val.json", "transforms_test.json" }));
        }
    }
}
