using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// <c>nerf-dataset flow</c>: adds flow/ to a dynamic dataset captured without it, writes nothing else, and refuses a
    /// static dataset, an existing flow/ and a geometry pack missing a step, each with nothing written.
    /// </summary>
    [TestFixture]
    public class FlowCommandTests
    {
        Scratch _scratch;

        [OneTimeSetUp] public void Create() => _scratch = new Scratch();

        [OneTimeTearDown] public void Delete() => _scratch.Dispose();

        string Dynamic(string name) => AnalyticDataset.Write(_scratch.Root, name, new AnalyticDataset.Options
        {
            Width = 32, Height = 24, Supersampling = 1, Train = 3, Val = 1, Test = 1, TimeSteps = 3, Monocular = true, PointCloud = 0,
            MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
        });

        static string[] Files(string folder) =>
            Directory.GetFiles(folder, "*", SearchOption.AllDirectories).Select(f => Path.GetRelativePath(folder, f)).OrderBy(f => f).ToArray();

        [Test]
        public void AddsFlowAndTouchesNothingElse()
        {
            var folder = Dynamic("dynamic");
            var before = Files(folder).ToDictionary(f => f, f => File.ReadAllBytes(Path.Combine(folder, f)));
            var run = ToolRun.Of("flow", folder, "--spans", "1,2", "--tracks", "0", "--stride", "4", "--threads", "2");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.StartWith("wrote flow/ holds 6 frame pairs of 1 video and 1 tracks file (flow/flow.json)."));
            var record = FlowRecord.Read(folder);
            Assert.That(record.Pairs.Select(p => p.From + ">" + p.To), Is.EqualTo(new[] { "0>1", "1>2", "1>0", "2>1", "0>2", "2>0" }));
            Assert.That(record.SceneFlow, Is.True);
            foreach (var pair in before) Assert.That(File.ReadAllBytes(Path.Combine(folder, pair.Key)), Is.EqualTo(pair.Value), pair.Key + " is unchanged");
            Assert.That(Files(folder).Where(f => !before.ContainsKey(f)), Has.All.StartWith("flow" + Path.DirectorySeparatorChar));
        }

        [Test]
        public void TheOptionsReachTheSettings()
        {
            var folder = Dynamic("options");
            var run = ToolRun.Of("flow", folder, "--no-backward", "--no-scene-flow");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            var record = FlowRecord.Read(folder);
            Assert.That(record.Pairs.All(p => p.Forward), Is.True);
            Assert.That(record.SceneFlow, Is.False);
            Assert.That(Directory.GetFiles(Path.Combine(folder, "flow", "train"), "scene_flow_*"), Is.Empty);
        }

        [Test]
        public void AStaticDatasetIsRefused()
        {
            var folder = AnalyticDataset.Write(_scratch.Root, "static", new AnalyticDataset.Options { Width = 32, Height = 24, Train = 2, Val = 1, Test = 1, PointCloud = 0 });
            var run = ToolRun.Of("flow", folder);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("error: time").And.Contain("has no time").And.Contain("flow refused: nothing was written."));
            Assert.That(Directory.Exists(Path.Combine(folder, "flow")), Is.False);
        }

        [Test]
        public void AnExistingFlowFolderIsRefusedAndKept()
        {
            var folder = Dynamic("existing");
            Directory.CreateDirectory(Path.Combine(folder, "flow"));
            File.WriteAllText(Path.Combine(folder, "flow", "mine.txt"), "not the plugin's");
            var run = ToolRun.Of("flow", folder);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("exists already").And.Contain("flow refused: nothing was written."));
            Assert.That(Files(Path.Combine(folder, "flow")), Is.EqualTo(new[] { "mine.txt" }));
        }

        [Test]
        public void AMissingStepMeshIsRefusedNamingIt()
        {
            var folder = Dynamic("missing");
            File.Delete(Path.Combine(folder, "geometry", "target_mesh_t0001.ply"));
            var run = ToolRun.Of("flow", folder);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Err, Does.Contain("target_mesh_t0001.ply"));
            Assert.That(Directory.Exists(Path.Combine(folder, "flow")), Is.False);
        }

        [TestCase("--spans", "0", "--spans = 0: is not a list of step spans of 1 or more")]
        [TestCase("--spans", "1,1", "names a value twice")]
        [TestCase("--tracks", "a", "--tracks = a: is not a list of query frames")]
        [TestCase("--stride", "0", "--stride = 0: is not a whole number of 1 or more")]
        [TestCase("--threads", "0", "--threads = 0: is not a whole number of 1 or more")]
        public void BadOptionsAreUsageErrors(string option, string value, string expected)
        {
            var run = ToolRun.Of("flow", _scratch.PathOf("none"), option, value);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain(expected));
        }
    }
}
