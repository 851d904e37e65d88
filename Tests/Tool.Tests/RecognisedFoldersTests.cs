using System.Diagnostics;
using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// validate and check say what they were given when it is not a dataset folder, and validate and evaluate name a
    /// JPEG where a PNG should be (issue 33: "validate given a file says the folder does not exist, with .jpg images
    /// says r_0.jpg.png is missing, and on an export does not say what the folder is; evaluate with a JPEG render
    /// says it is missing").
    /// </summary>
    [TestFixture]
    public class RecognisedFoldersTests
    {
        Scratch _scratch;
        string _dataset;

        /// <summary>The first bytes of a JFIF file: what makes a JPEG a JPEG to <see cref="ImageFormats.IsJpeg"/>.</summary>
        static readonly byte[] JpegBytes = { 0xFF, 0xD8, 0xFF, 0xE0, 0x00, 0x10, (byte)'J', (byte)'F', (byte)'I', (byte)'F', 0x00 };

        [SetUp]
        public void SetUp()
        {
            _scratch = new Scratch();
            _dataset = RenderedDataset.Create(_scratch, "ds");
        }

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        static string OneProblem(ToolRun run)
        {
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            return run.Out.Split('\n').Single(l => l.StartsWith("problem: "));
        }

        [Test]
        public void AFileIsNamedAsAFileWithItsFolder()
        {
            var file = Path.Combine(_dataset, "transforms_train.json");
            Assert.That(OneProblem(ToolRun.Of("validate", file)), Is.EqualTo("problem: " + file + ": is a file, not a folder: pass the dataset folder that holds transforms_train.json (here " + _dataset + ")."));
            var check = ToolRun.Of("check", file);
            Assert.That(check.ExitCode, Is.EqualTo(1));
            Assert.That(check.Err, Is.EqualTo("error: " + file + ": is a file, not a folder: pass the dataset folder that holds transforms_train.json (here " + _dataset + ").\n"));
        }

        [TestCase("nerfstudio", "is a nerfstudio export (transforms.json with train_filenames) of nerf-dataset convert; train with ns-train nerfacto --data ")]
        [TestCase("ngp", "is an instant-ngp export (transforms.json with aabb_scale) of nerf-dataset convert; train with ./instant-ngp ")]
        [TestCase("colmap", "is a COLMAP export (sparse/0/) of nerf-dataset convert, or a COLMAP reconstruction; train with 3D Gaussian Splatting: python train.py -s ")]
        public void AnExportIsNamedWithItsTrainingCommand(string target, string says)
        {
            var export = _scratch.PathOf("exported-" + target);
            Assert.That(ToolRun.Of("convert", _dataset, "--to", target, "--out", export).ExitCode, Is.EqualTo(0));
            var problem = OneProblem(ToolRun.Of("validate", export));
            Assert.That(problem, Does.StartWith("problem: " + export + ": " + says));
            Assert.That(problem, Does.EndWith("validate and check read the Blender-format dataset it came from (transforms_train/val/test.json): pass that folder."));
            Assert.That(ToolRun.Of("check", export).Err, Does.StartWith("error: " + export + ": " + says));
        }

        [Test]
        public void JpegImagesNamedWithTheirExtensionAreNamedAsJpegs()
        {
            foreach (var split in new[] { "train", "val", "test" })
            {
                var transforms = Path.Combine(_dataset, "transforms_" + split + ".json");
                var json = JObject.Parse(File.ReadAllText(transforms));
                foreach (var frame in json["frames"])
                {
                    var path = (string)frame["file_path"];
                    File.Delete(Path.Combine(_dataset, path + ".png"));
                    File.WriteAllBytes(Path.Combine(_dataset, path + ".jpg"), JpegBytes);
                    frame["file_path"] = path + ".jpg";
                }
                File.WriteAllText(transforms, json.ToString());
            }
            var run = ToolRun.Of("validate", _dataset);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Out, Does.Contain("problem: transforms_train.json frame 0 (./train/r_0.jpg): ./train/r_0.jpg is a JPEG; bmild/nerf, nerf-pytorch, nerfstudio's blender-data and 3DGS read PNG " +
                                              "(they append \".png\" to file_path), and so does this tool. Convert the images to PNG"));
            Assert.That(run.Out, Does.Not.Contain("r_0.jpg.png").And.Not.Contain("is not a PNG file"));
        }

        [Test]
        public void AJpegBesideAMissingPngIsNamed()
        {
            File.Delete(Path.Combine(_dataset, "val", "r_1.png"));
            File.WriteAllBytes(Path.Combine(_dataset, "val", "r_1.jpg"), JpegBytes);
            Assert.That(OneProblem(ToolRun.Of("validate", _dataset)),
                Does.EndWith(": image ./val/r_1.png is missing, but ./val/r_1.jpg is there (a JPEG): the loaders and this tool read PNG. Convert the images to PNG (e.g. `mogrify -format png */*.jpg`) and write file_path without an extension (./train/r_0)."));
        }

        /// <summary>A capture's working folder, with its journal naming a real process: running while it runs, ended once it is killed.</summary>
        [Test]
        public void AHalfWrittenFolderSaysWhetherItsRunIsStillGoing()
        {
            var output = _scratch.PathOf("lego");
            var working = output + ".partial-20261206-120000-0123abcd~";
            Directory.CreateDirectory(working);
            File.Copy(Path.Combine(_dataset, "transforms_train.json"), Path.Combine(working, "transforms_train.json"));
            using (var writer = Process.Start(new ProcessStartInfo("sleep", "60") { UseShellExecute = false }))
            {
                try
                {
                    var journal = new OperationJournal { Operation = "write", Output = output, Owner = new OperationOwner(OperationOwner.Current.Host, writer.Id, null) };
                    journal.Save(working);

                    var running = OneProblem(ToolRun.Of("validate", working));
                    Assert.That(running, Does.StartWith("problem: " + working + ": is the working folder of a capture or plan into " + output + ", not a dataset. It may still be running (process " + writer.Id));
                    Assert.That(OneProblem(ToolRun.Of("validate", output)), Does.StartWith("problem: " + output + ": does not exist yet: a capture or plan into it has not finished, and " + working + " holds its files so far. It may still be running"));
                }
                finally
                {
                    writer.Kill();
                    writer.WaitForExit();
                }
            }
            Assert.That(OneProblem(ToolRun.Of("validate", working)), Does.EndWith("Its run has ended without finishing (killed, crashed or cancelled): capture again, or run `nerf-dataset clean " + _scratch.Root + "` to finish or remove what it left."));
        }

        [Test]
        public void EvaluateNamesJpegRendersInsteadOfCallingThemMissing()
        {
            var dataset = _scratch.PathOf("sphere");
            AnalyticSphereDataset.Write(dataset, 40, 32, train: 4, test: 3);
            var renders = _scratch.PathOf("renders");
            Directory.CreateDirectory(renders);
            for (var i = 0; i < 3; i++) File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".jpg"), JpegBytes);
            var run = ToolRun.Of("evaluate", dataset, "--renders", renders, "--layout", "plain");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.StartWith("error: --renders = " + renders + ": holds JPEG renders where the PNGs should be (r_0.jpg, r_1.jpg, r_2.jpg: 3 of 3 frames); evaluate reads PNG, and JPEG's loss would be scored as the model's error. " +
                                                "Render the split again as PNG (converting a JPEG to PNG keeps its loss)."));
            Assert.That(run.Err, Does.Not.Contain("has no render"));
        }
    }
}
