using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ImportedSourcePlanTests
    {
        static DatasetSettings WithLegoTest(bool useFileIntrinsics = true)
        {
            var s = new DatasetSettings { Seed = 3, Normalisation = NormalisationMode.Recentre };
            s.Train.Count = 4;
            s.Val.Count = 2;
            s.Test.Source = new CameraSourceSettings { Kind = CameraSourceKind.ImportedPoses, Path = Fixtures.LegoTrainPath, UseFileIntrinsics = useFileIntrinsics };
            s.Camera.VerticalFovDegrees = 60;
            return s;
        }

        [Test]
        public void ImportedLegoCamerasAreWrittenWithTheirExactMatrices()
        {
            var plan = CapturePlan.Build(WithLegoTest(), PlanTarget.AtOrigin);
            var written = JObject.Parse(BlenderTransformsWriter.Write(plan, DatasetSplit.Test));
            var source = JObject.Parse(Fixtures.Text("nerf_synthetic_lego", "transforms_train.json"));
            var expected = (JArray)source["frames"];
            var frames = (JArray)written["frames"];
            Assert.That(frames, Has.Count.EqualTo(100), "one view per camera of the file, whatever the split's count");
            Assert.That(plan.Settings.Test.Count, Is.EqualTo(100));
            for (var i = 0; i < frames.Count; i++)
                Assert.That(frames[i]["transform_matrix"].ToObject<double[][]>(), Is.EqualTo(expected[i]["transform_matrix"].ToObject<double[][]>()), "frame " + i);
            Assert.That((double)written["camera_angle_x"], Is.EqualTo((double)source["camera_angle_x"]).Within(1e-12), "useFileIntrinsics: the file's field of view");
            Assert.That(frames[0]["rotation"].Value<double>(), Is.EqualTo(0.0), "an imported split has no formation step");
            Assert.That(plan.ViewsOf(DatasetSplit.Train).Count(), Is.EqualTo(4), "the other splits keep their formations");
            Assert.That(plan.Warnings.Where(w => w.Field.StartsWith("splits.test", StringComparison.Ordinal)), Is.Empty);
        }

        [Test]
        public void OtherIntrinsicsAreAWarningNotAStop()
        {
            var plan = CapturePlan.Build(WithLegoTest(useFileIntrinsics: false), PlanTarget.AtOrigin);
            var warning = plan.Warnings.Single(w => w.Field == "splits.test.source");
            Assert.That(warning.Reason, Does.Contain("same poses, other pictures"));
            Assert.That(warning.Fix, Does.Contain("useFileIntrinsics"));
        }

        [Test]
        public void ImportedSourceRoundTripsThroughTheConfigFile()
        {
            var s = WithLegoTest();
            s.Test.Source.FileSplit = "train";
            var text = DatasetSettingsJson.Write(s);
            Assert.That(text, Does.Contain("\"kind\": \"imported\""));
            var read = DatasetSettingsJson.Read(text).Settings.Test.Source;
            Assert.That(new object[] { read.Kind, read.Path, read.FileSplit, read.UseFileIntrinsics },
                Is.EqualTo(new object[] { CameraSourceKind.ImportedPoses, Fixtures.LegoTrainPath, "train", true }));
            Assert.That(DatasetSettingsJson.Write(new DatasetSettings()), Does.Not.Contain("\"source\""), "formation splits write no source: old configs stay as they were");
            var bad = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{\"splits\": {\"test\": {\"source\": {\"kind\": \"spline\"}}}}"));
            Assert.That(bad.Message, Does.Contain("splits.test.source.kind"));
        }

        [Test]
        public void BadSourcesNameTheFieldAndTheFix()
        {
            var s = WithLegoTest();
            s.Test.Source.Path = "";
            Assert.That(CapturePlan.Check(s, PlanTarget.AtOrigin).Select(p => p.Field), Does.Contain("splits.test.source.path"));
            s.Test.Source.Path = Path.Combine(Path.GetTempPath(), "no-such-file-" + Guid.NewGuid().ToString("N") + ".json");
            Assert.That(CapturePlan.Check(s, PlanTarget.AtOrigin).Single().Reason, Does.Contain("neither a file nor a folder"));
            s.Test.Source.Path = Fixtures.LegoTrainPath;
            s.Test.Source.FileSplit = "val";
            var none = CapturePlan.Check(s, PlanTarget.AtOrigin).Single();
            Assert.That(none.Field, Is.EqualTo("splits.test.source.fileSplit"));
            Assert.That(none.Reason, Does.Contain("none of the 100 cameras"));
            s.Test.Source.FileSplit = "";
            s.Camera.CopyFromCamera = "Main Camera";
            Assert.That(CapturePlan.Check(s, PlanTarget.AtOrigin).Single().Field, Is.EqualTo("splits.test.source.useFileIntrinsics"));
        }

        [Test]
        public void OnlyImportedSplitsSkipTheFormationDistanceChecks()
        {
            var s = WithLegoTest();
            foreach (var split in new[] { s.Train, s.Val })
                split.Source = new CameraSourceSettings { Kind = CameraSourceKind.ImportedPoses, Path = Fixtures.LegoTrainPath };
            s.Distance = 0.5; // inside a target of radius 1: wrong for a formation, irrelevant to imported cameras
            Assert.That(CapturePlan.Check(s, new PlanTarget(Vector3d.Zero, 1)), Is.Empty);
        }
    }
}
