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

        static void StringAssertScale(string folder)
        {
            var json = Newtonsoft.Json.Linq.JObject.Parse(System.IO.File.ReadAllText(System.IO.Path.Combine(folder, "transforms_train.json")));
            Assert.That((double)json["scene_normalisation"]["scale"], Is.EqualTo(0.5), "the normalised dataset's scale");
        }
    }
}
