using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The records check: an analytic dataset's records agree; a hand-edit of one record and not the other (unity_frame,
    /// a split's scene_normalisation, eval_protocol.json's background) is caught, naming the file.
    /// </summary>
    [TestFixture]
    public class RecordsCheckTests
    {
        TempFolder _temp;
        string _clean;
        int _copies;

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _clean = AnalyticDataset.Write(_temp.Path, "clean", new AnalyticDataset.Options { Width = 32, Height = 24, Train = 3, Val = 1, Test = 1, PointCloud = 0 });
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        string Copy() => DatasetFaults.Copy(_clean, _temp.Combine("fault-" + ++_copies));

        static DatasetCheckResult Records(string folder, out DatasetCheckReport report)
        {
            report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            return report.Results.Single(r => r.Name == RecordsCheck.CheckName);
        }

        static void Edit(string path, System.Action<JObject> edit)
        {
            var json = JObject.Parse(File.ReadAllText(path));
            edit(json);
            File.WriteAllText(path, json.ToString());
        }

        [Test]
        public void TheAnalyticDatasetsRecordsAgree()
        {
            var result = Records(_clean, out _);
            Assert.That(result.Status, Is.EqualTo(DatasetCheckStatus.Passed), result.SummaryLine);
            Assert.That(result.Figure, Does.Contain("0 of 5").And.Contain("unity_frame").And.Contain("eval_protocol.json"), "unity_frame, three splits and the protocol compared");
        }

        [Test]
        public void AnEditedUnityFrameIsCaught()
        {
            var folder = Copy();
            Edit(Path.Combine(folder, DatasetLayout.ConfigFileName), j => j["unity_frame"]["output_to_unity"][0][3] = (double)j["unity_frame"]["output_to_unity"][0][3] + 0.01);
            var result = Records(folder, out var report);
            Assert.That(result.Status, Is.EqualTo(DatasetCheckStatus.Failed));
            Assert.That(report.Problems.Single(p => p.Check == RecordsCheck.CheckName).ToString(), Does.Contain("dataset_config.json").And.Contain("unity_frame.output_to_unity differs"));
        }

        [Test]
        public void ASplitFromAnotherNormalisationIsCaught()
        {
            var folder = Copy();
            Edit(DatasetFolder.SplitPath(folder, "test"), j => j["scene_normalisation"]["scale"] = 0.5);
            var result = Records(folder, out var report);
            Assert.That(result.Status, Is.EqualTo(DatasetCheckStatus.Failed));
            Assert.That(report.Problems.Single(p => p.Check == RecordsCheck.CheckName).File, Is.EqualTo("transforms_test.json"));
        }

        [Test]
        public void AProtocolBackgroundTheSettingsDoNotGiveIsCaught()
        {
            var folder = Copy();
            Edit(Path.Combine(folder, EvalProtocolFile.FileName), j =>
            {
                j["background"] = "black";
                j["background_rgb"] = new JArray(0, 0, 0);
            });
            var result = Records(folder, out var report);
            Assert.That(result.Status, Is.EqualTo(DatasetCheckStatus.Failed));
            var problem = report.Problems.Single(p => p.Check == RecordsCheck.CheckName);
            Assert.That(problem.File, Is.EqualTo(EvalProtocolFile.FileName));
            Assert.That(problem.ToString(), Does.Contain("black (#000000)").And.Contain("white (#ffffff)"));
        }

        [Test]
        public void ADatasetWithoutRecordsIsSkippedWithTheReason()
        {
            var folder = Copy();
            File.Delete(Path.Combine(folder, DatasetLayout.ConfigFileName));
            Assert.That(Records(folder, out _).Status, Is.EqualTo(DatasetCheckStatus.Skipped));
        }
    }
}
