using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <c>convert --to hdr-nerf</c> from an analytic capture with linear HDR colour, read back as HDR-NeRF's
    /// <c>load_syn_llff_data</c> reads it (xhuangcv/hdr-nerf load_syn_llff.py at 41bde0f): poses and field of view as
    /// written, five exposure times per view keyed by <c>file_path + '_k.png'</c>, bracket 2 equal to the dataset's PNG,
    /// and hand-computed codes for the bracket rule.
    /// </summary>
    [TestFixture]
    public class HdrNerfExportTests
    {
        TempFolder _temp;
        string _dataset, _export;

        [OneTimeSetUp]
        public void Write()
        {
            _temp = new TempFolder();
            _dataset = AnalyticDataset.Write(_temp.Path, "hdr", new AnalyticDataset.Options { Train = 4, Val = 1, Test = 2, PointCloud = 0, Configure = s => { s.Hdr.On = true; s.Hdr.Val = false; } });
            _export = _temp.Combine("hdr-nerf");
            DatasetConverter.Convert(_dataset, ExportTarget.HdrNerf, _export);
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        /// <summary>The loader's reading of one split (:87–111): every frame's images, poses and exposure times.</summary>
        static List<(string image, double[][] pose, double exposure)> Load(string basedir, string split, out double cameraAngleX)
        {
            var meta = JObject.Parse(File.ReadAllText(Path.Combine(basedir, "transforms_" + split + ".json")));
            var exposures = JObject.Parse(File.ReadAllText(Path.Combine(basedir, "exposure_" + split + ".json")));
            cameraAngleX = (double)meta["camera_angle_x"];
            var read = new List<(string, double[][], double)>();
            foreach (JObject frame in (JArray)meta["frames"])
                for (var i = 0; i < 5; i++) // test reads all five; train one of 0, 2, 4 (:102): every one must exist
                {
                    var key = (string)frame["file_path"] + "_" + i + ".png";
                    var fname = Path.Combine(basedir, key);
                    Assert.That(File.Exists(fname), Is.True, fname);
                    read.Add((fname, frame["transform_matrix"].ToObject<double[][]>(), (double)exposures[key]));
                }
            return read;
        }

        [Test]
        public void TheLoaderReadsFiveBracketsPerViewWithTheirTimesAndTheDatasetsPoses()
        {
            foreach (var split in new[] { "train", "test" })
            {
                var read = Load(_export, split, out var angle);
                var source = JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "transforms_" + split + ".json")));
                var frames = (JArray)source["frames"];
                Assert.That(angle, Is.EqualTo((double)source["camera_angle_x"]));
                Assert.That(read.Count, Is.EqualTo(5 * frames.Count));
                for (var v = 0; v < frames.Count; v++)
                {
                    var pose = frames[v]["transform_matrix"].ToObject<double[][]>();
                    for (var k = 0; k < 5; k++)
                    {
                        Assert.That(read[5 * v + k].pose, Is.EqualTo(pose));
                        Assert.That(read[5 * v + k].exposure, Is.EqualTo(new[] { 0.0625, 0.25, 1, 4, 16 }[k]));
                    }
                }
            }
            Assert.That(File.Exists(Path.Combine(_export, "transforms_val.json")), Is.False, "the loader reads train and test only");
        }

        [Test]
        public void BracketTwoIsTheDatasetsPngAndBrightnessGrowsWithTime()
        {
            var read = Load(_export, "test", out _);
            var png = PngReader.Read(Path.Combine(_dataset, "test", "r_0.png"));
            var brackets = Enumerable.Range(0, 5).Select(k => PngReader.Read(read[k].image)).ToArray();
            Assert.That(brackets.All(b => b.Channels == 4 && b.Width == png.Width && b.Height == png.Height), Is.True, "RGBA of the image's size, as the loader's half_res buffer expects");
            int n = png.Width * png.Height, far = 0, covered = 0;
            for (var i = 0; i < n; i++)
            {
                var a = png.Samples[4 * i + 3];
                if (a == 0) continue;
                covered++;
                for (var c = 0; c < 4; c++)
                {
                    // The hdr check's own tolerance: the EXR encoded is the PNG within one code.
                    if (Math.Abs(brackets[2].Samples[4 * i + c] - png.Samples[4 * i + c]) > 1) far++;
                    for (var k = 1; k < 5; k++) Assert.That(brackets[k].Samples[4 * i + c], Is.GreaterThanOrEqualTo(brackets[k - 1].Samples[4 * i + c]), "pixel " + i + " bracket " + k);
                }
            }
            Assert.That(covered, Is.GreaterThan(100));
            Assert.That(far, Is.EqualTo(0));
            Assert.That(Saturated(brackets[4]), Is.GreaterThan(Saturated(brackets[2])), "16× saturates more than 1×");
        }

        static int Saturated(PngImage image) => image.Samples.Count(s => s == 255);

        [Test]
        public void BracketsOfHandPickedLinearValues()
        {
            // Pixel 0: opaque linear (0.5, 0.25, 2.0); pixel 1: grey 0.1 at alpha 0.5 (round(127.5) = 128).
            var exr = new ExrImage(2, 1, new Dictionary<string, float[]>
            {
                ["R"] = new[] { 0.5f, 0.1f }, ["G"] = new[] { 0.25f, 0.1f }, ["B"] = new[] { 2.0f, 0.1f }, ["A"] = new[] { 1f, 0.5f },
            });
            // sRGB of 0.5/16 = 0.03125: 1.055·0.03125^(1/2.4) − 0.055 = 0.19393 → 49.45 → 49; 0.25/16 → 34; 2/16 → 99;
            // grey 0.1/16 → 18, straight, with its alpha 128.
            Assert.That(HdrNerfExport.Bracket(exr, 1.0 / 16), Is.EqualTo(new byte[] { 49, 34, 99, 255, 18, 18, 18, 128 }));
            // × 1: 0.5 → 188, 0.25 → 137, 2 clipped → 255; grey 0.1 → 89.
            Assert.That(HdrNerfExport.Bracket(exr, 1), Is.EqualTo(new byte[] { 188, 137, 255, 255, 89, 89, 89, 128 }));
            // × 4: 0.4 → 170; a transparent pixel is (0, 0, 0, 0) whatever its colour.
            exr.Channel("A")[1] = 0;
            Assert.That(HdrNerfExport.Bracket(exr, 4), Is.EqualTo(new byte[] { 255, 255, 255, 255, 0, 0, 0, 0 }));
        }

        [Test]
        public void ALensIsRefusedBeforeAnythingIsWritten()
        {
            var problem = LensExports.Refusal(new LensDistortion(LensModel.OpenCv, -0.1, 0.01, 0, 0, 0, 0), ExportTarget.HdrNerf);
            Assert.That(problem, Is.Not.Null);
            Assert.That(problem.Field, Is.EqualTo("--to"));
            Assert.That(problem.Reason, Does.Contain("camera_angle_x only"));
        }

        [Test]
        public void ACaptureWithoutLinearColourIsRefusedBeforeAnythingIsWritten()
        {
            var plain = AnalyticDataset.Write(_temp.Path, "plain", new AnalyticDataset.Options { Train = 2, Val = 1, Test = 1, PointCloud = 0 });
            var output = _temp.Combine("plain-hdr-nerf");
            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(plain, ExportTarget.HdrNerf, output));
            Assert.That(e.Problems[0].Field, Is.EqualTo("hdr_path"));
            Assert.That(e.Problems[0].Value, Does.StartWith("3 of 3 train/test views"));
            Assert.That(e.Problems[0].Fix, Does.Contain("\"hdr\""));
            Assert.That(Directory.Exists(output), Is.False);
        }
    }
}
