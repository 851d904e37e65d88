using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// convert --to gaussian-grouping read back the way Gaussian Grouping's loader reads it (lkeab/gaussian-grouping
    /// 0ab60af): scene/__init__.py:43-44 (a source with sparse/ is COLMAP), scene/dataset_readers.py:95-99 (mask =
    /// object_mask/&lt;basename up to the first dot&gt;.png), :144-146 (folder object_mask), :149-160 (--train_split names),
    /// utils/camera_utils.py:54 (np.array of the PIL image, not resized), train.py:84-90 + :235 (class indices below
    /// num_classes from the config file, default 200).
    /// </summary>
    public class GaussianGroupingExportTests
    {
        /// <summary>images.txt of COLMAP's text model: the NAME (10th field) of every image line (every other non-comment line).</summary>
        static List<string> ColmapImageNames(string sparse)
        {
            var lines = File.ReadAllLines(Path.Combine(sparse, "images.txt")).Where(l => !l.StartsWith("#", StringComparison.Ordinal)).ToList();
            var names = new List<string>();
            for (var i = 0; i < lines.Count; i += 2)
            {
                if (lines[i].Trim().Length == 0) continue;
                names.Add(lines[i].Split(' ')[9]);
            }
            return names;
        }

        /// <summary><c>os.path.basename(image_path).split(".")[0]</c> (dataset_readers.py:96), written here from the Python.</summary>
        static string LoaderImageName(string name) => Path.GetFileName(name).Split('.')[0];

        /// <summary>
        /// <c>np.array(Image.open(path))</c> for the masks a loader can train on: PIL opens an 8-bit grey PNG as mode "L",
        /// a 2-D uint8 array (rows top first). Anything else would not be a class-index map.
        /// </summary>
        static byte[,] LoaderMask(string path)
        {
            var png = PngReader.Read(path);
            Assert.That(png.BitDepth, Is.EqualTo(8), path + ": 8-bit");
            Assert.That(png.ColorType, Is.EqualTo(PngInfo.ColorTypeGray), path + ": one grey channel");
            var array = new byte[png.Height, png.Width];
            for (var y = 0; y < png.Height; y++)
                for (var x = 0; x < png.Width; x++)
                    array[y, x] = png.Samples[y * png.Width + x];
            return array;
        }

        [Test]
        public void EveryImageHasItsObjectMaskWithTheDatasetsObjectsAsClassIndices()
        {
            using (var temp = new TempFolder())
            {
                var dataset = LabelledTestDataset.Write(temp.Path);
                var result = DatasetConverter.Convert(dataset, ExportTarget.GaussianGrouping);
                var source = Path.Combine(dataset, GaussianGrouping.FolderName);
                Assert.That(result.OutputDirectory, Is.EqualTo(source));
                Assert.That(Directory.Exists(Path.Combine(source, "sparse")), "scene/__init__.py:43: sparse/ makes it a COLMAP source");

                // train.py:235: num_classes = config.get("num_classes", 200) from the --config_file JSON.
                var config = JObject.Parse(File.ReadAllText(Path.Combine(source, GaussianGrouping.ConfigFileName)));
                var numClasses = config["num_classes"] != null ? (int)config["num_classes"] : 200;
                Assert.That(numClasses, Is.EqualTo(256));

                var ids = JObject.Parse(File.ReadAllText(Path.Combine(source, GaussianGrouping.ObjectIndexFileName)));
                var instanceOfValue = new Dictionary<int, int> { [0] = 0 };
                foreach (var o in (JArray)ids["objects"]) instanceOfValue[(int)o["value"]] = (int)o["instance_id"];
                Assert.That(instanceOfValue.Keys.OrderBy(v => v), Is.EqualTo(new[] { 0, 1, 2, 3, 4 }), "the 4 objects of labels.json, 1…4");

                var images = LabelledTestDataset.Images(dataset);
                var names = ColmapImageNames(Path.Combine(source, "sparse", "0"));
                Assert.That(names, Has.Count.EqualTo(images.Count));
                foreach (var name in names)
                {
                    // dataset_readers.py:95-98: the mask of image NAME.
                    var maskPath = Path.Combine(source, "object_mask", LoaderImageName(name) + ".png");
                    Assert.That(File.Exists(maskPath), maskPath);
                    var mask = LoaderMask(maskPath);
                    // camera_utils.py:54 keeps the mask unresized: it must be the image's size (the render's at -r 1).
                    var image = PngReader.Read(Path.Combine(source, "images", name));
                    Assert.That(mask.GetLength(0), Is.EqualTo(image.Height));
                    Assert.That(mask.GetLength(1), Is.EqualTo(image.Width));
                    // The flattened COLMAP name train_r_0.png is the dataset's train/r_0.png.
                    var frame = images.FindIndex(i => i.Replace('/', '_') == name);
                    Assert.That(frame, Is.GreaterThanOrEqualTo(0), name);
                    for (var y = 0; y < mask.GetLength(0); y++)
                        for (var x = 0; x < mask.GetLength(1); x++)
                        {
                            Assert.That(mask[y, x], Is.LessThan(numClasses), "CrossEntropyLoss needs class indices below num_classes");
                            Assert.That(instanceOfValue[mask[y, x]], Is.EqualTo(LabelledTestDataset.IdAt(frame, x, y)), name + " (" + x + ", " + y + ")");
                        }
                }
            }
        }

        [Test]
        public void TheTrainSplitFolderNamesExactlyTheTrainImages()
        {
            using (var temp = new TempFolder())
            {
                var dataset = LabelledTestDataset.Write(temp.Path);
                var result = DatasetConverter.Convert(dataset, ExportTarget.GaussianGrouping);
                var source = result.OutputDirectory;
                // dataset_readers.py:150-160: train = images whose name (up to the first dot) is listed in images_train/.
                var trainNames = Directory.GetFiles(Path.Combine(source, GaussianGrouping.TrainSplitFolder)).Select(f => LoaderImageName(f)).OrderBy(n => n).ToList();
                var allNames = ColmapImageNames(Path.Combine(source, "sparse", "0")).Select(LoaderImageName).ToList();
                var train = allNames.Where(trainNames.Contains).ToList();
                var test = allNames.Where(n => !trainNames.Contains(n)).ToList();
                Assert.That(train.OrderBy(n => n), Is.EqualTo(new[] { "train_r_0", "train_r_1", "train_r_2" }));
                Assert.That(test.OrderBy(n => n), Is.EqualTo(new[] { "test_r_0", "test_r_1", "val_r_0" }));
                Assert.That(result.TrainCommands[0], Does.Contain("-r 1").And.Contain("--eval --train_split").And.Contain(GaussianGrouping.ConfigFileName));
                Assert.That(result.TrainCommands[1], Does.Contain("--num_classes 256"));
            }
        }

        /// <summary>
        /// The model folder of the printed commands is named after the dataset for the default place inside it, and
        /// after the export folder itself with --out (issue 33: --out exports/lego-gg named the model "exports").
        /// </summary>
        [Test]
        public void TheTrainingCommandNamesTheModelAfterTheDatasetOrTheOutFolder()
        {
            var root = Path.GetFullPath(Path.Combine(Path.GetTempPath(), "nowhere"));
            var inside = GaussianGroupingExport.Commands(Path.Combine(root, "lego", GaussianGrouping.FolderName), false);
            Assert.That(inside[0], Does.Contain(" -m output/lego "));
            Assert.That(inside[1], Does.StartWith("python render.py -m output/lego "));
            var elsewhere = GaussianGroupingExport.Commands(Path.Combine(root, "exports", "lego-gg") + Path.DirectorySeparatorChar, true);
            Assert.That(elsewhere[0], Does.Contain(" -m output/lego-gg "));
            Assert.That(elsewhere[1], Does.StartWith("python render.py -m output/lego-gg "));
        }

        [Test]
        public void MaskValuesNumberTheIdsInOrderAndRefuseMoreThan255()
        {
            var values = GaussianGrouping.MaskValues(new[] { 40, 7, 65535 });
            Assert.That(values[7], Is.EqualTo(1));
            Assert.That(values[40], Is.EqualTo(2));
            Assert.That(values[65535], Is.EqualTo(3));
            var mask = GaussianGrouping.Mask(new ushort[] { 0, 40, 7, 65535, 9 }, values);
            Assert.That(mask, Is.EqualTo(new byte[] { 0, 2, 1, 3, 0 }), "ids without a value (9) are background");
            var problem = Assert.Throws<InvalidParameterException>(() => GaussianGrouping.MaskValues(Enumerable.Range(1, 256).ToList())).Problems[0];
            Assert.That(problem.ToString(), Does.Contain("255"));
        }

        [Test]
        public void ImageNamesAreCutAtTheFirstDotAsTheLoaderDoes()
        {
            Assert.That(GaussianGrouping.ImageName("train_r_0.png"), Is.EqualTo("train_r_0"));
            Assert.That(GaussianGrouping.ImageName("a.b.png"), Is.EqualTo("a"));
            Assert.That(GaussianGrouping.MaskPath("test_r_12.png"), Is.EqualTo("object_mask/test_r_12.png"));
        }

        [Test]
        public void ADatasetWithoutLabelsIsRefusedNamingLabelsJson()
        {
            using (var temp = new TempFolder())
            {
                var dataset = LabelledTestDataset.Write(temp.Path, labels: false);
                var stdout = new StringWriter();
                var stderr = new StringWriter();
                var code = ConvertCommand.Run(dataset, ExportTarget.GaussianGrouping, null, stdout, stderr);
                Assert.That(code, Is.EqualTo(ToolExitCodes.Failure));
                Assert.That(stderr.ToString(), Does.Contain("error: ").And.Contain("labels.json").And.Contain("labels on"));
                Assert.That(Directory.Exists(Path.Combine(dataset, GaussianGrouping.FolderName)), Is.False, "nothing was written");
            }
        }
    }
}
