using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A dataset with exposure and white balance written through the capture's own writer from analytic renders
    /// (<see cref="AnalyticDataset"/>): the recorded keys, the clean images and the EXIF, the check passing on it, and
    /// the writer bugs the check must catch, planted in copies.
    /// </summary>
    [TestFixture]
    public class ExposureDatasetTests
    {
        TempFolder _temp;
        string _dataset, _withoutClean;
        int _copies;

        static void Exposure(DatasetSettings s, bool clean)
        {
            s.Exposure.Mode = ExposureMode.Random;
            s.Exposure.EvMin = -1;
            s.Exposure.EvMax = 1;
            s.Exposure.GainMin = 0.7;
            s.Exposure.GainMax = 1.4;
            s.Exposure.WriteClean = clean;
            s.Seed = 11;
        }

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            var options = new AnalyticDataset.Options { Train = 6, Val = 2, Test = 2, PointCloud = 0, Configure = s => Exposure(s, true) };
            _dataset = AnalyticDataset.Write(_temp.Path, "exposed", options);
            options.Configure = s => Exposure(s, false);
            _withoutClean = AnalyticDataset.Write(_temp.Path, "exposed-no-clean", options);
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        string Copy() => DatasetFaults.Copy(_dataset, _temp.Combine("fault-" + ++_copies));

        static DatasetCheckReport Check(string folder)
        {
            var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            TestContext.WriteLine(string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(8)));
            return report;
        }

        static JArray Frames(string folder, string split) => (JArray)JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_" + split + ".json")))["frames"];

        [Test]
        public void TrainFramesRecordTheValuesThePlanGivesAndTheCleanImage()
        {
            var settings = DatasetSettingsJson.Read(JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "dataset_config.json")))["settings"].ToString()).Settings;
            Assert.That(settings.Exposure.Mode, Is.EqualTo(ExposureMode.Random), "the distribution is in dataset_config.json's settings");
            var plan = ExposurePlan.Of(settings);
            foreach (JObject frame in Frames(_dataset, "train"))
            {
                var index = int.Parse(((string)frame["file_path"]).Split('_').Last());
                var expected = plan.For(DatasetSplit.Train, index);
                Assert.That((double)frame["exposure_ev"], Is.EqualTo(expected.Ev));
                Assert.That(frame["white_balance"].ToObject<double[]>(), Is.EqualTo(new[] { expected.R, expected.G, expected.B }));
                Assert.That((string)frame["clean_path"], Is.EqualTo("./train/r_" + index + "_clean.png"));
                Assert.That(File.Exists(Path.Combine(_dataset, "train", "r_" + index + "_clean.png")));
            }
            foreach (JObject frame in Frames(_dataset, "test"))
                Assert.That(frame.Properties().Select(p => p.Name), Has.None.StartsWith("exposure").And.None.EqualTo("clean_path"), "test is not modified");
            Assert.That(Frames(_withoutClean, "train").Cast<JObject>().All(f => f["clean_path"] == null && f["exposure_ev"] != null));
        }

        [Test]
        public void ModifiedImageIsTheCleanOneTimesTheGainInLinearLight()
        {
            var frame = (JObject)Frames(_dataset, "train")[0];
            var e = ExposureKeys.Read(frame).Values.Value;
            var clean = PngReader.Read(Path.Combine(_dataset, "train", "r_0_clean.png"));
            var modified = PngReader.Read(Path.Combine(_dataset, "train", "r_0.png"));
            var changed = 0;
            for (var i = 0; i < clean.Samples.Length; i++)
            {
                var c = i % 4;
                if (c == 3) { Assert.That(modified.Samples[i], Is.EqualTo(clean.Samples[i]), "alpha"); continue; }
                var expected = Math.Min(1, Srgb.DecodeExact(clean.Samples[i] / 255.0) * Math.Pow(2, e.Ev) * e.Gain(c));
                var got = modified.Samples[i];
                Assert.That(Math.Abs((expected <= 0.0031308 ? 12.92 * expected : 1.055 * Math.Pow(expected, 1 / 2.4) - 0.055) * 255 - got), Is.LessThanOrEqualTo(0.5 + 1e-9));
                if (got != clean.Samples[i]) changed++;
            }
            Assert.That(changed, Is.GreaterThan(100), "the view is really changed");
        }

        [Test]
        public void ModifiedImageCarriesItsEvInExif()
        {
            var bytes = File.ReadAllBytes(Path.Combine(_dataset, "train", "r_2.png"));
            Assert.That(System.Text.Encoding.ASCII.GetString(bytes, 37, 4), Is.EqualTo("eXIf"));
            var clean = File.ReadAllBytes(Path.Combine(_dataset, "train", "r_2_clean.png"));
            Assert.That(System.Text.Encoding.ASCII.GetString(clean, 37, 4), Is.Not.EqualTo("eXIf"));
        }

        [Test]
        public void CheckAndValidatePassOnTheWrittenDataset()
        {
            foreach (var folder in new[] { _dataset, _withoutClean })
            {
                var report = Check(folder);
                var result = report.Results.Single(r => r.Name == "exposure");
                Assert.That(result.Status, Is.EqualTo(DatasetCheckStatus.Passed), result.Figure);
                Assert.That(report.Failed, Is.False);
            }
            Assert.That(Check(_dataset).Results.Single(r => r.Name == "exposure").Figure, Does.Contain("6 compared"));
            var validation = DatasetValidator.Validate(_dataset);
            Assert.That(validation.Problems, Is.Empty, string.Join("\n", validation.Problems));
            Assert.That(validation.Warnings, Is.Empty, "the clean images are companions, not stray images: " + string.Join("\n", validation.Warnings));
        }

        [Test]
        public void ConvertCarriesTheExifIntoTheColmapImagesAndReadsTheKeysEverywhere()
        {
            var folder = DatasetFaults.Copy(_dataset, _temp.Combine("convert"));
            foreach (var target in new[] { ExportTarget.Nerfstudio, ExportTarget.Ngp, ExportTarget.Colmap })
                DatasetConverter.Convert(folder, target);
            var images = Directory.GetFiles(Path.Combine(folder, "colmap", "images"));
            var train = images.Where(f => Path.GetFileName(f).StartsWith("train_", StringComparison.Ordinal)).ToList();
            Assert.That(train, Has.Count.EqualTo(6));
            foreach (var file in images)
            {
                var bytes = File.ReadAllBytes(file);
                var exif = System.Text.Encoding.ASCII.GetString(bytes, 37, 4) == "eXIf";
                Assert.That(exif, Is.EqualTo(train.Contains(file)), file + ": the modified train images keep their EXIF, the others have none");
            }
        }

        /// <summary>Rewrites every modified train image from its clean image with a wrong stage.</summary>
        void Plant(string folder, Func<byte, int, ViewExposure, byte> wrong)
        {
            foreach (JObject frame in Frames(folder, "train"))
            {
                var e = ExposureKeys.Read(frame).Values.Value;
                var cleanFile = Path.Combine(folder, ((string)frame["clean_path"]).Substring(2));
                var clean = PngReader.Read(cleanFile);
                var samples = (byte[])clean.Samples.Clone();
                for (var i = 0; i < samples.Length; i++)
                    if (i % 4 != 3) samples[i] = wrong(samples[i], i % 4, e);
                File.WriteAllBytes(Path.Combine(folder, ((string)frame["file_path"]).Substring(2) + ".png"), PngWriter.Encode(samples, clean.Width, clean.Height, PngPixelFormat.Rgba8));
            }
        }

        static byte Linear(byte b, double scale) => Srgb.EncodeByteExact(Math.Min(1, Srgb.DecodeExact(b / 255.0) * scale));

        static void AssertCaught(DatasetCheckReport report)
        {
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(5));
            Assert.That(report.Results.Single(r => r.Name == "exposure").Status, Is.EqualTo(DatasetCheckStatus.Failed), text);
            Assert.That(report.Problems.Count(p => p.Check == "exposure" && p.Frame >= 0), Is.GreaterThanOrEqualTo(4), text);
        }

        [Test]
        public void CorrectRewriteStillPasses()
        {
            var folder = Copy();
            Plant(folder, (b, c, e) => Linear(b, e.Scale(c)));
            Assert.That(Check(folder).Results.Single(r => r.Name == "exposure").Status, Is.EqualTo(DatasetCheckStatus.Passed));
        }

        [Test]
        public void GainAppliedToSrgbValuesIsCaught()
        {
            var folder = Copy();
            Plant(folder, (b, c, e) => (byte)Math.Min(255, Math.Round(b * e.Scale(c))));
            AssertCaught(Check(folder));
        }

        [Test]
        public void GainsSwappedBetweenChannelsAreCaught()
        {
            var folder = Copy();
            Plant(folder, (b, c, e) => Linear(b, e.Scale(2 - c)));
            AssertCaught(Check(folder));
        }

        [Test]
        public void EvSignFlippedIsCaught()
        {
            var folder = Copy();
            Plant(folder, (b, c, e) => Linear(b, Math.Pow(2, -e.Ev) * e.Gain(c)));
            AssertCaught(Check(folder));
        }

        [Test]
        public void RecordedValuesOutOfRangeOrOnSomeFramesOnlyAreCaught()
        {
            var folder = DatasetFaults.Copy(_withoutClean, _temp.Combine("fault-" + ++_copies));
            DatasetFaults.EditTransforms(folder, json =>
            {
                var frames = (JArray)json["frames"];
                if (frames.Count == 6)
                {
                    frames[0]["exposure_ev"] = 40;
                    ((JObject)frames[1]).Remove("exposure_ev");
                    ((JObject)frames[1]).Remove("white_balance");
                    frames[2]["white_balance"] = new JArray(1, 1);
                }
            });
            var report = Check(folder);
            Assert.That(report.Results.Single(r => r.Name == "exposure").Status, Is.EqualTo(DatasetCheckStatus.Failed));
            Assert.That(report.Problems.Count(p => p.Check == "exposure"), Is.EqualTo(2));
            Assert.That(report.Results.Single(r => r.Name == "exposure").Figure, Does.Contain("some frames only"));
        }
    }
}
