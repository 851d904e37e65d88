using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>labels.json, the frame keys, the 16-bit encoding and the preview, as the capture's writers produce them.</summary>
    [TestFixture]
    public class LabelFileTests
    {
        static LabelTable Table() => LabelTable.Build(LabelHierarchy.Settings(InstanceRule.PrefabInstance, ClassSource.Tag, new ClassRule("Vehicle", "car")), LabelHierarchy.Renderers());

        [Test]
        public void LabelsJsonListsEveryInstanceAndClassAndReadsBackTheSame()
        {
            var table = Table();
            var text = LabelsJson.Write(table);
            var json = JObject.Parse(text);
            Assert.That((string)json["format"], Is.EqualTo("nerf-dataset-labels"));
            Assert.That((int)json["background"], Is.EqualTo(0));
            Assert.That(json["classes"].Select(c => (int)c["id"] + ":" + (string)c["name"]), Is.EqualTo(new[] { "1:car" }));
            var first = json["instances"][0];
            Assert.That((int)first["id"], Is.EqualTo(1));
            Assert.That((string)first["name"], Is.EqualTo("Car"));
            Assert.That((string)first["path"], Is.EqualTo("City/Car"));
            Assert.That(first["sibling_path"].Select(v => (int)v), Is.EqualTo(new[] { 0, 0 }));
            Assert.That((int)first["class_id"], Is.EqualTo(1));
            Assert.That((string)first["class"], Is.EqualTo("car"));
            Assert.That((string)first["colour"], Does.Match("^#[0-9a-f]{6}$"));
            Assert.That(json["instances"].Select(i => (int)i["class_id"]), Is.EqualTo(new[] { 1, 0, 1, 0 }), "tree and lamp match no rule");

            var read = LabelsJson.Parse(text, "labels.json");
            Assert.That(LabelsJson.Difference(table, read), Is.Null);
            Assert.That(LabelsJson.Write(read), Is.EqualTo(text));
            Assert.That(read.ClassOfInstance, Is.EqualTo(new ushort[] { 0, 1, 0, 1, 0 }));
        }

        [Test]
        public void ABrokenLabelsJsonIsRefusedNamingTheField()
        {
            var json = JObject.Parse(LabelsJson.Write(Table()));
            json["instances"][2]["id"] = 7;
            json["instances"][1]["class_id"] = 4;
            var e = Assert.Throws<InvalidParameterException>(() => LabelsJson.Parse(json.ToString(), "ds/labels.json"));
            Assert.That(e.Problems.Select(p => p.Field), Is.EqualTo(new[] { "ds/labels.json: instances[1].class_id", "ds/labels.json: instances[2].id" }));
            e = Assert.Throws<InvalidParameterException>(() => LabelsJson.Parse("[1]", "ds/labels.json"));
            Assert.That(e.Message, Does.Contain("not valid JSON"));
        }

        [Test]
        public void DisagreeingTablesSayWhichIdDiffers()
        {
            var a = Table();
            var b = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.PrefabInstance, ClassSource.Tag, new ClassRule("Vehicle", "car")), LabelHierarchy.Renderers().Take(4));
            Assert.That(LabelsJson.Difference(a, b), Is.EqualTo("instance id 4 is \"City/Lamp\" in one and missing in the other"));
            var c = LabelTable.Build(LabelHierarchy.Settings(InstanceRule.Renderer, ClassSource.Tag, new ClassRule("Vehicle", "car")), LabelHierarchy.Renderers());
            Assert.That(LabelsJson.Difference(a, c), Does.StartWith("the label rules differ"));
        }

        [Test]
        public void TheWriterEncodesBothMapsAsSixteenBitGreyNamedByFrameKeys()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "keys", new AnalyticDataset.Options { Labels = true, Train = 2, Val = 1, Test = 1, PointCloud = 0 });
                var frame = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")))["frames"][1];
                Assert.That((string)frame["instance_path"], Is.EqualTo("./train/r_1_instance_0000.png"));
                Assert.That((string)frame["semantic_path"], Is.EqualTo("./train/r_1_semantic_0000.png"));
                var keys = ((JObject)frame).Properties().Select(p => p.Name).ToList();
                Assert.That(keys.IndexOf("instance_path"), Is.EqualTo(keys.IndexOf("mask_path") + 1), "after the other file keys");
                foreach (var kind in new[] { "instance", "semantic" })
                {
                    var png = PngReader.Read(Path.Combine(folder, "train", "r_1_" + kind + "_0000.png"));
                    Assert.That((png.BitDepth, png.ColorType, png.Width, png.Height), Is.EqualTo((16, PngInfo.ColorTypeGray, 96, 72)));
                }
                Assert.That(File.Exists(Path.Combine(folder, "labels.json")), Is.True);
                foreach (var split in new[] { "train", "val", "test" })
                    Assert.That(File.Exists(Path.Combine(folder, "labels_preview_" + split + ".png")), Is.True, split);
                Assert.That(OwnDataset.WhyNotOurs(folder), Is.Null, "every label file is one the plugin writes");
                Assert.That(DatasetValidator.Validate(folder).Problems, Is.Empty);

                // An 8-bit map where the 16-bit one belongs is a validation problem naming the key.
                var instance = Path.Combine(folder, "train", "r_1_instance_0000.png");
                File.WriteAllBytes(instance, PngWriter.Encode(new byte[96 * 72], 96, 72, PngPixelFormat.Gray8));
                Assert.That(DatasetValidator.Validate(folder).Problems.Select(p => p.ToString()),
                    Has.Some.Contains("instance_path ./train/r_1_instance_0000.png is 8-bit"));
            }
        }

        [Test]
        public void ThePreviewPaintsEachIdInItsDisplayColour()
        {
            // Two 3×2 maps side by side: ids 0…5 and 5…0.
            var maps = new[] { new ushort[] { 0, 1, 2, 3, 4, 5 }, new ushort[] { 5, 4, 3, 2, 1, 0 } };
            var png = PngReader.Decode(LabelPreview.Encode(maps, 3, 2), "preview");
            Assert.That((png.Width, png.Height, png.Channels), Is.EqualTo((6, 2, 3)));
            for (var y = 0; y < 2; y++)
                for (var x = 0; x < 6; x++)
                {
                    var id = maps[x / 3][y * 3 + x % 3];
                    LabelColours.Rgb(id, out var r, out var g, out var b);
                    var o = (y * 6 + x) * 3;
                    Assert.That(new[] { png.Samples[o], png.Samples[o + 1], png.Samples[o + 2] }, Is.EqualTo(new[] { r, g, b }), "id " + id);
                }
        }

        [Test]
        public void DisplayColoursAreBlackForTheBackgroundAndDistinctForTheFirstIds()
        {
            Assert.That(LabelColours.Hex(0), Is.EqualTo("#000000"));
            var colours = Enumerable.Range(1, 64).Select(LabelColours.Hex).ToList();
            Assert.That(colours.Distinct().Count(), Is.EqualTo(64));
            Assert.That(colours.Contains("#000000"), Is.False);
            Assert.That(LabelColours.Hex(1), Is.EqualTo(LabelColours.Hex(1)));
        }
    }
}
