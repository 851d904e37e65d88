using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class CameraPathFilesTests
    {
        [Test]
        public void ConvertingLegoWritesEachSplitsCameraPathOutsideNgpsTrainingFolder()
        {
            using (var lego = new LegoDataset())
            {
                var scene = BlenderDatasetLoader.Load(lego.Root);
                var ns = DatasetConverter.Export(scene, ExportTarget.Nerfstudio, null);
                var test = JObject.Parse(File.ReadAllText(Path.Combine(lego.Root, "camera_paths", "test.json")));
                Assert.That(test["camera_path"], Has.Count.EqualTo(LegoDataset.TestCount));
                Assert.That(test["camera_path"].Any(c => c["render_time"] != null), Is.False, "a still dataset has no times");
                Assert.That(ns.WrittenFiles.Select(Path.GetFileName), Is.EquivalentTo(new[] { "transforms.json", "train.json", "val.json", "test.json" }));
                var ngp = DatasetConverter.Export(scene, ExportTarget.Ngp, null);
                Assert.That(Directory.GetFiles(ngp.OutputDirectory, "*.json").Select(Path.GetFileName), Is.EqualTo(new[] { "transforms.json" }),
                    "instant-ngp trains on every json directly in its folder");
                Assert.That(File.Exists(Path.Combine(ngp.OutputDirectory, "camera_paths", "train.json")), Is.True);
            }
        }
    
        [Test]
        public void ADynamicCapturesNerfstudioPathCarriesEachFramesTimeAsRenderTime()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                var s = new DatasetSettings { Width = 16, Height = 12 };
                s.Train.Count = 5;
                s.Val.Count = 3;
                s.Test.Count = 3;
                s.Time.Mode = TimeMode.Monocular;
                s.Time.StartSeconds = 0;
                s.Time.EndSeconds = 2;
                TestDatasets.FromPlan(folder, CapturePlan.Build(s, new PlanTarget(Vector3d.Zero, 0.5)));
                DatasetConverter.Convert(folder, ExportTarget.Nerfstudio);
                foreach (var split in new[] { "train", "test" })
                {
                    var frames = (JArray)JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_" + split + ".json")))["frames"];
                    var path = (JArray)JObject.Parse(File.ReadAllText(Path.Combine(folder, "camera_paths", split + ".json")))["camera_path"];
                    Assert.That(path.Select(c => (double)c["render_time"]), Is.EqualTo(frames.Select(f => (double)f["time"])), split);
                }
                // Train view i of 5 is at time i/4 (dynamic-capture.md): the path renders the model at those times.
                var train = (JArray)JObject.Parse(File.ReadAllText(Path.Combine(folder, "camera_paths", "train.json")))["camera_path"];
                Assert.That(train.Select(c => (double)c["render_time"]), Is.EqualTo(new[] { 0, 0.25, 0.5, 0.75, 1.0 }));
            }
        }

        [Test]
        public void RenderTimeIsWrittenOnlyWhenEveryCameraHasATime()
        {
            var k = CameraIntrinsics.FromVerticalFov(40, 16, 12);
            var poses = new[] { Matrix4x4d.Identity, Matrix4x4d.Identity };
            var partial = NerfstudioCameraPath.Build(poses, k, times: new double?[] { 0, null });
            Assert.That(partial["camera_path"].Any(c => c["render_time"] != null), Is.False);
            var full = NerfstudioCameraPath.Build(poses, k, times: new double?[] { 0, 1 });
            Assert.That(full["camera_path"].Select(c => (double)c["render_time"]), Is.EqualTo(new[] { 0.0, 1.0 }));
        }
    }
}
