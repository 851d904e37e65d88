using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>What the capture's self-check relies on: progress, cancellation, the split and view options, the JSON report, a missing folder.</summary>
    [TestFixture]
    public class DatasetCheckRunTests
    {
        TempFolder _temp;
        string _folder;

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _folder = AnalyticDataset.Write(_temp.Path, "small", new AnalyticDataset.Options { Width = 48, Height = 36, Train = 6, Val = 2, Test = 2, PointCloud = 0 });
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        [Test]
        public void ProgressRisesToItsTotal()
        {
            var calls = new List<(int Done, int Total)>();
            DatasetCheck.Run(_folder, new DatasetCheckOptions(), (done, total) => calls.Add((done, total)));
            Assert.That(calls, Is.Not.Empty);
            Assert.That(calls.Select(c => c.Total).Distinct(), Is.EqualTo(new[] { 20 }), "one step per view, one more per view in the multi-view pass");
            Assert.That(calls.Select(c => c.Done), Is.Ordered);
            Assert.That(calls.Last(), Is.EqualTo((20, 20)));
        }

        [Test]
        public void ACancelledCheckSaysSo()
        {
            using (var cancel = new CancellationTokenSource())
            {
                cancel.Cancel();
                var report = DatasetCheck.Run(_folder, new DatasetCheckOptions(), null, cancel.Token);
                Assert.That(report.Cancelled, Is.True);
                Assert.That(report.ViewsChecked, Is.EqualTo(0));
                Assert.That(report.Results.Single(r => r.Name == "multi-view geometry").SummaryLine, Is.EqualTo("multi-view geometry: skipped (cancelled)"));
            }
        }

        [Test]
        public void SplitAndMaxViewsChooseTheViews()
        {
            var report = DatasetCheck.Run(_folder, new DatasetCheckOptions { Split = "train", MaxViews = 3 });
            Assert.That(report.ViewsChecked, Is.EqualTo(3));
            Assert.That(report.Failed, Is.False, string.Join("\n", report.SummaryLines));
            Assert.That(report.Results.Single(r => r.Name == "dataset").Figure, Is.EqualTo("3 of 3 views decoded (split train)"));
        }

        [Test]
        public void TheJsonHoldsEveryCheckAndProblem()
        {
            var copy = DatasetFaults.Copy(_folder, _temp.Combine("emptied"));
            DatasetFaults.EditImages(copy, DatasetFaults.IsColour, (png, s, _) => { for (var i = 3; i < s.Length; i += 4) s[i] = 0; });
            var report = DatasetCheck.Run(copy, new DatasetCheckOptions());
            var json = JObject.Parse(report.ToJson());
            Assert.That((bool)json["failed"], Is.True);
            Assert.That(json["checks"].Select(c => (string)c["name"]), Is.EqualTo(report.Results.Select(r => r.Name)));
            Assert.That(json["problems"].Count(), Is.EqualTo(report.Problems.Count));
            var first = json["problems"][0];
            Assert.That((string)first["check"], Is.EqualTo("alpha vs mask"));
            Assert.That((string)first["file"], Is.EqualTo("./train/r_0.png"));
            Assert.That((int)first["frame"], Is.EqualTo(0));
        }

        [Test]
        public void AMissingFolderIsAProblemNotAnException()
        {
            var report = DatasetCheck.Run(Path.Combine(_temp.Path, "nowhere"), new DatasetCheckOptions());
            Assert.That(report.Failed, Is.True);
            Assert.That(report.Problems.Single().Message, Is.EqualTo("is not an existing folder."));
        }
    }
}
