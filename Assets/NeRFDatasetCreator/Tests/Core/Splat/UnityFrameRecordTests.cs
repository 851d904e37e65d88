using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// dataset_config.json's unity_frame: the matrix undoes the normalisation and the axis swap (hand-derived entries),
    /// the Editor's facts are written and read back, a config without them holds nulls, an old config without the key
    /// derives it, a malformed one is refused naming the field, and convert's nerfstudio and ngp files carry it.
    /// </summary>
    [TestFixture]
    public class UnityFrameRecordTests
    {
        static readonly DateTime Created = new DateTime(2026, 12, 7, 0, 0, 0, DateTimeKind.Utc);

        static CapturePlan Plan()
        {
            var s = new DatasetSettings { Seed = 5, Name = "frame" };
            s.Train.Count = 3;
            s.Val.Count = 1;
            s.Test.Count = 1;
            return CapturePlan.Build(s, new PlanTarget(new Vector3d(1, 2, 3), 0.75));
        }

        [Test]
        public void TheMatrixIsTheNormalisationUndoneWithTheAxesSwappedBack()
        {
            var plan = Plan();
            var config = JObject.Parse(DatasetConfig.Write(plan, new Provenance(Created)));
            var frame = (JObject)config[UnityFrameRecord.Key];
            var k = 1 / plan.Normalisation.Scale;
            // x_out = s·((x, z, y) − (1, 3, 2)) ⇒ x_unity = (x_out.x / s + 1, x_out.z / s + 2, x_out.y / s + 3).
            Assert.That(frame["output_to_unity"].ToObject<double[][]>(), Is.EqualTo(new[]
            {
                new[] { k, 0, 0, 1.0 }, new[] { 0, 0, k, 2.0 }, new[] { 0, k, 0, 3.0 }, new[] { 0, 0, 0, 1.0 },
            }).Within(1e-12));
            Assert.That((double)frame["determinant"], Is.EqualTo(-k * k * k).Within(1e-12));
            Assert.That((string)frame["determinant_sign"], Does.StartWith("negative"));
            foreach (var key in new[] { "target_scene_path", "target_global_object_id", "target_local_to_world", "color_space" })
                Assert.That(frame[key].Type, Is.EqualTo(JTokenType.Null), key + " is unknown outside the Editor");
            // A Unity point goes out through the normalisation and comes back through the matrix.
            var unity = new Vector3d(1.5, 2.25, 2.5);
            var back = new DatasetConfig(config).UnityFrame.OutputToUnity.MultiplyPoint(plan.Normalisation.ApplyToUnityPoint(unity));
            Assert.That(Vector3d.Distance(back, unity), Is.LessThan(1e-12));
        }

        [Test]
        public void TheEditorsFactsAreWrittenAndReadBack()
        {
            var provenance = new Provenance(Created, "2022.3.45f1", "unity-editor")
            {
                UnityFrame = new UnityFrameFacts("Assets/Scenes/Lego.unity:/Root/Lego", "GlobalObjectId_V1-2-abc-123-0",
                    new double[] { 2, 0, 0, 1, 0, 2, 0, 2, 0, 0, 2, 3, 0, 0, 0, 1 }, "Linear"),
            };
            var config = DatasetConfig.Parse(DatasetConfig.Write(Plan(), provenance));
            var frame = config.Json[UnityFrameRecord.Key];
            Assert.That((string)frame["target_scene_path"], Is.EqualTo("Assets/Scenes/Lego.unity:/Root/Lego"));
            Assert.That((string)frame["color_space"], Is.EqualTo("Linear"));
            Assert.That(frame["target_local_to_world"][0].ToObject<double[]>(), Is.EqualTo(new double[] { 2, 0, 0, 1 }));
            var read = config.UnityFrame;
            Assert.That(read.Derived, Is.False);
            Assert.That(read.Facts.TargetGlobalObjectId, Is.EqualTo("GlobalObjectId_V1-2-abc-123-0"));
            Assert.That(read.Facts.TargetLocalToWorld, Is.EqualTo(new double[] { 2, 0, 0, 1, 0, 2, 0, 2, 0, 0, 2, 3, 0, 0, 0, 1 }));
            Assert.That(read.Facts.ColorSpace, Is.EqualTo("Linear"));
        }

        [Test]
        public void AnOldConfigDerivesTheSameMatrixFromSceneNormalisation()
        {
            var json = JObject.Parse(DatasetConfig.Write(Plan(), new Provenance(Created)));
            var recorded = new DatasetConfig(json).UnityFrame.OutputToUnity;
            json.Remove(UnityFrameRecord.Key);
            var derived = new DatasetConfig(json).UnityFrame;
            Assert.That(derived.Derived, Is.True);
            Assert.That(derived.DerivedFrom, Is.EqualTo("dataset_config.json's scene_normalisation"));
            Assert.That(derived.OutputToUnity, Is.EqualTo(recorded));
            json.Remove(BlenderTransformsWriter.SceneNormalisationKey);
            Assert.That(new DatasetConfig(json).UnityFrame, Is.Null);
        }

        [TestCase("\"unity_frame\": 3")]
        [TestCase("\"unity_frame\": { \"output_to_unity\": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]] }")]
        [TestCase("\"unity_frame\": { \"output_to_unity\": [[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]] }")]
        [TestCase("\"unity_frame\": { \"output_to_unity\": [[1, 0, 0, \"a\"], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] }")]
        public void AMalformedRecordIsRefusedNamingTheField(string record)
        {
            var config = DatasetConfig.Parse("{ " + record + " }");
            var e = Assert.Throws<InvalidParameterException>(() => _ = config.UnityFrame);
            Assert.That(e.Problems.Single().Field, Is.EqualTo("dataset_config.json: unity_frame.output_to_unity"));
            Assert.That(e.Problems.Single().Fix, Does.Contain("Remove the unity_frame key"));
        }

        [TestCase(ExportTarget.Nerfstudio, "transforms.json")]
        [TestCase(ExportTarget.Ngp, "ngp/transforms.json")]
        public void ConvertCarriesTheRecord(ExportTarget target, string file)
        {
            using (var temp = new TempFolder())
            {
                var dataset = AnalyticDataset.Write(temp.Path, "frame", new AnalyticDataset.Options { Width = 32, Height = 24, Train = 3, Val = 1, Test = 1, PointCloud = 50 });
                var recorded = JObject.Parse(File.ReadAllText(Path.Combine(dataset, DatasetLayout.ConfigFileName)))[UnityFrameRecord.Key];
                Assert.That(recorded, Is.Not.Null);
                DatasetConverter.Convert(dataset, target);
                var carried = JObject.Parse(File.ReadAllText(Path.Combine(dataset, file)))[UnityFrameRecord.Key];
                Assert.That(JToken.DeepEquals(carried, recorded), Is.True, carried?.ToString());
            }
        }
    }
}
