using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Which trainer wrote a folder, from its own files, and the refusals: an unknown folder names everything looked
    /// for, a --trainer that contradicts the folder names what was found, a folder missing its PLY says how to make it.
    /// </summary>
    [TestFixture]
    public class TrainedModelTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();

        [TearDown] public void Delete() => _temp.Dispose();

        static ValidationProblem Refusal(TestDelegate call) => Assert.Throws<InvalidParameterException>(call).Problems.Single();

        [Test]
        public void EachTrainersFolderIsRecognisedFromItsFiles()
        {
            var centres = SplatFixtures.SampleOutput();
            Assert.That(TrainedModel.Find(SplatFixtures.GaussianSplattingModel(_temp.Combine("m"), centres)).Trainer, Is.EqualTo("3dgs"));
            var run = _temp.Combine("run");
            Assert.That(TrainedModel.Find(SplatFixtures.NerfstudioRun(run, centres, Path.Combine(run, "exports", "splat"))).PlyPath, Is.EqualTo(Path.Combine(run, "exports", "splat", "splat.ply")));
            Assert.That(TrainedModel.Find(SplatFixtures.GsplatResult(_temp.Combine("g"), centres, "data", normalise: false)).Trainer, Is.EqualTo("gsplat"));
        }

        [Test]
        public void AnUnknownFolderNamesEverythingLookedFor()
        {
            Directory.CreateDirectory(_temp.Combine("empty"));
            var p = Refusal(() => TrainedModel.Find(_temp.Combine("empty")));
            Assert.That(p.Field, Is.EqualTo("--model"));
            Assert.That(p.Reason, Does.Contain("point_cloud/iteration_<N>/point_cloud.ply").And.Contains("dataparser_transforms.json").And.Contains("cfg.yml"));
            Assert.That(Refusal(() => TrainedModel.Find(_temp.Combine("missing"))).Reason, Is.EqualTo("is not an existing folder."));
        }

        [Test]
        public void ATrainerThatContradictsTheFolderIsRefusedNamingWhatWasFound()
        {
            var model = SplatFixtures.GaussianSplattingModel(_temp.Combine("m"), SplatFixtures.SampleOutput());
            var p = Refusal(() => TrainedModel.Find(model, "nerfstudio"));
            Assert.That(p.Field, Is.EqualTo("--trainer"));
            Assert.That(p.Reason, Does.Contain("is a 3dgs output (found cfg_args, point_cloud/iteration_30000/point_cloud.ply)"));
            Assert.That(Refusal(() => TrainedModel.Find(model, "splatfacto")).Reason, Does.Contain("is not a trainer this tool places"));
        }

        [Test]
        public void ANerfstudioRunWithoutItsExportSaysHowToMakeIt()
        {
            var run = SplatFixtures.NerfstudioRun(_temp.Combine("run"), SplatFixtures.SampleOutput(), exportFolder: null);
            var p = Refusal(() => TrainedModel.Find(run));
            Assert.That(p.Reason, Does.Contain("holds no splat.ply"));
            Assert.That(p.Fix, Does.Contain("ns-export gaussian-splat --load-config " + Path.Combine(run, "config.yml")).And.Contains("--ply <file>"));
            var elsewhere = _temp.Combine("exports", "splat.ply");
            SplatFixtures.WriteGaussianPly(elsewhere, SplatFixtures.SampleOutput());
            Assert.That(TrainedModel.Find(run, ply: elsewhere).PlyPath, Is.EqualTo(elsewhere));
        }

        [Test]
        public void ANerfactoRunIsNotASplat()
        {
            var run = SplatFixtures.NerfstudioRun(_temp.Combine("run"), SplatFixtures.SampleOutput(), _temp.Combine("run", "exports"), method: "nerfacto");
            Assert.That(Refusal(() => TrainedModel.Find(run)).Reason, Does.Contain("is a nerfstudio nerfacto run"));
        }

        [Test]
        public void AModelThatHasNotSavedYetIsRefused()
        {
            Directory.CreateDirectory(_temp.Combine("m"));
            File.WriteAllText(_temp.Combine("m", "cfg_args"), "Namespace()");
            Assert.That(Refusal(() => TrainedModel.Find(_temp.Combine("m"))).Reason, Does.Contain("without point_cloud/iteration_<N>/point_cloud.ply"));
            Directory.CreateDirectory(_temp.Combine("g"));
            File.WriteAllText(_temp.Combine("g", "cfg.yml"), "normalize_world_space: false\n");
            Assert.That(Refusal(() => TrainedModel.Find(_temp.Combine("g"))).Fix, Does.Contain("--save-ply"));
        }

        [Test]
        public void AGsplatRunWhoseDataIsGoneIsRefusedNamingBothPlacesTried()
        {
            var result = SplatFixtures.GsplatResult(_temp.Combine("results", "run"), SplatFixtures.SampleOutput(), "gone", normalise: true);
            var p = Refusal(() => TrainedModel.Find(result));
            Assert.That(p.Field, Is.EqualTo("cfg.yml: data_dir"));
            Assert.That(p.Reason, Does.Contain(_temp.Combine("results", "gone")).And.Contains("against the working directory"));
            Assert.That(p.Fix, Does.Contain("--no-normalize-world-space"));
        }
    }
}
