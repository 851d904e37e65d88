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
                Assert.That(ns.WrittenFiles.Select(Path.GetFileName), Is.EquivalentTo(new[] { "transforms.json", "train.json", "val.json", "test.json" }));
                var ngp = DatasetConverter.Export(scene, ExportTarget.Ngp, null);
                Assert.That(Directory.GetFiles(ngp.OutputDirectory, "*.json").Select(Path.GetFileName), Is.EqualTo(new[] { "transforms.json" }),
                    "instant-ngp trains on every json directly in its folder");
                Assert.That(File.Exists(Path.Combine(ngp.OutputDirectory, "camera_paths", "train.json")), Is.True);
            }
        }
    }
}
