using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 32 item 10: the Gaussian Grouping export on hostile labels — more than 65 535 ids, instance ids labels.json
    /// does not list, an 8-bit or truncated instance map — refused naming the file, nothing written.
    /// </summary>
    public class HostileLabelsTests
    {
        static (int code, string err) Convert(string dataset)
        {
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            var code = ConvertCommand.Run(dataset, ExportTarget.GaussianGrouping, null, stdout, stderr);
            return (code, stderr.ToString());
        }

        [Test]
        public void LabelsJsonWithMoreThan65535IdsIsRefusedNamingIt()
        {
            using (var temp = new TempFolder())
            {
                var dataset = LabelledTestDataset.Write(temp.Path);
                var labels = Path.Combine(dataset, DatasetLayout.LabelsFileName);
                var json = JObject.Parse(File.ReadAllText(labels));
                var instances = (JArray)json["instances"];
                var template = (JObject)instances[0];
                for (var id = instances.Count + 1; id <= 65536; id++)
                {
                    var copy = (JObject)template.DeepClone();
                    copy["id"] = id;
                    instances.Add(copy);
                }
                File.WriteAllText(labels, json.ToString());
                var (code, err) = Convert(dataset);
                Assert.That(code, Is.EqualTo(ToolExitCodes.Failure), err);
                Assert.That(err, Does.Contain(labels + ": instances = 65536 entries: has more than the 65535 ids a 16-bit instance or semantic map can hold. Restore labels.json from the capture."));
                Assert.That(Directory.Exists(Path.Combine(dataset, GaussianGrouping.FolderName)), Is.False, "nothing was written");
            }
        }

        [Test]
        public void InstanceIdsLabelsJsonDoesNotListAreAnErrorNamingThemNotBackground()
        {
            using (var temp = new TempFolder())
            {
                var dataset = LabelledTestDataset.Write(temp.Path);
                // Frame 0's map: the objects of LabelledTestDataset plus ids 7 and 900, which labels.json (ids 1…4) does not list.
                var first = LabelledTestDataset.Images(dataset)[0];
                var mapPath = Path.Combine(dataset, LabelledDataset.InstanceMapOf(first));
                var map = new ushort[LabelledTestDataset.Width * LabelledTestDataset.Height];
                for (var i = 0; i < map.Length; i++) map[i] = (ushort)(i == 0 ? 7 : i == 1 ? 900 : LabelledTestDataset.IdAt(0, i % LabelledTestDataset.Width, i / LabelledTestDataset.Width));
                File.WriteAllBytes(mapPath, PngWriter.EncodeGray16(map, LabelledTestDataset.Width, LabelledTestDataset.Height));
                var (code, err) = Convert(dataset);
                Assert.That(code, Is.EqualTo(ToolExitCodes.Failure), err);
                Assert.That(err, Does.Contain(LabelledDataset.InstanceMapOf(first) + " = ids 7, 900: holds instance ids that labels.json does not list, so no export could name their objects."));
                Assert.That(Directory.Exists(Path.Combine(dataset, GaussianGrouping.FolderName)), Is.False, "nothing was written");
            }
        }

        [TestCase(false)]
        [TestCase(true)]
        public void An8BitOrTruncatedInstanceMapIsNamedAsTheInstanceMapNotDepth(bool truncated)
        {
            using (var temp = new TempFolder())
            {
                var dataset = LabelledTestDataset.Write(temp.Path);
                var mapPath = Path.Combine(dataset, LabelledDataset.InstanceMapOf(LabelledTestDataset.Images(dataset)[0]));
                if (truncated)
                {
                    var bytes = File.ReadAllBytes(mapPath);
                    File.WriteAllBytes(mapPath, bytes.Take(bytes.Length / 2).ToArray());
                }
                else File.WriteAllBytes(mapPath, PngWriter.Encode(new byte[LabelledTestDataset.Width * LabelledTestDataset.Height], LabelledTestDataset.Width, LabelledTestDataset.Height, PngPixelFormat.Gray8));
                var (code, err) = Convert(dataset);
                Assert.That(code, Is.EqualTo(ToolExitCodes.Failure), err);
                Assert.That(err, Does.Contain("instance map = " + mapPath + ": "));
                Assert.That(err, Does.Contain("Re-capture the instance map with this plugin (16-bit PNG)."));
                Assert.That(err, Does.Not.Contain("depth"));
            }
        }
    }
}
