using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Threading.Tasks;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// Issue 32 items 5–11 through the tool: hostile files in a dataset (a FIFO, a character device, a sparse 3 GB
    /// split, lying PLY headers …) are problems naming the file — never a hang, never "ran out of memory".
    /// </summary>
    [TestFixture]
    public class HostileFilesTests
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

        static void AssumeUnix() =>
            Assume.That(RuntimeInformation.IsOSPlatform(OSPlatform.Linux) || RuntimeInformation.IsOSPlatform(OSPlatform.OSX), "FIFOs and devices are Unix's");

        /// <summary>Runs a command of the tool (in this process) on another thread: a run that opens a FIFO waits forever, and the test must still end.</summary>
        internal static ToolRun Within(params string[] args)
        {
            var task = Task.Run(() => ToolRun.Of(args));
            Assert.That(task.Wait(TimeSpan.FromMinutes(3)), Is.True, "'" + string.Join(" ", args) + "' hung");
            return task.Result;
        }

        internal static void Run(string file, string arguments)
        {
            using (var process = Process.Start(new ProcessStartInfo(file, arguments) { UseShellExecute = false }))
            {
                process.WaitForExit();
                Assume.That(process.ExitCode, Is.EqualTo(0), file + " " + arguments);
            }
        }

        [Test]
        public void AFifoInPlaceOfAnImageIsAProblemNamingItInCheckAndValidate()
        {
            AssumeUnix();
            var image = Path.Combine(_dataset, "train", "r_0.png");
            File.Delete(image);
            Run("mkfifo", "\"" + image + "\"");
            foreach (var command in new[] { "check", "validate" })
            {
                var run = Within(command, _dataset);
                Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
                Assert.That(run.Out, Does.Contain(image + " is empty (0 bytes) or is not a regular file (a pipe or device reports no size), so it is not read."), command);
            }
        }

        [Test]
        public void AFifoInPlaceOfThePointCloudIsNotTheTargetsSurfaceAndNoFileOperationFailure()
        {
            AssumeUnix();
            var cloud = Path.Combine(_dataset, "points3d.ply");
            Run("mkfifo", "\"" + cloud + "\"");
            var validate = Within("validate", _dataset);
            Assert.That(validate.Out, Does.Contain("warning: points3d.ply: cannot be read (" + cloud + " is empty (0 bytes) or is not a regular file"), validate.ToString());
            foreach (var run in new[] { validate, Within("check", _dataset) })
                Assert.That(run.Err, Does.Not.Contain("a file operation failed"), run.ToString());
        }

        [Test]
        public void ACharacterDeviceInPlaceOfAnImageIsAProblemNotOutOfMemory()
        {
            // A device like /dev/zero (char 1,5) inside the dataset: a symbolic link to /dev/zero leaves the dataset and is refused as such.
            AssumeUnix();
            var image = Path.Combine(_dataset, "train", "r_0.png");
            File.Delete(image);
            Run("mknod", "\"" + image + "\" c 1 5"); // needs root, as the CI runs; skipped otherwise
            var run = Within("check", _dataset);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Out, Does.Contain("./train/r_0.png frame 0 [dataset]: cannot be decoded as the colour image: " + image + " is empty (0 bytes) or is not a regular file"));
        }

        [Test]
        public void ASparse3GbSplitIsRefusedByItsSizeInCheckAndValidate()
        {
            var val = Path.Combine(_dataset, "transforms_val.json");
            // The real split, then a sparse tail of zero bytes to 3 GiB (no disk used): JSON readers stop at the object's end.
            using (var file = new FileStream(val, FileMode.Open)) file.SetLength(3L << 30);
            var reason = "is 3 GiB, more than the 512 MiB read whole for a file of this kind (this plugin's largest are a few hundred MB), so it is refused unread.";
            var check = Within("check", _dataset);
            Assert.That(check.ExitCode, Is.EqualTo(1), check.ToString());
            Assert.That(check.Out, Does.Contain("problem: transforms_val.json [dataset]: cannot be read: " + val + " " + reason));
            var validate = Within("validate", _dataset);
            Assert.That(validate.ExitCode, Is.EqualTo(1), validate.ToString()); // validate's streaming read used to say OK
            Assert.That(validate.Out, Does.Contain("problem: transforms_val.json: " + reason));
        }

        /// <summary>A renders folder of the test split's own images (plain layout): a perfect model.</summary>
        string Renders()
        {
            var renders = _scratch.PathOf("renders");
            if (Directory.Exists(renders)) return renders;
            Directory.CreateDirectory(renders);
            foreach (var image in Directory.GetFiles(Path.Combine(_dataset, "test"), "r_?.png")) File.Copy(image, Path.Combine(renders, Path.GetFileName(image)));
            return renders;
        }

        string Write(string name, string text) => _scratch.WriteText(name, text);

        const string Triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

        [Test]
        public void AMaskOfAnotherSizeThanItsImageIsAProblemNamingTheMask()
        {
            var test = Path.Combine(_dataset, "transforms_test.json");
            var json = JObject.Parse(File.ReadAllText(test));
            foreach (var frame in (JArray)json["frames"])
            {
                var mask = (string)frame["file_path"] + "_mask.png";
                frame["mask_path"] = mask;
                TestPng.Write(Path.Combine(_dataset, mask.TrimStart('.', '/')), RenderedDataset.Width / 2, RenderedDataset.Height / 2, 8, PngInfo.ColorTypeGray);
            }
            File.WriteAllText(test, json.ToString());
            var run = Within("evaluate", _dataset, "--renders", Renders(), "--out", _scratch.PathOf("eval"));
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            // The views are scored in parallel: whichever frame's mask is met first is named.
            var named = Enumerable.Range(0, RenderedDataset.Test).Any(i =>
                run.Err.Contains("r_" + i + "_mask.png = " + Path.Combine(_dataset, "test", "r_" + i + "_mask.png") + ": is 16×12 but its frame's image " +
                                 Path.Combine(_dataset, "test", "r_" + i + ".png") + " is 32×24. Re-capture the mask, or fix the frame's key so that it names this image's mask."));
            Assert.That(named, Is.True, run.ToString());
        }

        [Test]
        public void AMetricsJsonWhoseGeneratorIsAnObjectIsNotOursAndIsLeftAlone()
        {
            var outFolder = _scratch.PathOf("eval");
            Directory.CreateDirectory(outFolder);
            var metrics = Path.Combine(outFolder, "metrics.json");
            File.WriteAllText(metrics, "{ \"generator\": { \"name\": \"x\" } }");
            File.WriteAllText(Path.Combine(outFolder, "report.html"), "<html></html>");
            var run = Within("evaluate", _dataset, "--renders", Renders(), "--out", outFolder);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("holds files named like an evaluation's, but no metrics.json written by"));
            Assert.That(File.ReadAllText(metrics), Is.EqualTo("{ \"generator\": { \"name\": \"x\" } }"));
        }

        [Test]
        public void ADegenerateGroundTruthMeshIsAGtMeshProblemNotTheCapturesPointCloud()
        {
            var flat = Write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"); // collinear: zero area
            var run = Within("evaluate", _dataset, "--renders", Renders(), "--out", _scratch.PathOf("eval"), "--geometry", Write("recon.obj", Triangle), "--gt-mesh", flat);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("--gt-mesh = " + flat + ": has 1 triangle(s) but no surface area (every face degenerate); the ground truth must be a surface to sample. Pass the target's triangle mesh."));
            Assert.That(run.Err, Does.Not.Contain("pointCloud"));
        }

        [Test]
        public void ReconstructionCoordinatesOf1e300AreAProblemNotAnIndexOutOfRange()
        {
            var recon = Write("recon.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\nend_header\n1e300 0 0\n0 1e300 0\n0 0 -1e300\n");
            var run = Within("evaluate", _dataset, "--renders", Renders(), "--out", _scratch.PathOf("eval"), "--geometry", recon, "--gt-mesh", Write("gt.obj", Triangle));
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("--geometry = " + recon + ": has a vertex beyond ±1e30 (number 0: 1E+300, 0, 0)"));
        }

        [TestCase("abc", "has an unreadable header line 'element vertex abc'.")]
        [TestCase("-5", "has an unreadable header line 'element vertex -5'.")]
        [TestCase("12345678901234567890", "has an unreadable header line 'element vertex 12345678901234567890'.")]
        [TestCase("500000000", "is truncated: its header declares element vertex 500000000, at least 1500000000 bytes of ascii data, but only 12 bytes follow the header.")]
        public void ALyingPlyHeaderIsAProblemNamingTheFileInEvaluate(string count, string reason)
        {
            var recon = Write("recon.ply", "ply\nformat ascii 1.0\nelement vertex " + count + "\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 1 1\n");
            var gt = Write("gt.obj", Triangle);
            var run = Within("evaluate", _dataset, "--renders", Renders(), "--out", _scratch.PathOf("eval"), "--geometry", recon, "--gt-mesh", gt);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("--geometry = " + recon + ": " + reason));
            // The same file as the ground truth names --gt-mesh.
            var asTruth = Within("evaluate", _dataset, "--renders", Renders(), "--out", _scratch.PathOf("eval2"), "--geometry", gt, "--gt-mesh", recon);
            Assert.That(asTruth.Err, Does.Contain("--gt-mesh = " + recon + ": " + reason), asTruth.ToString());
        }

        [Test]
        public void JsonIntegersBeyond32BitsAreProblemsNamingTheKeyInCheckValidateAndEvaluate()
        {
            // A geometry step of 1e11 and a point count of 3e9 used to end in "unexpected OverflowException".
            File.WriteAllText(Path.Combine(_dataset, "dataset_config.json"),
                "{ \"geometry\": { \"everyStep\": true, \"steps\": [ { \"step\": 100000000000, \"file\": \"geometry/step_0.ply\", \"triangles\": 123456789012345678901234567890 } ] }," +
                " \"pointCloud\": { \"file\": \"points3d.ply\", \"sha256\": \"00\", \"points\": 3000000000 } }");
            var validate = Within("validate", _dataset);
            Assert.That(validate.ExitCode, Is.EqualTo(1), validate.ToString());
            Assert.That(validate.Out, Does.Contain("problem: dataset_config.json: geometry step = 100000000000 (geometry/step_0.ply) is not a whole number from 0 to 2147483647. Capture again, or correct the record."));
            var check = Within("check", _dataset);
            Assert.That(check.Err + check.Out, Does.Not.Contain("unexpected"), check.ToString());
            var evaluate = Within("evaluate", _dataset, "--renders", Renders(), "--out", _scratch.PathOf("eval"), "--geometry", Write("recon.obj", Triangle));
            Assert.That(evaluate.ExitCode, Is.EqualTo(1), evaluate.ToString());
            Assert.That(evaluate.Err, Does.Contain("error: dataset_config.json = " + Path.Combine(_dataset, "dataset_config.json") + ": geometry step = 100000000000 (geometry/step_0.ply) is not a whole number from 0 to 2147483647."));
        }

        [TestCase("[0, 0, 0.5]", true, null)]
        [TestCase("[0, 0, \"x\", 1]", false, "rolling_shutter = [0,0,\"x\",1] is not [A, B, C] or [A, B, C, D] of finite numbers (instant-ngp's t = A + B·u + C·v + D·r).")]
        [TestCase("[0, 0]", false, "rolling_shutter = [0,0] is not [A, B, C] or [A, B, C, D] of finite numbers (instant-ngp's t = A + B·u + C·v + D·r).")]
        [TestCase("\"fast\"", false, "rolling_shutter = \"fast\" is not [A, B, C] or [A, B, C, D] of finite numbers (instant-ngp's t = A + B·u + C·v + D·r).")]
        public void AMalformedRollingShutterIsRefusedByCheckValidateAndTheNgpExport(string value, bool valid, string reason)
        {
            // In the train file's top level and, for the same value, in a val frame of its own.
            var train = Path.Combine(_dataset, "transforms_train.json");
            var json = JObject.Parse(File.ReadAllText(train));
            json["rolling_shutter"] = JToken.Parse(value);
            File.WriteAllText(train, json.ToString());
            var val = Path.Combine(_dataset, "transforms_val.json");
            var valJson = JObject.Parse(File.ReadAllText(val));
            valJson["frames"][1]["rolling_shutter"] = JToken.Parse(value);
            File.WriteAllText(val, valJson.ToString());

            var validate = Within("validate", _dataset);
            var check = Within("check", _dataset);
            var ngp = Within("convert", _dataset, "--to", "ngp", "--out", _scratch.PathOf("ngp"));
            if (valid)
            {
                Assert.That(validate.ExitCode, Is.EqualTo(0), validate.ToString());
                Assert.That(check.Out, Does.Not.Contain("rolling_shutter"), check.ToString());
                Assert.That(ngp.ExitCode, Is.EqualTo(0), ngp.ToString());
                Assert.That(JObject.Parse(File.ReadAllText(Path.Combine(_scratch.PathOf("ngp"), "transforms.json")))["rolling_shutter"].ToString(Newtonsoft.Json.Formatting.None), Is.EqualTo("[0.0,0.0,0.5,0.0]"));
                return;
            }
            Assert.That(validate.ExitCode, Is.EqualTo(1), validate.ToString());
            Assert.That(validate.Out, Does.Contain("problem: transforms_train.json: " + reason));
            Assert.That(validate.Out, Does.Contain("problem: transforms_val.json frame 1 (./val/r_1): " + reason));
            Assert.That(check.ExitCode, Is.EqualTo(1), check.ToString());
            Assert.That(check.Out, Does.Contain("problem: transforms_train.json [dataset]: " + reason));
            Assert.That(check.Out, Does.Contain("problem: transforms_val.json frame 1 [dataset]: " + reason));
            Assert.That(ngp.ExitCode, Is.EqualTo(1), ngp.ToString());
            Assert.That(ngp.Err, Does.Contain("error: --to ngp = train/r_0.png: " + reason));
            Assert.That(Directory.Exists(_scratch.PathOf("ngp")), Is.False, "nothing was written");
        }
    }
}
