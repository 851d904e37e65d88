using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// <c>convert --images copy|link|relative</c> (issue 33, "Exports that silently depend on the source"): a
    /// nerfstudio or ngp export written elsewhere holds its files by default, so it still trains after the dataset
    /// is moved away; link does the same by hard links; relative names the dataset's files, and says so.
    /// </summary>
    [TestFixture]
    public class ConvertImagesTests
    {
        Scratch _scratch;
        string _dataset;

        [SetUp]
        public void SetUp()
        {
            _scratch = new Scratch();
            _dataset = RenderedDataset.Create(_scratch, "ds");
        }

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        static JObject Json(string path) => JObject.Parse(File.ReadAllText(path));

        /// <summary>Every path a transforms.json names (images, depth, masks, point cloud), relative to its folder.</summary>
        static List<string> NamedFiles(JObject json) =>
            json["frames"].SelectMany(f => new[] { f["file_path"], f["depth_file_path"], f["depth_path"], f["mask_path"] })
                .Concat(new[] { json["ply_file_path"] }).Where(t => t != null).Select(t => (string)t).Distinct().ToList();

        /// <summary>Moves the dataset away, as copying only the export to a GPU machine would leave it.</summary>
        void MoveTheDatasetAway() => Directory.Move(_dataset, _scratch.PathOf("moved-away"));

        [TestCase("nerfstudio", 7)]
        [TestCase("ngp", 3)]
        public void AnExportElsewhereCopiesItsFilesByDefault_AndWorksWithoutTheDataset(string target, int files)
        {
            var output = _scratch.PathOf("exports", "ds-" + target);
            var run = ToolRun.Of("convert", _dataset, "--to", target, "--out", output);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.Contain("\nfiles: the export holds copies of its " + files + " files: a self-contained folder\n"));
            var named = NamedFiles(Json(Path.Combine(output, "transforms.json")));
            Assert.That(named, Has.Count.EqualTo(files));
            Assert.That(named, Has.All.StartWith("train/").Or.StartWith("val/").Or.StartWith("test/"), "the dataset's own paths, inside the export");
            foreach (var file in named)
                Assert.That(File.ReadAllBytes(Path.Combine(output, file)), Is.EqualTo(File.ReadAllBytes(Path.Combine(_dataset, file))), file);

            MoveTheDatasetAway();
            foreach (var file in named) Assert.That(File.Exists(Path.Combine(output, file)), Is.True, file + " after the dataset moved away");
        }

        [Test]
        public void RelativeNamesTheDatasetsFilesAndSaysTheExportDependsOnIt()
        {
            var output = _scratch.PathOf("exports", "ds-ngp");
            var run = ToolRun.Of("convert", _dataset, "--to", "ngp", "--out", output, "--images", "relative");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var named = NamedFiles(Json(Path.Combine(output, "transforms.json")));
            Assert.That(named.First(), Is.EqualTo("../../ds/train/r_0.png"));
            Assert.That(run.Out, Does.Contain("\nfiles: the export names 3 files of the dataset by relative path (e.g. ../../ds/train/r_0.png): it works only beside " + _dataset +
                                              " (--images copy makes a self-contained folder)\n"));
            Assert.That(Directory.Exists(Path.Combine(output, "train")), Is.False, "nothing copied");
        }

        [Test]
        public void TheDefaultPlaceInsideTheDatasetKeepsRelativePaths()
        {
            var run = ToolRun.Of("convert", _dataset, "--to", "ngp");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(NamedFiles(Json(Path.Combine(_dataset, "ngp", "transforms.json"))).First(), Is.EqualTo("../train/r_0.png"));
            Assert.That(run.Out, Does.Contain("files: the export names 3 files of the dataset by relative path (e.g. ../train/r_0.png)"));
            Assert.That(Directory.Exists(Path.Combine(_dataset, "ngp", "train")), Is.False);
        }

        /// <summary>
        /// A hard link is the file itself under a second name: bytes appended to the dataset's image appear in the
        /// export's (a copy would not change), and the export keeps its files when the dataset moves away.
        /// </summary>
        [Test]
        public void LinkHardLinksTheFiles_TheSameFileUnderTwoNames()
        {
            var output = _scratch.PathOf("exports", "ds-linked");
            var run = ToolRun.Of("convert", _dataset, "--to", "nerfstudio", "--out", output, "--images", "link");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.Contain("\nfiles: the export holds its 7 files: 7 hard-linked to the dataset's (no extra disk space; editing one in place edits both); a self-contained folder\n"));
            var source = Path.Combine(_dataset, "train", "r_0.png");
            var linked = Path.Combine(output, "train", "r_0.png");
            var before = new FileInfo(linked).Length;
            using (var append = new FileStream(source, FileMode.Append, FileAccess.Write)) append.WriteByte(0x2A);
            Assert.That(new FileInfo(linked).Length, Is.EqualTo(before + 1), "the same file");
            Assert.That(File.ReadAllBytes(linked), Is.EqualTo(File.ReadAllBytes(source)));

            MoveTheDatasetAway();
            Assert.That(File.Exists(linked), Is.True, "a hard link survives the dataset moving away (a symbolic link would not)");
        }

        [Test]
        public void ADestinationThatExistsIsRefusedBeforeAnythingIsWritten()
        {
            var output = _scratch.PathOf("exports", "taken");
            Directory.CreateDirectory(Path.Combine(output, "val"));
            File.WriteAllText(Path.Combine(output, "val", "r_1.png"), "someone else's");
            var run = ToolRun.Of("convert", _dataset, "--to", "nerfstudio", "--out", output);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain(Path.Combine(output, "val", "r_1.png") + ": already exists"));
            Assert.That(File.ReadAllText(Path.Combine(output, "val", "r_1.png")), Is.EqualTo("someone else's"));
            Assert.That(File.Exists(Path.Combine(output, "transforms.json")), Is.False);
            Assert.That(Directory.Exists(Path.Combine(output, "train")), Is.False);
        }

        [TestCase("colmap", "link")]
        [TestCase("gaussian-grouping", "relative")]
        [TestCase("dynamic3dgs", "link")]
        public void LinkAndRelativeAreForTheExportsThatNameTheDatasetsFiles(string target, string images)
        {
            var run = ToolRun.Of("convert", _dataset, "--to", target, "--images", images);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.StartWith("error: --images = " + images + ": is for nerfstudio and ngp, whose transforms.json names the dataset's files; --to " + target +
                                                " writes its own images into the export"));
        }

        [Test]
        public void AnUnknownModeIsAUsageErrorWithASuggestion()
        {
            var run = ToolRun.Of("convert", _dataset, "--to", "ngp", "--images", "lnk");
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.StartWith("error: --images = lnk: is not copy, link or relative. Use copy (a self-contained folder), link (the same, by hard links: no extra space) or relative (paths back into the dataset). Did you mean \"link\"?"));
        }
    }
}
