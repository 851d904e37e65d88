using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    [TestFixture]
    public class ConvertCommandTests
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

        /// <summary>The camera centres of a split file: the translation column of each c2w matrix.</summary>
        static double[][] Centres(JObject transforms) =>
            transforms["frames"].Select(f => new[] { (double)f["transform_matrix"][0][3], (double)f["transform_matrix"][1][3], (double)f["transform_matrix"][2][3] }).ToArray();

        [Test]
        public void NerfstudioGoesNextToTheSplitFiles()
        {
            var run = ToolRun.Of("convert", _dataset, "--to", "nerfstudio");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var file = Path.Combine(_dataset, "transforms.json");
            Assert.That(run.Out, Is.EqualTo(
                "converted " + _dataset + " to nerfstudio:\n" +
                "  wrote " + file + "\n" +
                string.Concat(new[] { "train", "val", "test" }.Select(split => "  wrote " + Path.Combine(_dataset, "camera_paths", split + ".json") + "\n")) +
                "files: every file the export names is inside its folder\n" +
                // No dataset_config.json here: the target counts as nerf_synthetic's ±1.5 box, 1/1.5 → 0.666.
                "train with: ns-train nerfacto --data " + file + " nerfstudio-data --orientation-method none --center-method none --auto-scale-poses False --scale-factor 0.666\n" +
                "train with: ns-train splatfacto --data " + file + " nerfstudio-data --orientation-method none --center-method none\n" +
                "train with: ns-train instant-ngp --data " + file + " nerfstudio-data --orientation-method none --center-method none --auto-scale-poses False --scale-factor 0.666\n"));
            var json = Json(file);
            Assert.That((int)json["w"], Is.EqualTo(RenderedDataset.Width));
            Assert.That((int)json["h"], Is.EqualTo(RenderedDataset.Height));
            Assert.That(json["frames"].Select(f => (string)f["file_path"]).Take(4), Is.EqualTo(new[] { "train/r_0.png", "train/r_1.png", "train/r_2.png", "val/r_0.png" }));
            Assert.That(json["test_filenames"].Select(t => (string)t), Is.EqualTo(new[] { "test/r_0.png", "test/r_1.png" }));
            Assert.That(Centres(json).Take(RenderedDataset.Train), Is.EqualTo(Centres(Json(Path.Combine(_dataset, "transforms_train.json")))).Within(1e-9));
        }

        [Test]
        public void AnInsideOutCaptureIsTrainedWithSceneContractionCentredOnItsCameras()
        {
            // The config records a volume split and the environment's size: a 10-unit sphere at the Unity origin, no normalisation.
            File.WriteAllText(Path.Combine(_dataset, "dataset_config.json"),
                "{\"target\": {\"unityCentre\": [0, 0, 0], \"boundingRadius\": 10}, \"settings\": {\"splits\": {\"train\": {\"source\": {\"kind\": \"volume\", \"box\": \"Room\"}}}}}");
            var run = ToolRun.Of("convert", _dataset, "--to", "nerfstudio");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var file = Path.Combine(_dataset, "transforms.json");
            // Independently of Core: nerfstudio-data's centre and scale of these cameras, then instant-ngp's box
            // (reach + |mean|) · scale rounded up to 2 significant digits.
            var centres = Centres(Json(file));
            var mean = new double[3];
            foreach (var c in centres) for (var k = 0; k < 3; k++) mean[k] += c[k] / centres.Length;
            var largest = centres.Max(c => Enumerable.Range(0, 3).Max(k => System.Math.Abs(c[k] - mean[k])));
            var box = (10 + System.Math.Sqrt(mean.Sum(m => m * m))) / largest;
            var unit = System.Math.Pow(10, System.Math.Floor(System.Math.Log10(box)) - 1);
            var sceneScale = System.Math.Ceiling(box / unit - 1e-9) * unit;
            var flags = "nerfstudio-data --orientation-method none --center-method poses --auto-scale-poses True";
            Assert.That(run.Out, Does.EndWith(
                "train with: ns-train nerfacto --pipeline.model.disable-scene-contraction False --data " + file + " " + flags + "\n" +
                "train with: ns-train splatfacto --data " + file + " " + flags + "\n" +
                "train with: ns-train instant-ngp --pipeline.model.disable-scene-contraction False --data " + file + " " + flags +
                " --scene-scale " + sceneScale.ToString("0.##########", System.Globalization.CultureInfo.InvariantCulture) + "\n"));
            Assert.That(sceneScale, Is.GreaterThan(1), "the environment reaches beyond the cameras");
            Assert.That(run.Err, Does.Contain("dataparser_transforms.json"), "camera paths must be mapped into the model's frame");
        }

        [Test]
        public void NgpGetsItsOwnFolderWithTheTrainFramesOnly()
        {
            var run = ToolRun.Of("convert", _dataset, "--to=ngp");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var file = Path.Combine(_dataset, "ngp", "transforms.json");
            Assert.That(run.Out, Does.Contain("  wrote " + file + "\n").And.EndWith("train with: ./instant-ngp " + file + "   (from the instant-ngp folder)\n"));
            var frames = (JArray)Json(file)["frames"];
            Assert.That(frames.Count, Is.EqualTo(RenderedDataset.Train));
            foreach (var frame in frames)
                Assert.That(File.Exists(Path.Combine(_dataset, "ngp", (string)frame["file_path"])), Is.True, (string)frame["file_path"]);
        }

        /// <summary>The config's loader names work for --to: 3dgs is the COLMAP source 3DGS reads, instant-ngp the ngp export.</summary>
        [TestCase("3dgs", "colmap", "sparse/0/cameras.txt")]
        [TestCase("instant-ngp", "ngp", "transforms.json")]
        [TestCase("gsplat", "colmap", "sparse/0/cameras.txt")]
        public void TheConfigsLoaderNamesConvertToTheirFormat(string loader, string target, string file)
        {
            var run = ToolRun.Of("convert", _dataset, "--to", loader, "--out", _scratch.PathOf("by-loader"));
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.StartWith("converted " + _dataset + " to " + target + ":"));
            Assert.That(File.Exists(Path.Combine(_scratch.PathOf("by-loader"), file)), Is.True, run.ToString());
        }

        [Test]
        public void ColmapToAChosenFolderSummarisesTheImageCopiesAndWarns()
        {
            var output = _scratch.PathOf("exports", "ds-colmap");
            var run = ToolRun.Of("convert", "--to", "colmap", "--out", output, _dataset);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var sparse = Path.Combine(output, "sparse", "0");
            Assert.That(run.Out.Split('\n'), Is.EqualTo(new[]
            {
                "converted " + _dataset + " to colmap:",
                "  wrote " + Path.Combine(sparse, "cameras.txt"),
                "  wrote " + Path.Combine(sparse, "images.txt"),
                "  wrote " + Path.Combine(sparse, "points3D.txt"),
                "  wrote " + Path.Combine(sparse, "test.txt"),
                "  wrote 7 files into " + Path.Combine(output, "images") + Path.DirectorySeparatorChar,
                "train with: python train.py -s " + output + " --eval   (3D Gaussian Splatting)",
                "",
            }));
            Assert.That(Directory.GetFiles(Path.Combine(output, "images")).Select(Path.GetFileName).OrderBy(n => n, System.StringComparer.Ordinal),
                Is.EqualTo(new[] { "test_r_0.png", "test_r_1.png", "train_r_0.png", "train_r_1.png", "train_r_2.png", "val_r_0.png", "val_r_1.png" }));
            Assert.That(File.ReadAllText(Path.Combine(sparse, "cameras.txt")), Does.Contain("1 PINHOLE 32 24 "));
            var warnings = run.Err.TrimEnd('\n').Split('\n');
            Assert.That(warnings, Has.All.StartWith("warning: "));
            Assert.That(warnings, Has.Some.StartWith("warning: points3D.txt = 100000 random points"));
            Assert.That(warnings, Has.Some.StartWith("warning: images.txt = 7 images: COLMAP has no splits"));
            Assert.That(Directory.Exists(Path.Combine(_dataset, "colmap")), Is.False, "--out replaces the default place");
        }

        [Test]
        public void ASecondConvertRefusesToOverwrite()
        {
            Assert.That(ToolRun.Of("convert", _dataset, "--to", "nerfstudio").ExitCode, Is.EqualTo(0));
            var file = Path.Combine(_dataset, "transforms.json");
            File.WriteAllText(file, "edited by hand");
            var run = ToolRun.Of("convert", _dataset, "--to", "nerfstudio");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Out, Is.Empty);
            Assert.That(run.Err, Is.EqualTo(
                "error: output = " + file + ": already exists (an earlier convert?); convert never overwrites files. Move or delete it, or convert into another folder (--out <folder>).\n" +
                "convert refused: 1 problem; nothing was written.\n"));
            Assert.That(File.ReadAllText(file), Is.EqualTo("edited by hand"));
        }

        [Test]
        public void ALeftOverCameraPathIsRefusedBeforeAnythingIsPlaced()
        {
            var paths = Path.Combine(_dataset, "camera_paths");
            Directory.CreateDirectory(paths);
            var leftover = Path.Combine(paths, "val.json");
            File.WriteAllText(leftover, "mine");
            var run = ToolRun.Of("convert", _dataset, "--to", "nerfstudio");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.StartWith("error: output = " + leftover + ": already exists (an earlier convert?); convert never overwrites files."));
            Assert.That(File.Exists(Path.Combine(_dataset, "transforms.json")), Is.False, "nothing of the export was placed");
            Assert.That(Directory.GetFiles(paths), Is.EqualTo(new[] { leftover }));
            Assert.That(File.ReadAllText(leftover), Is.EqualTo("mine"));
        }

        [Test]
        public void APlanOnlyDatasetIsRefusedInOneLineNotOnePerFrame()
        {
            var plan = RenderedDataset.PlanOnly(_scratch, "planned");
            var before = Directory.GetFileSystemEntries(plan, "*", SearchOption.AllDirectories).OrderBy(p => p, System.StringComparer.Ordinal).ToList();
            var run = ToolRun.Of("convert", plan, "--to", "colmap");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Out, Is.Empty);
            var lines = run.Err.TrimEnd('\n').Split('\n');
            Assert.That(lines, Has.Length.EqualTo(2), run.Err);
            Assert.That(lines[0], Does.StartWith("error: dataset_config.json: imagesRendered = false: this dataset was planned by nerf-dataset plan and has no images")
                .And.EndWith("Render the dataset with the Unity plugin (window or batch mode) and convert that folder."));
            Assert.That(lines[1], Does.StartWith("convert refused: 7 problems, the first: train.frames[0].file_path = ./train/r_0: names no image")
                .And.EndWith("Nothing was written."));
            Assert.That(Directory.GetFileSystemEntries(plan, "*", SearchOption.AllDirectories).OrderBy(p => p, System.StringComparer.Ordinal), Is.EqualTo(before));
        }

        [Test]
        public void AMissingImageOfARenderedDatasetIsNamed()
        {
            File.Delete(Path.Combine(_dataset, "val", "r_1.png"));
            var run = ToolRun.Of("convert", _dataset, "--to", "ngp");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Is.EqualTo(
                "error: val.frames[1].file_path = ./val/r_1: names no image (looked for the path and the path + \".png\"). Copy the images next to the split files.\n" +
                "convert refused: 1 problem; nothing was written.\n"));
            Assert.That(Directory.Exists(Path.Combine(_dataset, "ngp")), Is.False);
        }

        [Test]
        public void AFolderWithoutTransformsIsNotADataset()
        {
            var empty = _scratch.PathOf("empty");
            Directory.CreateDirectory(empty);
            var run = ToolRun.Of("convert", empty, "--to", "nerfstudio");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("has no transforms_train.json, so it is not a Blender-format (nerf_synthetic) dataset."));
            Assert.That(ToolRun.Of("convert", _scratch.PathOf("nowhere"), "--to", "nerfstudio").Err, Does.Contain("is not an existing folder."));
        }

        [Test]
        public void TheRealLegoTransformsConvert()
        {
            var lego = _scratch.PathOf("lego");
            TestDatasets.Lego(lego);
            var run = ToolRun.Of("convert", lego, "--to", "nerfstudio");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var json = Json(Path.Combine(lego, "transforms.json"));
            Assert.That(json["frames"], Has.Count.EqualTo(300));
            // nerf_synthetic: camera_angle_x 0.6911112070083618 at 800 px → fl = 400 / tan(0.3455556035041809).
            Assert.That((double)json["fl_x"], Is.EqualTo(1111.1110311937682).Within(1e-6));
            Assert.That(Centres(json).Take(100), Is.EqualTo(Centres(Json(Path.Combine(lego, "transforms_train.json")))).Within(1e-9));
        }

        [TestCase(new[] { "convert", "ds", "--to", "blender" }, "--to = blender: is the format the dataset is already in (nerf_synthetic / Blender)")]
        [TestCase(new[] { "convert", "ds", "--to", "gaussian-splatting" }, "--to = gaussian-splatting: is not an export format.")]
        [TestCase(new[] { "convert", "ds", "--to", "instantngp" }, "--to = instantngp: is not an export format. Use one of: nerfstudio, colmap, ngp, dynamic3dgs, gaussian-grouping, nerfies, dycheck, llff, dynerf, neus, replica, tum, multiscale, hdr-nerf, tensoir, gs-ir, r3dg, kubric, nsff, shape-of-motion (or the trainers' names 3dgs = gsplat = colmap, instant-ngp = ngp). Did you mean \"instant-ngp\"?")]
        [TestCase(new[] { "convert", "ds" }, "convert needs --to nerfstudio|colmap|ngp")]
        [TestCase(new[] { "convert", "--to", "ngp" }, "convert needs exactly one dataset folder")]
        public void UsageErrorsExitTwo(string[] args, string error)
        {
            var run = ToolRun.Of(args);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("error: " + error).And.Contain("usage:"));
        }
    }
}
