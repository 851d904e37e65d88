using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Datasets rendered analytically through the capture's own writers pass every check that has its inputs.</summary>
    [TestFixture]
    public class CleanDatasetCheckTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();
        [TearDown] public void Delete() => _temp.Dispose();

        static readonly string[] AllChecks = { "alpha vs mask", "depth vs mask", "depth vs normals", "multi-view geometry", "point cloud vs masks", "colour vs geometry" };

        static void AssertClean(DatasetCheckReport report)
        {
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems);
            TestContext.WriteLine(text);
            Assert.That(report.Problems, Is.Empty, text);
            Assert.That(report.Failed, Is.False, text);
            foreach (var name in AllChecks)
                Assert.That(report.Results.Single(r => r.Name == name).Status, Is.EqualTo(DatasetCheckStatus.Passed), name + "\n" + text);
        }

        [Test]
        public void NonSquareDatasetPasses()
        {
            var folder = AnalyticDataset.Write(_temp.Path, "wide", new AnalyticDataset.Options());
            AssertClean(DatasetCheck.Run(folder, new DatasetCheckOptions()));
        }

        [Test]
        public void SquareDatasetPasses()
        {
            var folder = AnalyticDataset.Write(_temp.Path, "square", new AnalyticDataset.Options { Width = 80, Height = 80 });
            AssertClean(DatasetCheck.Run(folder, new DatasetCheckOptions()));
        }

        [Test]
        public void DepthAndNormalsAtTheSupersampledSizePass()
        {
            // CaptureOptions.DepthAndNormalAtOutputSize off: depth and normals point-sampled from 2×2 blocks, a quarter
            // pixel off the pixel centre (pixels.md §4).
            var folder = AnalyticDataset.Write(_temp.Path, "blocks", new AnalyticDataset.Options { DataAtOutputSize = false });
            AssertClean(DatasetCheck.Run(folder, new DatasetCheckOptions()));
        }

        [Test]
        public void NormalisedDatasetPasses()
        {
            var folder = AnalyticDataset.Write(_temp.Path, "half", new AnalyticDataset.Options { Normalised = true });
            StringAssertScale(folder);
            AssertClean(DatasetCheck.Run(folder, new DatasetCheckOptions()));
        }

        [Test]
        public void DynamicDatasetPasses()
        {
            // Three times, the sphere moving between them: multi-view pairs only within a time.
            var folder = AnalyticDataset.Write(_temp.Path, "moving", new AnalyticDataset.Options { Train = 6, Val = 2, Test = 2, TimeSteps = 3 });
            var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            Assert.That(report.Results.Single(r => r.Name == "dataset").Figure, Does.Contain("3 times"));
            Assert.That(report.Results.Single(r => r.Name == "point cloud vs masks").Status, Is.EqualTo(DatasetCheckStatus.Skipped));
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems);
            Assert.That(report.Problems, Is.Empty, text);
            Assert.That(report.Results.Single(r => r.Name == "multi-view geometry").Status, Is.EqualTo(DatasetCheckStatus.Passed), text);
        }

        [Test]
        public void LowResolutionLensCapturePassesMultiViewGeometry()
        {
            // Issue 32 item 19: a lens capture renders its data passes at the supersampled size. With each depth pixel one
            // sample a quarter pixel off the centre, this clean 128×96 capture failed multi-view geometry (median depth
            // error 0.54–0.79 % in four pairs against 0.5 %); with the harmonic mean of the central samples it is ~0.03 %.
            var folder = AnalyticDataset.Write(_temp.Path, "lens", new AnalyticDataset.Options
            {
                Lens = new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.02 }, ThroughWideRender = true, DataAtOutputSize = false,
                VerticalFovDegrees = 70, Distance = 1.8, Width = 128, Height = 96, PointCloud = 0, Train = 6, Val = 1, Test = 1,
            });
            var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems);
            TestContext.WriteLine(text);
            Assert.That(report.Problems, Is.Empty, text);
            Assert.That(report.Results.Single(r => r.Name == "multi-view geometry").Status, Is.EqualTo(DatasetCheckStatus.Passed), text);
        }

        static void StringAssertScale(string folder)
        {
            var json = Newtonsoft.Json.Linq.JObject.Parse(System.IO.File.ReadAllText(System.IO.Path.Combine(folder, "transforms_train.json")));
            Assert.That((double)json["scene_normalisation"]["scale"], Is.EqualTo(0.5), "the normalised dataset's scale");
        }
    }
}
