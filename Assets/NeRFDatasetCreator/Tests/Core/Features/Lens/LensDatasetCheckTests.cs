using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A dataset taken through a lens — rendered analytically along each distorted pixel's ray, or through the capture's
    /// own wide render and <see cref="LensResampler"/> — passes every check, because the projecting checks use the lens
    /// its transforms files declare; the same dataset with wrong lens keys (k1's sign flipped, the coefficients left
    /// out) fails them.
    /// </summary>
    [TestFixture]
    public class LensDatasetCheckTests
    {
        TempFolder _temp;
        string _barrel;
        int _copies;

        static readonly string[] AllChecks = { "alpha vs mask", "depth vs mask", "depth vs normals", "multi-view geometry", "point cloud vs masks", "colour vs geometry" };

        /// <summary>A barrel lens with tangential terms, as a wide action camera's.</summary>
        static LensSettings Barrel() => new LensSettings { Model = "opencv", K1 = -0.2, K2 = 0.04, P1 = 0.004, P2 = -0.003 };

        /// <summary>A 70° view from close by, so the scene fills the frame where the lens bends most.</summary>
        static AnalyticDataset.Options Wide(LensSettings lens, bool throughWideRender = false) =>
            new AnalyticDataset.Options { Lens = lens, ThroughWideRender = throughWideRender, DataAtOutputSize = !throughWideRender, VerticalFovDegrees = 70, Distance = 1.8, Width = 128, Height = 96 };

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _barrel = AnalyticDataset.Write(_temp.Path, "barrel", Wide(Barrel()));
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        static DatasetCheckReport Check(string folder)
        {
            var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            TestContext.WriteLine(string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(12)));
            return report;
        }

        static void AssertClean(DatasetCheckReport report)
        {
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems);
            Assert.That(report.Problems, Is.Empty, text);
            foreach (var name in AllChecks)
                Assert.That(report.Results.Single(r => r.Name == name).Status, Is.EqualTo(DatasetCheckStatus.Passed), name + "\n" + text);
        }

        [Test]
        public void TheWrittenKeysAreTheLens()
        {
            var json = JObject.Parse(File.ReadAllText(Path.Combine(_barrel, "transforms_train.json")));
            Assert.That((string)json["camera_model"], Is.EqualTo("OPENCV"));
            Assert.That((double)json["k1"], Is.EqualTo(-0.2));
            Assert.That((double)json["k2"], Is.EqualTo(0.04));
            Assert.That((double)json["p1"], Is.EqualTo(0.004));
            Assert.That((double)json["p2"], Is.EqualTo(-0.003));
            Assert.That(json["k3"], Is.Null, "k3 = 0 is not written (instant-ngp would store p1 over it anyway)");
            var split = DatasetFolder.ReadSplit(_barrel, "train", DatasetReadMode.Strict);
            Assert.That(split.LensProblems, Is.Empty);
            Assert.That(TransformsLens.Same(split.Lens, Barrel().ToDistortion()), Is.True);
            var config = JObject.Parse(File.ReadAllText(Path.Combine(_barrel, "dataset_config.json")));
            Assert.That((string)config["settings"]["lens"]["model"], Is.EqualTo("opencv"));
            Assert.That((double)config["settings"]["lens"]["k1"], Is.EqualTo(-0.2));
            var validation = DatasetValidator.Validate(_barrel);
            Assert.That(validation.Problems.Select(p => p.ToString()), Is.Empty, "nerf-dataset validate accepts the lens keys");
            // convert reads the same keys and carries the lens (ConvertLensTests covers each target's file).
            var converted = DatasetConverter.Convert(_barrel, ExportTarget.Nerfstudio, _temp.Combine("barrel-ns"));
            var ns = JObject.Parse(File.ReadAllText(converted.MainFile));
            Assert.That((string)ns["camera_model"], Is.EqualTo("OPENCV"));
            Assert.That((double)ns["k1"], Is.EqualTo(-0.2));
            Assert.That((double)ns["p2"], Is.EqualTo(-0.003));
        }

        [Test]
        public void DistortedDatasetPasses() => AssertClean(Check(_barrel));

        [Test]
        public void DatasetThroughTheWideRenderPasses()
        {
            var folder = AnalyticDataset.Write(_temp.Path, "wide", Wide(Barrel(), true));
            AssertClean(Check(folder));
        }

        [Test]
        public void FisheyeDatasetThroughTheWideRenderPasses()
        {
            var lens = new LensSettings { Model = "opencv_fisheye", K1 = 0.05, K2 = -0.01, K3 = 0.002, K4 = 0 };
            var folder = AnalyticDataset.Write(_temp.Path, "fisheye", Wide(lens, true));
            var json = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")));
            Assert.That((string)json["camera_model"], Is.EqualTo("OPENCV_FISHEYE"));
            Assert.That((bool)json["is_fisheye"], Is.True);
            Assert.That(json["p1"], Is.Null);
            AssertClean(Check(folder));
        }

        [Test]
        public void FisheyeDatasetPasses()
        {
            var lens = new LensSettings { Model = "opencv_fisheye", K1 = 0.05, K2 = -0.01, K3 = 0.002, K4 = 0 };
            AssertClean(Check(AnalyticDataset.Write(_temp.Path, "fisheye-direct", Wide(lens))));
        }

        [Test]
        public void FlippedK1IsCaught()
        {
            var folder = EditKeys(json => json["k1"] = 0.2);
            var report = Check(folder);
            Assert.That(report.Failed, Is.True);
            AssertFailed(report, "multi-view geometry");
            AssertFailed(report, "point cloud vs masks");
        }

        [Test]
        public void MissingCoefficientsAreCaught()
        {
            var folder = EditKeys(json =>
            {
                foreach (var key in new[] { "camera_model", "k1", "k2", "p1", "p2" }) json.Remove(key);
            });
            var report = Check(folder);
            Assert.That(report.Failed, Is.True);
            AssertFailed(report, "multi-view geometry");
            AssertFailed(report, "point cloud vs masks");
        }

        static void AssertFailed(DatasetCheckReport report, string check)
        {
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(20));
            Assert.That(report.Results.Single(r => r.Name == check).Status, Is.EqualTo(DatasetCheckStatus.Failed), check + "\n" + text);
        }

        string EditKeys(System.Action<JObject> edit)
        {
            var folder = DatasetFaults.Copy(_barrel, _temp.Combine("keys-" + ++_copies));
            foreach (var split in DatasetSplits.Names)
            {
                var path = Path.Combine(folder, "transforms_" + split + ".json");
                var json = JObject.Parse(File.ReadAllText(path));
                edit(json);
                File.WriteAllText(path, json.ToString());
            }
            return folder;
        }
    }
}
