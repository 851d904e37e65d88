using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// check --model: the protocol against 3DGS's cfg_args (train.py's str(Namespace(**vars(args)))) and nerfstudio's
    /// config.yml (yaml.dump of the TrainerConfig), both written here as those trainers write them.
    /// </summary>
    public class TrainerConfigCheckTests
    {
        // As 3DGS train.py writes it for `python train.py -s /data/lego -m output/lego --eval` (ModelParams only, no -w).
        const string CfgArgsBlack = "Namespace(data_device='cuda', eval=True, images='images', model_path='output/lego', resolution=-1, sh_degree=3, source_path='/data/white_background=True/lego', white_background=False)";

        // The lines of a splatfacto config.yml that matter, at yaml.dump's indentation (keys sorted, nested by two spaces).
        static string ConfigYml(string background, string alpha) =>
            "!!python/object:nerfstudio.engine.trainer.TrainerConfig\n_target: !!python/name:nerfstudio.engine.trainer.Trainer ''\ndata: null\nexperiment_name: lego\n" +
            "method_name: splatfacto\nmixed_precision: false\n" +
            "pipeline: !!python/object:nerfstudio.pipelines.base_pipeline.VanillaPipelineConfig\n  _target: !!python/name:nerfstudio.pipelines.base_pipeline.VanillaPipeline ''\n" +
            "  datamanager: !!python/object:nerfstudio.data.datamanagers.full_images_datamanager.FullImageDatamanagerConfig\n" +
            "    dataparser: !!python/object:nerfstudio.data.dataparsers.blender_dataparser.BlenderDataParserConfig\n" +
            "      _target: !!python/name:nerfstudio.data.dataparsers.blender_dataparser.Blender ''\n      alpha_color: " + alpha + "\n      data: !!python/object/apply:pathlib.PosixPath\n      - data\n      - lego\n" +
            "  model: !!python/object:nerfstudio.models.splatfacto.SplatfactoModelConfig\n    _target: !!python/name:nerfstudio.models.splatfacto.SplatfactoModel ''\n    background_color: " + background + "\n" +
            "    camera_optimizer: !!python/object:nerfstudio.cameras.camera_optimizers.CameraOptimizerConfig\n      mode: 'off'\n";

        [Test]
        public void CfgArgsIsReadAsPythonWritesItAndAQuotedPathIsNeverTakenForTheKey()
        {
            var pairs = GaussianCfgArgs.Parse(CfgArgsBlack);
            Assert.That(pairs["white_background"], Is.EqualTo("False"));
            Assert.That(pairs["source_path"], Is.EqualTo("'/data/white_background=True/lego'"));
            Assert.That(GaussianCfgArgs.Background(pairs), Is.EqualTo("black"));
            Assert.That(GaussianCfgArgs.Background(GaussianCfgArgs.Parse(CfgArgsBlack.Replace("white_background=False", "white_background=True"))), Is.EqualTo("white"));
            Assert.That(GaussianCfgArgs.Parse("{\"white_background\": true}"), Is.Null);
        }

        [Test]
        public void AThreeDgsModelTrainedWithoutWIsWarnedAgainstAWhiteProtocol()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("d");
                Directory.CreateDirectory(dataset);
                File.WriteAllText(Path.Combine(dataset, EvalProtocolFile.FileName), EvalProtocolFile.Text(EvalProtocol.For(new BackgroundSettings())));
                var model = temp.Combine("model");
                Directory.CreateDirectory(model);
                File.WriteAllText(Path.Combine(model, "cfg_args"), CfgArgsBlack);
                var result = TrainerConfigCheck.Run(dataset, model);
                Assert.That(result.Warnings.Single(), Does.Contain("white_background=False (black) but eval_protocol.json says white").And.Contain("Train again with -w"));
                File.WriteAllText(Path.Combine(model, "cfg_args"), CfgArgsBlack.Replace("white_background=False", "white_background=True"));
                Assert.That(TrainerConfigCheck.Run(dataset, model).Warnings, Is.Empty);
                Assert.That(TrainerConfigCheck.Run(dataset, Path.Combine(model, "cfg_args")).Read.Single(), Does.Contain("white_background=True"), "the file itself may be named");
            }
        }

        [Test]
        public void ANerfstudioConfigIsComparedOnBackgroundAndAlphaColour()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("d"); // no protocol file: the default, white
                Directory.CreateDirectory(dataset);
                var model = temp.Combine("outputs", "lego", "splatfacto", "2026-12-07_000000");
                Directory.CreateDirectory(model);
                File.WriteAllText(Path.Combine(model, "config.yml"), ConfigYml("random", "white"));
                var random = TrainerConfigCheck.Run(dataset, model);
                Assert.That(random.Read.Single(), Is.EqualTo("nerfstudio " + Path.Combine(model, "config.yml") + ": method splatfacto, background_color random, alpha_color white"));
                Assert.That(random.Warnings.Single(), Does.Contain("background_color random but the default protocol").And.Contain("--pipeline.model.background-color white"));
                File.WriteAllText(Path.Combine(model, "config.yml"), ConfigYml("white", "black"));
                Assert.That(TrainerConfigCheck.Run(dataset, model).Warnings.Single(), Does.Contain("alpha_color black").And.Contain("--alpha-color white"));
                File.WriteAllText(Path.Combine(model, "config.yml"), ConfigYml("white", "white"));
                Assert.That(TrainerConfigCheck.Run(dataset, model).Warnings, Is.Empty);
            }
        }

        [Test]
        public void AFolderWithNeitherFileIsRefused()
        {
            using (var temp = new TempFolder())
            {
                var e = Assert.Throws<InvalidParameterException>(() => TrainerConfigCheck.Run(temp.Path, temp.Path));
                Assert.That(e.Problems[0].Field, Is.EqualTo("--model"));
                Assert.That(e.Problems[0].Reason, Does.Contain("neither cfg_args").And.Contain("config.yml"));
            }
        }
    }
}
