using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>eval_protocol.json: the default per background, the settings key's validation, the file's round trip, and ProtocolBackground reading it first.</summary>
    public class EvalProtocolTests
    {
        static BackgroundSettings Solid(string hex) => BackgroundSettings.Parse(hex);

        [Test]
        public void ATransparentDatasetIsScoredOverWhiteAndASolidOneOverItsOwnColour()
        {
            var transparent = EvalProtocol.For(new BackgroundSettings());
            Assert.That((transparent.Background, transparent.R, transparent.G, transparent.B), Is.EqualTo(("white", (byte)255, (byte)255, (byte)255)));
            var grey = EvalProtocol.For(Solid("#80a0ff"));
            Assert.That((grey.Background, grey.R, grey.G, grey.B), Is.EqualTo(("dataset", (byte)0x80, (byte)0xa0, (byte)0xff)));
            var black = EvalProtocol.For(new BackgroundSettings(), "black");
            Assert.That((black.Background, black.R, black.G, black.B), Is.EqualTo(("black", (byte)0, (byte)0, (byte)0)));
            var random = EvalProtocol.For(new BackgroundSettings(), "random");
            Assert.That((random.EvaluationBackgroundName, random.R), Is.EqualTo(("white", (byte)255)), "random backgrounds in training are scored over white");
            Assert.That(EvalProtocol.For(null).Background, Is.EqualTo("white"), "no dataset_config.json: nerf_synthetic's white");
            Assert.That(EvalProtocol.For(BackgroundSettings.Parse("sky")).Background, Is.EqualTo("white"), "opaque sky images: white for RGBA renders");
        }

        [Test]
        public void AChoiceThatContradictsTheDatasetIsRefusedNamingTheKey()
        {
            var own = Assert.Throws<InvalidParameterException>(() => EvalProtocol.For(new BackgroundSettings(), "dataset"));
            Assert.That(own.Problems[0].Field, Is.EqualTo("evaluationBackground"));
            Assert.That(own.Problems[0].Reason, Does.Contain("transparent"));
            var white = Assert.Throws<InvalidParameterException>(() => EvalProtocol.For(Solid("#808080"), "white"));
            Assert.That(white.Problems[0].ToString(), Does.Contain("#808080").And.Contain("opaque"));
            Assert.That(EvalProtocol.For(Solid("#ffffff"), "white").Background, Is.EqualTo("white"), "white on a white solid background is the same colour");
            var typo = EvalProtocol.Problem(new BackgroundSettings(), "whte");
            Assert.That(typo.Reason, Does.Contain("white, black, random, dataset").And.Contain("white"));
        }

        [Test]
        public void TheSettingsKeyRoundTripsAndIsValidated()
        {
            var settings = new DatasetSettings { EvaluationBackground = "black" };
            var text = DatasetSettingsJson.Write(settings);
            Assert.That(text, Does.Contain("\"evaluationBackground\": \"black\""));
            Assert.That(DatasetSettingsJson.Read(text).Settings.EvaluationBackground, Is.EqualTo("black"));
            Assert.That(DatasetSettingsJson.Write(new DatasetSettings()), Does.Not.Contain("evaluationBackground"), "left out when not chosen");
            var bad = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"evaluationBackground\": \"grey\" }", "/tmp/x.json"));
            Assert.That(bad.Message, Does.Contain("evaluationBackground").And.Contain("white, black, random, dataset"));
            var contradicting = new DatasetSettings { EvaluationBackground = "dataset" };
            Assert.That(SettingsValidator.Validate(contradicting).Select(p => p.Field), Does.Contain("evaluationBackground"));
        }

        [Test]
        public void TheFileReadsBackWhatWasWrittenAndNamesTheTrainerFlags()
        {
            using (var temp = new TempFolder())
            {
                var written = EvalProtocol.For(new BackgroundSettings());
                File.WriteAllText(temp.Combine(EvalProtocolFile.FileName), EvalProtocolFile.Text(written));
                var json = JObject.Parse(File.ReadAllText(temp.Combine(EvalProtocolFile.FileName)));
                Assert.That((string)json["trainer_flags"]["3dgs"], Does.StartWith("-w"));
                Assert.That((string)json["trainer_flags"]["nerf-pytorch"], Is.EqualTo("--white_bkgd"));
                Assert.That((string)json["trainer_flags"]["nerfstudio"], Does.Contain("--pipeline.model.background-color white"));
                Assert.That((string)json["lpips"]["network"], Is.EqualTo("vgg"));
                Assert.That((string)json["compositing"], Does.Contain("straight alpha"));
                var read = EvalProtocolFile.Read(temp.Path);
                Assert.That((read.Background, read.R, read.EvaluationSplit, read.ResolutionFactor, string.Join(",", read.TrainSplits)), Is.EqualTo(("white", (byte)255, "test", 1, "train")));

                var black = JObject.Parse(EvalProtocolFile.Text(EvalProtocol.For(new BackgroundSettings(), "black")));
                Assert.That((string)black["trainer_flags"]["3dgs"], Does.StartWith("no -w"));
            }
        }

        [Test]
        public void ADamagedProtocolIsRefusedNamingTheFileAndKey()
        {
            using (var temp = new TempFolder())
            {
                var path = temp.Combine(EvalProtocolFile.FileName);
                File.WriteAllText(path, EvalProtocolFile.Text(EvalProtocol.For(null)).Replace("\"background\": \"white\"", "\"background\": \"blue\""));
                var e = Assert.Throws<InvalidParameterException>(() => EvalProtocolFile.Read(temp.Path));
                Assert.That(e.Problems[0].Field, Is.EqualTo("eval_protocol.json: background"));
                Assert.That(e.Problems[0].Reason, Does.Contain("\"blue\""));
                File.WriteAllText(path, "{ not json");
                Assert.That(Assert.Throws<InvalidParameterException>(() => EvalProtocolFile.Read(temp.Path)).Problems[0].Reason, Does.Contain("not valid JSON"));
                Assert.That(DatasetValidator.Validate(temp.Path).Problems.Select(p => p.ToString()), Has.Some.Contains(EvalProtocolFile.FileName));
            }
        }

        [Test]
        public void ProtocolBackgroundReadsTheFileBeforeTheDatasetsBackground()
        {
            using (var temp = new TempFolder())
            {
                Assert.That(ProtocolBackground.For(temp.Path), Is.EqualTo(("white", (byte)255, (byte)255, (byte)255)), "no protocol, no config: white");
                File.WriteAllText(temp.Combine(EvalProtocolFile.FileName), EvalProtocolFile.Text(EvalProtocol.For(new BackgroundSettings(), "black")));
                Assert.That(ProtocolBackground.For(temp.Path), Is.EqualTo(("black", (byte)0, (byte)0, (byte)0)));
            }
        }

        [Test]
        public void ACaptureWritesTheProtocolAndConvertAndMergeKeepIt()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "black", new AnalyticDataset.Options { Train = 3, Val = 1, Test = 2, Width = 24, Height = 18, Supersampling = 1, PointCloud = 0,
                    Configure = s => s.EvaluationBackground = "black" });
                var protocol = File.ReadAllText(Path.Combine(folder, EvalProtocolFile.FileName));
                Assert.That(EvalProtocolFile.Read(folder).Background, Is.EqualTo("black"));

                DatasetConverter.Convert(folder, ExportTarget.Ngp);
                Assert.That(File.ReadAllText(Path.Combine(folder, NgpWriter.FolderName, EvalProtocolFile.FileName)), Is.EqualTo(protocol), "convert copies it beside the export");
                Assert.That(OwnDataset.WhyNotOurs(folder), Is.Null, "the protocol and its copy are the product's own files");

                var shards = Enumerable.Range(0, 2).Select(i => AnalyticDataset.Write(temp.Path, "sharded", new AnalyticDataset.Options
                {
                    Train = 3, Val = 1, Test = 2, Width = 24, Height = 18, Supersampling = 1, PointCloud = 0, Shard = new ShardSpec(i, 2), DatasetFolder = "shard" + i,
                    Configure = s => s.EvaluationBackground = "black",
                })).ToList();
                var merged = temp.Combine("merged");
                var result = ShardMerger.Merge(shards, merged);
                Assert.That(result.Problems.Select(p => p.ToString()), Is.Empty);
                Assert.That(result.Warnings.Where(w => w.Contains(EvalProtocolFile.FileName)), Is.Empty, "not left behind as an unknown file");
                Assert.That(EvalProtocolFile.Read(merged).Background, Is.EqualTo("black"));

                // A shard whose protocol differs stops the merge.
                File.WriteAllText(Path.Combine(shards[1], EvalProtocolFile.FileName), EvalProtocolFile.Text(EvalProtocol.For(new BackgroundSettings())));
                var refused = ShardMerger.Merge(shards, temp.Combine("merged2"));
                Assert.That(refused.Problems.Select(p => p.ToString()), Has.Some.Contains("is not the same protocol"));
            }
        }
    }
}
