using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A dataset with every material pass, written through the capture's own <see cref="ViewPipeline"/> from analytic
    /// renders (<see cref="AnalyticDataset.Options.Materials"/>): the keys, files and record; the values where a pixel's
    /// samples all see one object, traced independently of the pipeline; the check passing on it (also over a solid
    /// background, through a lens and with motion blur); and planted faults it fails.
    /// </summary>
    [TestFixture]
    public class MaterialDatasetTests
    {
        TempFolder _temp;
        string _dataset;
        int _copies;

        /// <summary>Train view 0's object id per output pixel where all k×k sample rays hit the same object first (else −1).</summary>
        int[] _objectOf;
        int _width, _height;

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _dataset = AnalyticDataset.Write(_temp.Path, "materials", new AnalyticDataset.Options
            {
                Train = 3, Val = 1, Test = 1, PointCloud = 0, Materials = true,
                OutputRays = (view, scene, rays) =>
                {
                    if (view.Split != DatasetSplit.Train || view.Index != 0) return;
                    _width = 96;
                    _height = 72;
                    _objectOf = new int[_width * _height];
                    for (var y = 0; y < _height; y++)
                        for (var x = 0; x < _width; x++)
                        {
                            var ids = new HashSet<int>();
                            foreach (var (dx, dy) in new[] { (0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75) })
                            {
                                rays(x + dx, y + dy, out var o, out var d);
                                ids.Add(scene.Trace(o, d, 0, out _, out _, out _, out _, out var id) ? id : 0);
                            }
                            _objectOf[y * _width + x] = ids.Count == 1 ? ids.First() : -1;
                        }
                },
            });
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        static DatasetCheckResult Materials(string folder, out DatasetCheckReport report)
        {
            report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            TestContext.WriteLine(string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(8)));
            return report.Results.Single(r => r.Name == "materials");
        }

        [Test]
        public void EveryFrameNamesItsPassesAndTheConfigRecordsTheirEncodings()
        {
            foreach (var split in new[] { "train", "val", "test" })
                foreach (JObject frame in (JArray)JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "transforms_" + split + ".json")))["frames"])
                {
                    var image = (string)frame["file_path"];
                    foreach (var pass in new[] { "albedo", "metallic", "roughness", "specular" })
                    {
                        Assert.That((string)frame[pass + "_path"], Is.EqualTo(image + "_" + pass + ".png"), image);
                        Assert.That(File.Exists(Path.Combine(_dataset, image + "_" + pass + ".png")) && File.Exists(Path.Combine(_dataset, image + "_" + pass + ".exr")), Is.True, image + " " + pass);
                    }
                    Assert.That((string)frame["emission_path"], Is.EqualTo(image + "_emission.exr"));
                    Assert.That(File.Exists(Path.Combine(_dataset, image + "_emission.png")), Is.False, "emission has no PNG");
                    Assert.That((string)frame["material_coverage_path"], Is.EqualTo(image + "_material_coverage.png"));
                }
            var record = (JObject)JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "dataset_config.json")))["materials"];
            Assert.That(record["passes"].Select(t => (string)t), Is.EqualTo(new[] { "albedo", "metallic", "roughness", "specular", "emission" }));
            Assert.That((string)record["truth"], Is.EqualTo("exr"));
            Assert.That(record["encodings"].ToString(Newtonsoft.Json.Formatting.None),
                Is.EqualTo("{\"albedo_png\":\"srgb\",\"metallic_png\":\"linear\",\"roughness_png\":\"linear\",\"specular_png\":\"srgb\",\"emission\":\"linear-float-exr\"}"));
            Assert.That((string)record["roughness"], Is.EqualTo("perceptual (1 - smoothness)"));
            Assert.That((string)record["pipeline"], Is.EqualTo("analytic"));
            Assert.That(record["supported_shaders"].Select(t => (string)t), Is.EqualTo(new[] { "Analytic/Metallic", "Analytic/Specular" }));
            Assert.That(record["unsupported_shaders"], Is.Empty);
        }

        [Test]
        public void WhereAPixelSeesOneObjectThePassesHoldThatObjectsMaterial()
        {
            // The test look's objects (AnalyticScene.Layout): 1 Ball, 2 Glass, 3 Slab; the constants of AnalyticMaterials, written out here.
            var albedo = new Dictionary<int, float[]> { [1] = new[] { 0.8f, 0.25f, 0.1f }, [2] = new[] { 0.2f, 0.4f, 0.9f }, [3] = new[] { 0.3f, 0.7f, 0.3f } };
            var metallic = new Dictionary<int, float> { [1] = 0.6f, [2] = 0, [3] = 0 };
            var roughness = new Dictionary<int, float> { [1] = 0.4f, [2] = 0.1f, [3] = 0.85f };
            var emission = new Dictionary<int, float[]> { [1] = new[] { 0f, 0, 0 }, [2] = new[] { 0f, 0, 0 }, [3] = new[] { 1.5f, 0.75f, 0.25f } };
            var specular = new Dictionary<int, float[]> { [1] = new[] { 0f, 0, 0 }, [2] = new[] { 0.25f, 0.5f, 0.75f }, [3] = new[] { 0f, 0, 0 } };
            ExrImage Exr(string pass) => ExrReader.Read(Path.Combine(_dataset, "train", "r_0_" + pass + ".exr"));
            var files = new[] { "albedo", "metallic", "roughness", "specular", "emission" }.ToDictionary(p => p, Exr);
            var colour = PngReader.Read(Path.Combine(_dataset, "train", "r_0.png"));
            var coverage = PngReader.Read(Path.Combine(_dataset, "train", "r_0_material_coverage.png"));
            var seen = new HashSet<int>();
            for (var i = 0; i < _objectOf.Length; i++)
            {
                var id = _objectOf[i];
                foreach (var pass in files.Values) Assert.That(pass.Channel("A")[i], Is.EqualTo(colour.Samples[i * 4 + 3] / 255f), "alpha is the colour image's, pixel " + i);
                if (id == 0)
                {
                    Assert.That(coverage.Samples[i], Is.EqualTo(0), "nothing drawn: not supported");
                    foreach (var pass in files.Values) Assert.That(pass.Channel("R")[i], Is.EqualTo(0f));
                }
                if (id <= 0) continue;
                seen.Add(id);
                Assert.That(coverage.Samples[i], Is.EqualTo(255));
                float[] Rgb(string pass) => new[] { files[pass].Channel("R")[i], files[pass].Channel("G")[i], files[pass].Channel("B")[i] };
                Assert.That(Rgb("albedo"), Is.EqualTo(albedo[id]), "albedo, object " + id);
                Assert.That(Rgb("metallic"), Is.EqualTo(new[] { metallic[id], metallic[id], metallic[id] }), "metallic, object " + id);
                Assert.That(Rgb("roughness"), Is.EqualTo(new[] { roughness[id], roughness[id], roughness[id] }), "roughness, object " + id);
                Assert.That(Rgb("specular"), Is.EqualTo(specular[id]), "specular, object " + id);
                Assert.That(Rgb("emission"), Is.EqualTo(emission[id]), "emission, object " + id);
            }
            Assert.That(seen, Is.EquivalentTo(new[] { 1, 2, 3 }), "view 0 shows every object whole somewhere");
            // The PNGs: the ball's albedo sRGB-encoded (0.8 → 231, 0.25 → 137, 0.1 → 89), its roughness linear (0.4 → 102).
            var ball = Array.IndexOf(_objectOf, 1);
            var albedoPng = PngReader.Read(Path.Combine(_dataset, "train", "r_0_albedo.png"));
            var roughnessPng = PngReader.Read(Path.Combine(_dataset, "train", "r_0_roughness.png"));
            Assert.That(albedoPng.Samples.Skip(ball * 4).Take(3), Is.EqualTo(new byte[] { 231, 137, 89 }));
            Assert.That(roughnessPng.Samples.Skip(ball * 4).Take(4), Is.EqualTo(new byte[] { 102, 102, 102, colour.Samples[ball * 4 + 3] }));
        }

        [Test]
        public void TheCheckPassesOnEveryVariant()
        {
            var variants = new Dictionary<string, AnalyticDataset.Options>
            {
                ["solid background"] = new AnalyticDataset.Options { Train = 2, Val = 1, Test = 1, PointCloud = 0, Materials = true, Configure = s => s.Background = BackgroundSettings.Parse("#808080") },
                ["lens"] = new AnalyticDataset.Options
                {
                    Train = 2, Val = 1, Test = 1, PointCloud = 0, Materials = true, Width = 128, Height = 128, Lens = new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.02 },
                    ThroughWideRender = true, DataAtOutputSize = false, VerticalFovDegrees = 55,
                },
                ["blur"] = new AnalyticDataset.Options
                {
                    Train = 2, Val = 1, Test = 1, PointCloud = 0, Materials = true,
                    MotionBlur = new MotionBlurSettings { Enabled = true, Camera = ShutterCameraMotion.Shake, ShakeDistance = 0.1, ShakeDegrees = 1, SubFrames = 2 },
                },
            };
            Assert.That(Materials(_dataset, out var plain).Status, Is.EqualTo(DatasetCheckStatus.Passed));
            Assert.That(plain.Problems, Is.Empty);
            foreach (var variant in variants)
            {
                var folder = AnalyticDataset.Write(_temp.Path, "variant-" + ++_copies, variant.Value);
                Assert.That(Materials(folder, out var report).Status, Is.EqualTo(DatasetCheckStatus.Passed), variant.Key);
                Assert.That(report.Problems.Where(p => p.Check == "materials"), Is.Empty, variant.Key);
            }
        }

        [Test]
        public void UnderASkyTheAlphaIsTheMasksCoverage()
        {
            // A sky leaves the colour image opaque everywhere: the passes take the mask's coverage (glass 255, not its 50 % alpha).
            var folder = AnalyticDataset.Write(_temp.Path, "sky", new AnalyticDataset.Options { Train = 2, Val = 1, Test = 1, PointCloud = 0, Materials = true, Configure = s => s.Background = BackgroundSettings.Parse("sky") });
            var mask = PngReader.Read(Path.Combine(folder, "train", "r_0_mask_0000.png")).Samples;
            var albedo = PngReader.Read(Path.Combine(folder, "train", "r_0_albedo.png")).Samples;
            Assert.That(Enumerable.Range(0, mask.Length).Select(i => albedo[i * 4 + 3]), Is.EqualTo(mask));
            Assert.That(mask.Count(m => m > 0 && m < 255), Is.GreaterThan(0), "edges: coverage between 0 and 255");
            Assert.That(Materials(folder, out var report).Status, Is.EqualTo(DatasetCheckStatus.Passed));
        }

        [Test]
        public void TheCheckSkipsADatasetWithoutMaterials()
        {
            var folder = AnalyticDataset.Write(_temp.Path, "plain", new AnalyticDataset.Options { Train = 2, Val = 1, Test = 1, PointCloud = 0 });
            var result = Materials(folder, out _);
            Assert.That(result.Status, Is.EqualTo(DatasetCheckStatus.Skipped));
            Assert.That(result.Reason, Does.Contain("materials are off"));
        }

        /// <summary>Rewrites train view 1's files of <paramref name="suffix"/> (e.g. "_roughness.png") and returns the check's problems.</summary>
        List<string> Planted(string suffix, Action<PngImage, byte[], string> edit, string copy = null)
        {
            copy = copy ?? DatasetFaults.Copy(_dataset, _temp.Combine("fault-" + ++_copies));
            DatasetFaults.EditImages(copy, f => f.EndsWith(Path.Combine("train", "r_1" + suffix), StringComparison.Ordinal), edit);
            Assert.That(Materials(copy, out var report).Status, Is.EqualTo(DatasetCheckStatus.Failed), suffix);
            return report.Problems.Where(p => p.Check == "materials").Select(p => p.ToString()).ToList();
        }

        /// <summary>The EXR beside a PNG, values top row first (R G B A planes).</summary>
        static ExrImage ExrOf(string png) => ExrReader.Read(png.Substring(0, png.Length - 4) + ".exr");

        [Test]
        public void AnSrgbEncodedLinearMapFails()
        {
            var problems = Planted("_roughness.png", (png, s, file) =>
            {
                var r = ExrOf(file).Channel("R");
                for (var i = 0; i < r.Length; i++)
                    for (var c = 0; c < 3; c++) s[i * 4 + c] = Srgb.EncodeByteExact(r[i]);
            });
            Assert.That(problems.Single(), Does.Contain("roughness: ").And.Contain("differ from the EXR linearly encoded").And.Contain("matches the EXR sRGB-encoded instead"));
        }

        [Test]
        public void ALinearEncodedColourMapFails()
        {
            var problems = Planted("_albedo.png", (png, s, file) =>
            {
                var exr = ExrOf(file);
                for (var i = 0; i < png.Width * png.Height; i++)
                    for (var c = 0; c < 3; c++) s[i * 4 + c] = MaterialEncoding.LinearByte(exr.Channel("RGB".Substring(c, 1))[i]);
            });
            Assert.That(problems.Single(), Does.Contain("albedo: ").And.Contain("differ from the EXR sRGB-encoded").And.Contain("matches the EXR linearly encoded (no curve) instead"));
        }

        [Test]
        public void SwappedChannelsFail()
        {
            // Metallic with roughness packed into G (a channel-packed map written as the metallic pass): not grey.
            var copy = DatasetFaults.Copy(_dataset, _temp.Combine("fault-" + ++_copies));
            var roughness = PngReader.Read(Path.Combine(copy, "train", "r_1_roughness.png")).Samples;
            var packed = Planted("_metallic.png", (png, s, _) =>
            {
                for (var i = 0; i < png.Width * png.Height; i++) s[i * 4 + 1] = roughness[i * 4];
            }, copy);
            Assert.That(packed, Has.Some.Contains("metallic: ").And.Some.Contains("are not grey (R = G = B)"));
            // Albedo with R and B swapped: it matches neither encoding.
            var swapped = Planted("_albedo.png", (png, s, _) =>
            {
                for (var i = 0; i < png.Width * png.Height; i++) (s[i * 4], s[i * 4 + 2]) = (s[i * 4 + 2], s[i * 4]);
            });
            Assert.That(swapped.Single(), Does.Contain("albedo: ").And.Contain("matches neither encoding"));
        }

        [Test]
        public void CoverageAndAlphaThatAreNotTheColourImagesFail()
        {
            var coverage = Planted("_material_coverage.png", (png, s, _) =>
            {
                for (var i = 0; i < s.Length; i++) s[i] = 255;
            });
            Assert.That(coverage.Single(), Does.Contain("material_coverage_path marks").And.Contain("supported where the mask is 0"));
            var opaque = Planted("_albedo.png", (png, s, _) =>
            {
                for (var i = 0; i < png.Width * png.Height; i++) s[i * 4 + 3] = 255;
            });
            Assert.That(opaque, Has.Some.Contains("EXR's A are not the PNG's alpha"));
            Assert.That(opaque, Has.Some.Contains("another alpha than the colour image"));
            Assert.That(opaque, Has.Some.Contains("whole in the pass and empty in the mask"));
        }

        [Test]
        public void AnOutOfRangeMetallicAndColourOutsideTheCoverageFail()
        {
            var copy = DatasetFaults.Copy(_dataset, _temp.Combine("fault-" + ++_copies));
            Rewrite(Path.Combine(copy, "train", "r_1_metallic.exr"), (rgba, alpha) => { for (var c = 0; c < 3; c++) rgba[c] *= 2; });
            Rewrite(Path.Combine(copy, "train", "r_1_specular.exr"), (rgba, alpha) => { if (alpha == 0) rgba[0] = 0.5f; });
            Assert.That(Materials(copy, out var report).Status, Is.EqualTo(DatasetCheckStatus.Failed));
            var problems = report.Problems.Where(p => p.Check == "materials").Select(p => p.ToString()).ToList();
            Assert.That(problems, Has.Some.Contains("metallic: ").And.Some.Contains("lie outside [0, 1] (from 0 to 1.2)"));
            Assert.That(problems, Has.Some.Contains("specular: ").And.Some.Contains("with alpha 0 have RGB other than 0"));
        }

        [Test]
        public void TheRecordedEncodingIsTheOneCompared()
        {
            var copy = DatasetFaults.Copy(_dataset, _temp.Combine("fault-" + ++_copies));
            var path = Path.Combine(copy, "dataset_config.json");
            var config = JObject.Parse(File.ReadAllText(path));
            config["materials"]["encodings"]["metallic_png"] = "srgb";
            File.WriteAllText(path, config.ToString());
            Assert.That(Materials(copy, out var report).Status, Is.EqualTo(DatasetCheckStatus.Failed));
            Assert.That(report.Problems.Where(p => p.Check == "materials").Select(p => p.Message), Has.All.Contains("metallic: ").And.All.Contains("matches the EXR linearly encoded (no curve) instead"));
        }

        [Test]
        public void AMissingExrIsNamed()
        {
            var copy = DatasetFaults.Copy(_dataset, _temp.Combine("fault-" + ++_copies));
            File.Delete(Path.Combine(copy, "test", "r_0_roughness.exr"));
            Assert.That(Materials(copy, out var report).Status, Is.EqualTo(DatasetCheckStatus.Failed));
            Assert.That(report.Problems.Single(p => p.Check == "materials").Message, Does.Contain("roughness_path").And.Contain("r_0_roughness.exr").And.Contain("is not a file inside the dataset"));
        }

        /// <summary>Rewrites an RGBA EXR through <paramref name="edit"/> per pixel (its RGBA and its alpha as a byte).</summary>
        static void Rewrite(string path, Action<float[], int> edit)
        {
            var exr = ExrReader.Read(path);
            int w = exr.Width, h = exr.Height;
            var pixels = new float[w * h * 4];
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    var at = y * w + x;
                    var rgba = new[] { exr.Channel("R")[at], exr.Channel("G")[at], exr.Channel("B")[at], exr.Channel("A")[at] };
                    edit(rgba, (int)Math.Round(rgba[3] * 255));
                    Array.Copy(rgba, 0, pixels, ((h - 1 - y) * w + x) * 4, 4); // back to texture order
                }
            File.WriteAllBytes(path, ExrWriter.Encode(pixels, w, h, 4));
        }
    }
}
