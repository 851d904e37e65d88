using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A dataset with "hdr" written through the capture's own writer from analytic renders (<see cref="AnalyticDataset"/>,
    /// EXRs by <see cref="ExrWriter"/>): the keys and files, the check passing on it (also with exposure, with and without
    /// clean images), and planted faults it fails.
    /// </summary>
    [TestFixture]
    public class HdrDatasetTests
    {
        TempFolder _temp;
        string _dataset, _exposed, _exposedNoClean;
        int _copies;

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _dataset = AnalyticDataset.Write(_temp.Path, "hdr", new AnalyticDataset.Options { Train = 4, Val = 1, Test = 2, PointCloud = 0, Configure = s => { s.Hdr.On = true; s.Hdr.Val = false; } });
            foreach (var clean in new[] { true, false })
            {
                var folder = AnalyticDataset.Write(_temp.Path, clean ? "hdr-exposed" : "hdr-exposed-no-clean", new AnalyticDataset.Options
                {
                    Train = 4, Val = 1, Test = 1, PointCloud = 0,
                    Configure = s =>
                    {
                        s.Hdr.On = true;
                        s.Exposure.Mode = ExposureMode.Random;
                        s.Exposure.EvMin = -1.5;
                        s.Exposure.EvMax = 1.5;
                        s.Exposure.WriteClean = clean;
                    },
                });
                if (clean) _exposed = folder;
                else _exposedNoClean = folder;
            }
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        static DatasetCheckResult Hdr(string folder, out DatasetCheckReport report)
        {
            report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            TestContext.WriteLine(string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(8)));
            return report.Results.Single(r => r.Name == "hdr");
        }

        [Test]
        public void EveryFrameOfTheChosenSplitsNamesItsExr()
        {
            foreach (var (split, expected) in new[] { ("train", true), ("val", false), ("test", true) })
                foreach (JObject frame in (JArray)JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "transforms_" + split + ".json")))["frames"])
                {
                    var image = (string)frame["file_path"];
                    Assert.That((string)frame["hdr_path"], Is.EqualTo(expected ? image + "_hdr.exr" : null), image);
                    Assert.That(File.Exists(Path.Combine(_dataset, image + "_hdr.exr")), Is.EqualTo(expected));
                }
            var exr = ExrReader.Read(Path.Combine(_dataset, "train", "r_0_hdr.exr"));
            Assert.That((exr.Width, exr.Height), Is.EqualTo((96, 72)));
            Assert.That(exr.Channel("A").Max(), Is.EqualTo(1f));
            Assert.That(exr.Channel("A").Min(), Is.EqualTo(0f), "the background is transparent");
        }

        [Test]
        public void TheCheckPassesWithAndWithoutExposure()
        {
            foreach (var folder in new[] { _dataset, _exposed, _exposedNoClean })
            {
                var hdr = Hdr(folder, out var report);
                Assert.That(hdr.Status, Is.EqualTo(DatasetCheckStatus.Passed), folder);
                Assert.That(report.Problems.Where(p => p.Check == "hdr"), Is.Empty);
            }
        }

        [Test]
        public void AScaledOrGammaEncodedExrFails()
        {
            foreach (var fault in new[] { "scaled", "gamma" })
            {
                var copy = DatasetFaults.Copy(_dataset, _temp.Combine("fault-" + ++_copies));
                var path = Path.Combine(copy, "train", "r_1_hdr.exr");
                var exr = ExrReader.Read(path);
                int w = exr.Width, h = exr.Height;
                var pixels = new float[w * h * 4];
                for (var y = 0; y < h; y++)
                    for (var x = 0; x < w; x++)
                    {
                        var at = y * w + x;
                        var o = ((h - 1 - y) * w + x) * 4; // back to texture order
                        for (var c = 0; c < 3; c++)
                        {
                            var v = exr.Channel("RGB".Substring(c, 1))[at];
                            pixels[o + c] = fault == "scaled" ? v * 2 : (float)Srgb.EncodeExact(v);
                        }
                        pixels[o + 3] = exr.Channel("A")[at];
                    }
                File.WriteAllBytes(path, ExrWriter.Encode(pixels, w, h, 4));
                var hdr = Hdr(copy, out var report);
                Assert.That(hdr.Status, Is.EqualTo(DatasetCheckStatus.Failed), fault);
                Assert.That(report.Problems.Single(p => p.Check == "hdr").Message, Does.Contain("r_1_hdr.exr").And.Contain("not this view's linear colour"), fault);
            }
        }

        [Test]
        public void AMissingExrIsNamed()
        {
            var copy = DatasetFaults.Copy(_dataset, _temp.Combine("fault-" + ++_copies));
            File.Delete(Path.Combine(copy, "test", "r_0_hdr.exr"));
            var hdr = Hdr(copy, out var report);
            Assert.That(hdr.Status, Is.EqualTo(DatasetCheckStatus.Failed));
            Assert.That(report.Problems.Select(p => p.Message), Has.Some.Contains("r_0_hdr.exr"));
        }
    }
}
