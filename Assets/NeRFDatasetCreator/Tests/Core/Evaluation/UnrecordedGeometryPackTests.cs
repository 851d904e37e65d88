using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 32 item 12: validate and evaluate agree about a <c>geometry/target_mesh.ply</c> that dataset_config.json does
    /// not record. In this plugin's dataset (a config) validate warns that evaluate will not use it, and evaluate indeed
    /// refuses to take it for the target, naming the file and <c>--gt-mesh</c> (before, it scored against it without a
    /// word). In another tool's dataset (no config) evaluate uses the conventional file and says so in a note.
    /// </summary>
    [TestFixture]
    public class UnrecordedGeometryPackTests
    {
        TempFolder _temp;
        string _dataset, _renders, _recon;

        [SetUp]
        public void SetUp()
        {
            _temp = new TempFolder();
            _dataset = _temp.Combine("sphere");
            var views = AnalyticSphereDataset.Write(_dataset, 48, 40, train: 4, test: 2);
            _renders = _temp.Combine("renders");
            Directory.CreateDirectory(_renders);
            for (var i = 0; i < views.Count; i++)
                File.WriteAllBytes(Path.Combine(_renders, "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], 48, 40, 3), 48, 40, PngPixelFormat.Rgb8));
            _recon = _temp.Combine("recon.ply");
            using (var file = File.Create(_recon)) TargetMeshPly.Write(file, new[] { AnalyticSphereDataset.UvSphere(1.0, 16, 32) });
        }

        [TearDown] public void TearDown() => _temp.Dispose();

        EvaluationOptions Options(string outName) => new EvaluationOptions
        {
            DatasetFolder = _dataset, RendersFolder = _renders, Threads = 2, GeometryPath = _recon, TruthPoints = 20000, OutFolder = _temp.Combine(outName),
        };

        [Test]
        public void InThisPluginsDatasetAnUnrecordedMeshIsNotTakenForTheTarget()
        {
            // This plugin's dataset whose config records no geometry (the pack was off), with a stray mesh in geometry/.
            File.WriteAllText(Path.Combine(_dataset, DatasetLayout.ConfigFileName), "{ \"pluginVersion\": \"test\" }\n");
            var mesh = Path.Combine(_dataset, TargetMeshPly.Folder, TargetMeshPly.FileName);

            var warning = DatasetValidator.Validate(_dataset).Warnings.Single(w => w.File == TargetMeshPly.RelativePath);
            Assert.That(warning.Message, Does.Contain("so evaluate will not use it"));

            var refused = Assert.Throws<InvalidParameterException>(() => RenderEvaluator.Run(Options("refused")));
            Assert.That(refused.Problems.Single().ToString(), Is.EqualTo("--geometry = " + _recon + ": needs the ground-truth mesh, and " + mesh +
                " is not recorded in dataset_config.json's geometry, so it is not taken for this capture's target (a leftover of another capture?). " +
                "If it is this capture's target in the output frame, pass it explicitly: --gt-mesh " + mesh + "; or capture again with the geometry pack on."));
            Assert.That(Directory.Exists(_temp.Combine("refused")), Is.False, "refused before anything is written");

            // Named explicitly, it is the user's choice and is used.
            var explicitly = Options("explicit");
            explicitly.TruthMeshPath = mesh;
            var result = RenderEvaluator.Run(explicitly);
            Assert.That(result.Geometry.TruthSource, Is.EqualTo("--gt-mesh"));
        }

        [Test]
        public void InAnotherToolsDatasetTheConventionalMeshIsUsedWithANote()
        {
            Assert.That(File.Exists(Path.Combine(_dataset, DatasetLayout.ConfigFileName)), Is.False);
            var result = RenderEvaluator.Run(Options("conventional"));
            Assert.That(result.Geometry.TruthSource, Is.EqualTo("the geometry pack geometry/target_mesh.ply, by its conventional name (no dataset_config.json records it)"));
            Assert.That(result.Notes, Has.Member("--geometry is scored against geometry/target_mesh.ply, found by its conventional name: the dataset has no dataset_config.json to record it. Pass --gt-mesh to name the ground truth yourself."));
        }
    }
}
