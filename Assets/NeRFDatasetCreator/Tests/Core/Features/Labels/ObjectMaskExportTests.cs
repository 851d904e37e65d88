using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// convert --to nerfstudio --object read back the way nerfstudio reads it (nerfstudio-project/nerfstudio 50e0e3c):
    /// nerfstudio_dataparser.py:171-178 and :185-187 (mask_path per frame, resolved against the transforms file's folder,
    /// on all frames or none) and data/utils/data_utils.py:59-71 (one channel, <c>.bool()</c>: non-zero = train on the
    /// pixel); the errors through the command as a user meets them.
    /// </summary>
    public class ObjectMaskExportTests
    {
        /// <summary>get_image_mask_tensor_from_path: PIL → array → bool; more than one channel raises.</summary>
        static bool[,] NerfstudioMask(string path)
        {
            var png = PngReader.Read(path);
            Assert.That(png.Channels, Is.EqualTo(1), path + ": \"The mask image should have 1 channel\"");
            var mask = new bool[png.Height, png.Width];
            var bytesPerSample = png.BitDepth / 8;
            for (var y = 0; y < png.Height; y++)
                for (var x = 0; x < png.Width; x++)
                {
                    var at = (y * png.Width + x) * bytesPerSample;
                    mask[y, x] = png.Samples[at] != 0 || (bytesPerSample == 2 && png.Samples[at + 1] != 0);
                }
            return mask;
        }

        static (int code, string stdout, string stderr) Convert(string dataset, ExportTarget target, string objectName, string outDir = null)
        {
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            var code = ConvertCommand.Run(dataset, target, outDir, stdout, stderr, objectName: objectName);
            return (code, stdout.ToString(), stderr.ToString());
        }

        [Test]
        public void TheMasksKeepExactlyThePixelsOfTheNamedObject()
        {
            using (var temp = new TempFolder())
            {
                var dataset = LabelledTestDataset.Write(temp.Path);
                var (code, stdout, stderr) = Convert(dataset, ExportTarget.Nerfstudio, "Tree");
                Assert.That(code, Is.EqualTo(ToolExitCodes.Success), stderr);
                var output = Path.Combine(dataset, "object_2");
                var transforms = JObject.Parse(File.ReadAllText(Path.Combine(output, "transforms.json")));
                var frames = (JArray)transforms["frames"];
                var images = LabelledTestDataset.Images(dataset);
                Assert.That(frames, Has.Count.EqualTo(images.Count));
                Assert.That(frames.All(f => f["mask_path"] != null), "mask_path on every frame (nerfstudio_dataparser.py:185-187)");
                foreach (var frame in frames)
                {
                    // _get_fname: data_dir / path, data_dir being the transforms file's folder.
                    var image = Path.GetFullPath(Path.Combine(output, (string)frame["file_path"]));
                    var index = images.FindIndex(i => Path.GetFullPath(Path.Combine(dataset, i)) == image);
                    Assert.That(index, Is.GreaterThanOrEqualTo(0), "file_path names the dataset's own image: " + frame["file_path"]);
                    var mask = NerfstudioMask(Path.GetFullPath(Path.Combine(output, (string)frame["mask_path"])));
                    Assert.That(mask.GetLength(0), Is.EqualTo(LabelledTestDataset.Height), "the mask has the image's shape (base_dataset.py:156)");
                    Assert.That(mask.GetLength(1), Is.EqualTo(LabelledTestDataset.Width));
                    for (var y = 0; y < LabelledTestDataset.Height; y++)
                        for (var x = 0; x < LabelledTestDataset.Width; x++)
                            Assert.That(mask[y, x], Is.EqualTo(LabelledTestDataset.IdAt(index, x, y) == 2), frame["file_path"] + " (" + x + ", " + y + ")");
                }
                // The Tree is only in the even frames: the odd ones are named in a warning.
                Assert.That(stderr, Does.Contain("warning: ").And.Contain("not visible in 3 of 6 views"));
                Assert.That(stdout, Does.Contain("train with:"));
            }
        }

        [Test]
        public void AnIdOrAPathWorksAsWellAsAName()
        {
            using (var temp = new TempFolder())
            {
                var dataset = LabelledTestDataset.Write(temp.Path);
                Assert.That(Convert(dataset, ExportTarget.Nerfstudio, "4").code, Is.EqualTo(ToolExitCodes.Success));
                Assert.That(File.Exists(Path.Combine(dataset, "object_4", "transforms.json")));
                Assert.That(Convert(dataset, ExportTarget.Nerfstudio, "City/Tree", temp.Combine("tree")).code, Is.EqualTo(ToolExitCodes.Success));
                var frame = JObject.Parse(File.ReadAllText(temp.Combine("tree", "transforms.json")))["frames"][0];
                // An output outside the dataset holds copies of the images under their dataset paths (convert --images, default copy there).
                Assert.That((string)frame["file_path"], Is.EqualTo("train/r_0.png"));
                Assert.That(File.Exists(temp.Combine("tree", "train", "r_0.png")), Is.True);
                Assert.That(File.Exists(Path.Combine(temp.Combine("tree"), (string)frame["mask_path"])), Is.True, "the object's mask, written into the export");
            }
        }

        [Test]
        public void AnAmbiguousNameListsTheObjectsItNames()
        {
            using (var temp = new TempFolder())
            {
                var dataset = LabelledTestDataset.Write(temp.Path);
                var (code, _, stderr) = Convert(dataset, ExportTarget.Nerfstudio, "Car");
                Assert.That(code, Is.EqualTo(ToolExitCodes.Failure));
                Assert.That(stderr, Does.Contain("error: --object").And.Contain("names 2 objects").And.Contain("id 1 \"City/Car\"").And.Contain("id 3 \"City/Car\""));
                Assert.That(Directory.GetDirectories(dataset, "object_*"), Is.Empty, "nothing was written");
            }
        }

        [Test]
        public void AnUnknownNameSuggestsTheClosestAndAnUnknownIdSaysTheRange()
        {
            using (var temp = new TempFolder())
            {
                var dataset = LabelledTestDataset.Write(temp.Path);
                var (code, _, stderr) = Convert(dataset, ExportTarget.Nerfstudio, "Tre");
                Assert.That(code, Is.EqualTo(ToolExitCodes.Failure));
                Assert.That(stderr, Does.Contain("error: --object").And.Contain("Did you mean \"Tree\"?"));
                var byId = Convert(dataset, ExportTarget.Nerfstudio, "9");
                Assert.That(byId.code, Is.EqualTo(ToolExitCodes.Failure));
                Assert.That(byId.stderr, Does.Contain("ids 1 to 4"));
            }
        }

        [Test]
        public void ADatasetWithoutLabelsIsRefused()
        {
            using (var temp = new TempFolder())
            {
                var dataset = LabelledTestDataset.Write(temp.Path, labels: false);
                var (code, _, stderr) = Convert(dataset, ExportTarget.Nerfstudio, "Tree");
                Assert.That(code, Is.EqualTo(ToolExitCodes.Failure));
                Assert.That(stderr, Does.Contain("error: --object").And.Contain("labels.json"));
            }
        }

        [Test]
        public void TheCommandLineTakesObjectOnlyWithNerfstudio()
        {
            var ok = ToolCommandLine.Parse(new[] { "convert", "d", "--to", "nerfstudio", "--object", "Car 2" });
            Assert.That(ok.Errors, Is.Empty);
            Assert.That(((ConvertCommand.Options)ok.Options).ObjectName, Is.EqualTo("Car 2"));
            var wrong = ToolCommandLine.Parse(new[] { "convert", "d", "--to", "colmap", "--object", "Car" });
            Assert.That(wrong.Errors.Single(), Does.Contain("--to nerfstudio"));
            Assert.That(((ConvertCommand.Options)ToolCommandLine.Parse(new[] { "convert", "d", "--to", "gaussian-grouping" }).Options).Target, Is.EqualTo(ExportTarget.GaussianGrouping));
        }

        [Test]
        public void AMaskIs255OnTheObjectsIdAndAUniqueNameIsFoundInAnyCase()
        {
            var table = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.PrefabInstance, ClassSource.Tag), LabelHierarchy.Renderers());
            var mask = ObjectMaskExport.Mask(new ushort[] { 0, 1, 2, 1 }, 1);
            Assert.That(mask, Is.EqualTo(new byte[] { 0, 255, 0, 255 }));
            Assert.That(ObjectSelection.Find(table, "Lamp").Id, Is.EqualTo(4));
            Assert.That(ObjectSelection.Find(table, "lamp").Id, Is.EqualTo(4), "a name differing only in case still finds the one object");
        }
    }
}
