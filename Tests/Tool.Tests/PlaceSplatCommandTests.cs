using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// <c>nerf-dataset place-splat</c> as a user runs it: on a planned dataset (no images) and trainer folders laid out
    /// as each trainer writes them; what it prints, what --json holds, where cameras.json goes, and the refusals, which
    /// write nothing.
    /// </summary>
    [TestFixture]
    public class PlaceSplatCommandTests
    {
        Scratch _scratch;

        [SetUp] public void SetUp() => _scratch = new Scratch();

        [TearDown] public void TearDown() => _scratch.Dispose();

        const string Config = "{ \"seed\": 3, \"splits\": { \"train\": { \"count\": 6 }, \"val\": { \"count\": 2 }, \"test\": { \"count\": 2 } } }";

        /// <summary>A dataset made by the real <c>plan</c> command: dataset_config.json with unity_frame, no images.</summary>
        string Planned()
        {
            var output = _scratch.PathOf("planned");
            var run = ToolRun.Of("plan", "--config", _scratch.WriteText("plan.json", Config), "--out", output);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            return output;
        }

        [Test]
        public void APlannedDatasetAndA3dgsModelPrintTheTransformAndWriteJsonAndCameras()
        {
            var dataset = Planned();
            var model = SplatFixtures.GaussianSplattingModel(_scratch.PathOf("model"), SplatFixtures.SampleOutput());
            var json = _scratch.PathOf("placement.json");
            var run = ToolRun.Of("place-splat", dataset, "--model", model, "--json", json);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var ply = Path.Combine(model, "point_cloud", "iteration_30000", "point_cloud.ply");
            var cameras = Path.Combine(model, "point_cloud", "iteration_30000", "cameras.json");
            Assert.That(run.Out, Does.StartWith("placed " + ply + "\n  trainer 3dgs: the dataset's own frame"));
            Assert.That(run.Out, Does.Contain("  rotation (90, 0, 0) (Euler degrees, as the Inspector shows it); quaternion (x, y, z, w) (0.707106781, 0, 0, 0.707106781)"));
            Assert.That(run.Out, Does.Contain("(the negative component carries the reflection)"));
            Assert.That(run.Out, Does.Contain("wrote " + cameras + " (6 train cameras in the PLY's frame); aras-p's importer will read it"));
            var written = JObject.Parse(File.ReadAllText(json));
            foreach (var key in new[] { "trainer", "ply", "object_to_world", "position", "rotation", "scale" }) Assert.That(written[key], Is.Not.Null, key);
            Assert.That((string)written["trainer"], Is.EqualTo("3dgs"));
            Assert.That((string)written["ply"], Is.EqualTo(ply));
            Assert.That(written["object_to_world"].ToObject<double[][]>().Length, Is.EqualTo(4));
            Assert.That(written["scale"].ToObject<double[]>().Count(s => s < 0), Is.EqualTo(1));
            Assert.That(JArray.Parse(File.ReadAllText(cameras)), Has.Count.EqualTo(6));
        }

        [Test]
        public void AnExistingJsonFileIsRefusedBeforeAnythingIsWritten()
        {
            var dataset = Planned();
            var model = SplatFixtures.GaussianSplattingModel(_scratch.PathOf("model"), SplatFixtures.SampleOutput());
            var json = _scratch.WriteText("placement.json", "keep");
            var run = ToolRun.Of("place-splat", dataset, "--model", model, "--json", json);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("error: --json = " + json + ": already exists; place-splat never replaces a file."));
            Assert.That(File.ReadAllText(json), Is.EqualTo("keep"));
            Assert.That(File.Exists(Path.Combine(model, "point_cloud", "iteration_30000", "cameras.json")), Is.False);
        }

        [Test]
        public void AFolderNoTrainerWroteIsOneClearError()
        {
            var dataset = Planned();
            var run = ToolRun.Of("place-splat", dataset, "--model", dataset);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err.Split('\n').Count(l => l.StartsWith("error: ")), Is.EqualTo(1));
            Assert.That(run.Err, Does.Contain("holds none of the files a trainer leaves: looked for a 3DGS model folder"));
            Assert.That(run.Err, Does.Contain("place-splat refused: nothing was written."));
        }

        [Test]
        public void ATrainerThatContradictsTheFolderIsRefused()
        {
            var dataset = Planned();
            var run = SplatFixtures.NerfstudioRun(_scratch.PathOf("run"), SplatFixtures.SampleOutput(), _scratch.PathOf("run", "exports"));
            var result = ToolRun.Of("place-splat", dataset, "--model", run, "--trainer", "gsplat");
            Assert.That(result.ExitCode, Is.EqualTo(1), result.ToString());
            Assert.That(result.Err, Does.Contain("error: --trainer = gsplat: contradicts the folder: " + run + " is a nerfstudio output (found dataparser_transforms.json and config.yml)."));
            Assert.That(ToolRun.Of("place-splat", dataset, "--model", run, "--trainer", "inria").Err, Does.Contain("--trainer = inria: is not 3dgs, nerfstudio, gsplat."));
        }

        [Test]
        public void WithoutModelTheUsageSaysWhatToPass()
        {
            var run = ToolRun.Of("place-splat", Planned());
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("place-splat needs --model <folder>"));
        }
    }
}
