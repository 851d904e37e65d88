using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;
using static NerfDatasetCreator.Tests.InverseRenderingLoaders;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <c>convert --to tensoir | gs-ir | r3dg</c> of a dataset with known materials, relit views and an environment map
    /// (<see cref="InverseRenderingFixture"/>), read back by re-implementations of each loader's reading code
    /// (<see cref="InverseRenderingLoaders"/>) into the arrays the fixture's closed-form values give.
    /// </summary>
    [TestFixture]
    public class InverseRenderingExportTests
    {
        TempFolder _temp;
        string _dataset, _tensoir, _gsir, _r3dg;
        ConversionResult _tensoirResult, _gsirResult, _r3dgResult;

        [OneTimeSetUp]
        public void Write()
        {
            _temp = new TempFolder();
            _dataset = InverseRenderingFixture.Write(_temp.Path, "ir");
            _tensoir = _temp.Combine("tensoir");
            _gsir = _temp.Combine("gs-ir");
            _r3dg = _temp.Combine("Synthetic4Relight", "ir");
            _tensoirResult = DatasetConverter.Convert(_dataset, ExportTarget.Tensoir, _tensoir);
            _gsirResult = DatasetConverter.Convert(_dataset, ExportTarget.GsIr, _gsir);
            _r3dgResult = DatasetConverter.Convert(_dataset, ExportTarget.R3dg, _r3dg);
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        PngImage DatasetImage(string split, string stem) => PngReader.Read(Path.Combine(_dataset, split, stem + ".png"));

        [Test]
        public void TensoIRsTestLoaderReadsPosesRelitViewsDiffuseAlbedoAndNormals()
        {
            var frames = InverseRenderingFixture.Frames(_dataset, "test");
            var angle = (double)JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "transforms_test.json")))["camera_angle_x"];
            var list = TensoIRSplitList(_tensoir, "test");
            Assert.That(list.Select(Path.GetFileName), Is.EqualTo(new[] { "test_000", "test_001" }), "one folder per test view, nothing else starts with 'test'");
            for (var k = 0; k < frames.Count; k++)
            {
                var item = TensoIRGetItem(list[k], "sunset", new[] { "000", "090" });
                Assert.That(item.Width, Is.EqualTo(32));
                Assert.That(item.Height, Is.EqualTo(32));
                Assert.That(item.Focal, Is.EqualTo(0.5 * 32 / Math.Tan(0.5 * angle)));
                for (var r = 0; r < 4; r++)
                    for (var c = 0; c < 4; c++) Assert.That(item.CamTrans[r, c], Is.EqualTo(frames[k].pose[r][c]), "cam_transform_mat is transform_matrix, row-major");
                var image = DatasetImage("test", frames[k].stem);
                var normal = PngReader.Read(Path.Combine(_dataset, "test", frames[k].stem + "_normal_0000.png"));
                int covered = 0;
                for (var i = 0; i < 32 * 32; i++)
                {
                    int x = i % 32, y = i / 32;
                    var a = image.Samples[4 * i + 3] / 255.0;
                    Assert.That(item.Mask[i], Is.EqualTo(a > 0));
                    if (a > 0) covered++;
                    var diffuse = InverseRenderingFixture.Base(x, y, 32, 32).Select(b => Math.Round(b * (1 - InverseRenderingFixture.Metallic) * 255, MidpointRounding.AwayFromZero) / 255).ToArray();
                    var n = new double[3];
                    for (var c = 0; c < 3; c++)
                    {
                        var code = image.Samples[4 * i + c];
                        for (var rot = 0; rot < 2; rot++)
                        {
                            var relit = a > 0 ? InverseRenderingFixture.RelitCode(code, rot) / 255.0 : 0;
                            Assert.That(item.Rgbs[rot][3 * i + c], Is.EqualTo(relit * a + 1 - a).Within(1e-6), "rgba_sunset_" + (rot == 0 ? "000" : "090"));
                        }
                        Assert.That(item.Albedo[3 * i + c], Is.EqualTo((a > 0 ? diffuse[c] : 0) * a + 1 - a).Within(1e-6), "albedo.png = diffuse, linear 8-bit, pixel " + i);
                        n[c] = (normal.Samples[normal.Channels * i + c] / 255.0 - 0.5) * 2 * a + (c == 2 ? 1 - a : 0);
                    }
                    var length = Math.Sqrt(n.Sum(v => v * v));
                    for (var c = 0; c < 3; c++) Assert.That(item.Normals[3 * i + c], Is.EqualTo(n[c] / length).Within(1e-9));
                }
                Assert.That(covered, Is.GreaterThan(50));
            }
        }

        [Test]
        public void NerfactorGlobsEverySplitWithThreeDigitsAndReadsRgbaAsTheDatasetsImage()
        {
            foreach (var (split, count) in new[] { ("train", 2), ("val", 1), ("test", 2) })
            {
                var paths = NerfactorGlob(_tensoir, split);
                Assert.That(paths.Count, Is.EqualTo(count), split);
                var frames = InverseRenderingFixture.Frames(_dataset, split);
                for (var k = 0; k < count; k++)
                {
                    var meta = JObject.Parse(File.ReadAllText(paths[k]));
                    var imh = 16; // a config's imh: nerf.py:145 scales imw by it
                    Assert.That((int)(imh / (double)(int)meta["imh"] * (int)meta["imw"]), Is.EqualTo(16));
                    var rgba = PngReader.Read(Path.Combine(Path.GetDirectoryName(paths[k]), "rgba.png"));
                    Assert.That(rgba.Channels, Is.EqualTo(4), "nerf.py:159 asserts RGBA");
                    Assert.That(rgba.Samples, Is.EqualTo(DatasetImage(split, frames[k].stem).Samples), "rgba.png is the scene's own lighting");
                }
            }
        }

        [Test]
        public void LightFilesAreTheEnvironmentUnrotatedAndRotatedAndTheOlatPointLocation()
        {
            var sunset = ReadHdr(Path.Combine(_tensoir, "env_maps", "sunset.hdr"), out var w, out var h);
            var rotated = ReadHdr(Path.Combine(_tensoir, "env_maps", "sunset_090.hdr"), out _, out _);
            Assert.That((w, h), Is.EqualTo((16, 8)));
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    var expected = InverseRenderingFixture.Map(x, y);
                    // 90° counter-clockwise about +Z: φ → φ + 90°, u → u − 1/4, so column x shows the source's x + 4.
                    var turned = InverseRenderingFixture.Map((x + 4) % 16, y);
                    for (var c = 0; c < 3; c++)
                    {
                        // RGBE keeps 8 bits of mantissa of the largest component: a relative step of 1/128 at worst.
                        var scale = expected.Max() / 128 + 1e-30;
                        Assert.That(sunset[(y * w + x) * 3 + c], Is.EqualTo(expected[c]).Within(scale));
                        Assert.That(rotated[(y * w + x) * 3 + c], Is.EqualTo(turned[c]).Within(turned.Max() / 128 + 1e-30));
                    }
                }
            var olat = JObject.Parse(File.ReadAllText(Path.Combine(_tensoir, "env_maps", "olat-00.json")));
            Assert.That(olat["point_location"].ToObject<double[]>(), Is.EqualTo(new[] { 0.0, -3.0, 3.0 }), "NeRFactor render.py:203–209 reads point_location");
            Assert.That(File.Exists(Path.Combine(_tensoir, "test_000", "rgba_sunset.png")), Is.True, "rotation 0 under the plain name too");
            Assert.That(File.ReadAllBytes(Path.Combine(_tensoir, "test_000", "rgba_sunset.png")), Is.EqualTo(File.ReadAllBytes(Path.Combine(_tensoir, "test_000", "rgba_sunset_000.png"))));
        }

        [Test]
        public void TheRecordNamesTheAlbedoItsEncodingAndTheConfigLines()
        {
            var record = JObject.Parse(File.ReadAllText(Path.Combine(_tensoir, TensoIR.RecordFileName)));
            Assert.That((string)record["albedo"]["content"], Is.EqualTo("diffuse colour = base colour * (1 - metallic)"));
            Assert.That((string)record["albedo"]["encoding"], Does.StartWith("linear, clipped to 8 bits, no sRGB curve"));
            Assert.That(record["config"]["tensoir_rotated_sunset"].Select(t => (string)t), Has.Member("light_rotation = [000, 090]"));
            Assert.That(record["config"]["tensoir_rotated_sunset"].Select(t => (string)t), Has.Member("light_name = sunset"));
            Assert.That(record["config"]["tensoir_general_multi_lights"].Select(t => (string)t), Has.Member("light_name_list = [\"olat-00\", \"sunset\"]"));
            Assert.That((string)record["config"]["gs_ir_relight_eval_py_28"], Is.EqualTo("num_test = 2"));
            Assert.That((string)record["points"], Is.EqualTo("points3d.ply"));
            Assert.That(File.ReadAllBytes(Path.Combine(_tensoir, "points3d.ply")), Is.EqualTo(File.ReadAllBytes(Path.Combine(_dataset, "points3d.ply"))));
            var r3dg = JObject.Parse(File.ReadAllText(Path.Combine(_r3dg, TensoIR.RecordFileName)));
            Assert.That((string)r3dg["albedo"]["content"], Is.EqualTo("base colour (not diffuse)"));
            Assert.That((string)r3dg["albedo"]["encoding"], Does.StartWith("sRGB"));
            Assert.That(_tensoirResult.Warnings.Select(w => w.Field), Has.Member("resolution"), "32×32 is not TensoIR's 800×800");
        }

        [Test]
        public void GsIrsBlenderReaderAlbedoRuleNormalsAndRelightEvaluationFindTheirFiles()
        {
            foreach (var split in new[] { "train", "test" })
            {
                // scene/dataset_readers.py:229–249: file_path + ".png", c2w from transform_matrix.
                var contents = JObject.Parse(File.ReadAllText(Path.Combine(_gsir, "transforms_" + split + ".json")));
                var frames = InverseRenderingFixture.Frames(_dataset, split);
                var listed = (JArray)contents["frames"];
                Assert.That(listed.Count, Is.EqualTo(frames.Count));
                for (var idx = 0; idx < listed.Count; idx++)
                {
                    var filePath = (string)listed[idx]["file_path"];
                    Assert.That(File.Exists(Path.Combine(_gsir, filePath + ".png")), Is.True, filePath);
                    Assert.That(listed[idx]["transform_matrix"].ToObject<double[][]>(), Is.EqualTo(frames[idx].pose));
                    if (split != "test") continue;
                    // render.py:322–324: the albedo truth and its mask.
                    var albedo = PngReader.Read(Path.Combine(_gsir, filePath.Replace("rgba", "albedo") + ".png"));
                    var image = DatasetImage("test", frames[idx].stem);
                    for (var i = 0; i < 32 * 32; i++)
                    {
                        Assert.That(albedo.Samples[4 * i + 3] > 0, Is.EqualTo(image.Samples[4 * i + 3] > 0));
                        if (albedo.Samples[4 * i + 3] == 0) continue;
                        var b = InverseRenderingFixture.Base(i % 32, i / 32, 32, 32);
                        for (var c = 0; c < 3; c++) Assert.That(albedo.Samples[4 * i + c], Is.EqualTo((byte)Math.Round(b[c] * 0.75 * 255, MidpointRounding.AwayFromZero)));
                    }
                    // relight_eval.py:36: test frame idx ↔ test_<idx:03>; the sunset and olat-00 lights.
                    foreach (var light in new[] { "sunset", "olat-00" })
                        Assert.That(File.Exists(Path.Combine(_gsir, "test_" + idx.ToString("000"), "rgba_" + light + ".png")), Is.True, light);
                }
            }
            // normal_eval.py:29–38: glob test_*, sorted, id from the name.
            var testDirs = Directory.GetDirectories(_gsir, "test_*").OrderBy(d => d, StringComparer.Ordinal).ToList();
            Assert.That(testDirs.Select(d => int.Parse(d.Split('_').Last())), Is.EqualTo(new[] { 0, 1 }));
            Assert.That(testDirs.All(d => File.Exists(Path.Combine(d, "normal.png"))), Is.True);
            Assert.That(Directory.Exists(Path.Combine(_gsir, "val_000")), Is.False, "GS-IR reads train and test only");
            Assert.That(_gsirResult.Warnings.Select(w => w.Field), Has.Member("relight_eval.py"));
            Assert.That(_gsirResult.Warnings.Select(w => w.Field), Has.Member("val"));
        }

        [Test]
        public void R3dgsSynthetic4RelightReaderReadsLinearHdrMasksAlbedoRoughnessAndRelitViews()
        {
            // dataset_readers.py:526–565 with extension "_rgb.exr" (train) and "_rgba.png" (test), :570–573.
            var train = JObject.Parse(File.ReadAllText(Path.Combine(_r3dg, "transforms_train.json")));
            var frames = InverseRenderingFixture.Frames(_dataset, "train");
            foreach (var (frame, k) in ((JArray)train["frames"]).Select((f, k) => (f, k)))
            {
                var imagePath = Path.Combine(_r3dg, (string)frame["file_path"] + "_rgb.exr");
                var maskPath = imagePath.Replace("_rgb.exr", "_mask.png");                                     // :536
                var exr = ExrReader.Read(imagePath);                                                            // utils.py:42–45 (pyexr)
                var mask = PngReader.Read(maskPath);                                                            // utils.py:52–57
                var hdr = ExrReader.Read(Path.Combine(_dataset, "train", frames[k].stem + "_hdr.exr"));
                var image = DatasetImage("train", frames[k].stem);
                for (var i = 0; i < 32 * 32; i++)
                {
                    var inside = mask.Samples[i] > 0.5 ? 1.0 : 0.0;
                    Assert.That(inside, Is.EqualTo(image.Samples[4 * i + 3] > 0 ? 1.0 : 0.0));
                    foreach (var c in new[] { "R", "G", "B" })
                        Assert.That(exr.Channel(c)[i], Is.EqualTo(image.Samples[4 * i + 3] > 0 ? hdr.Channel(c)[i] : 0f), "linear HDR colour, black outside");
                }
            }
            var test = JObject.Parse(File.ReadAllText(Path.Combine(_r3dg, "transforms_test.json")));
            var testFrames = InverseRenderingFixture.Frames(_dataset, "test");
            foreach (var (frame, k) in ((JArray)test["frames"]).Select((f, k) => (f, k)))
            {
                var name = ((string)frame["file_path"]).Split('/').Last();
                var image = DatasetImage("test", testFrames[k].stem);
                var rgba = PngReader.Read(Path.Combine(_r3dg, (string)frame["file_path"] + "_rgba.png"));
                var albedo = PngReader.Read(Path.Combine(_r3dg, "test/" + name + "_albedo.png"));               // eval_relighting_syn4.py:174
                var rough = PngReader.Read(Path.Combine(_r3dg, "test/" + name + "_rough.png"));                 // :180
                foreach (var env in new[] { "sunset_000", "sunset_090" })
                    Assert.That(File.Exists(Path.Combine(_r3dg, "test_rli/" + env + "_" + name + ".png")), Is.True, env);   // :129
                for (var i = 0; i < 32 * 32; i++)
                {
                    var a = image.Samples[4 * i + 3];
                    // :536 leaves the path unchanged, so the test mask is the image itself read as grey: non-black RGB.
                    var luma = Luma(rgba.Samples[4 * i], rgba.Samples[4 * i + 1], rgba.Samples[4 * i + 2]);
                    if (a == 0) Assert.That(luma, Is.EqualTo(0), "transparent pixels are black, outside R3DG's mask");
                    if (a == 0) continue;
                    var b = InverseRenderingFixture.Base(i % 32, i / 32, 32, 32);
                    for (var c = 0; c < 3; c++)
                    {
                        Assert.That(albedo.Samples[4 * i + c], Is.EqualTo(Srgb.EncodeByteExact(b[c])), "base colour, sRGB");
                        Assert.That(rough.Samples[4 * i + c], Is.EqualTo(153), "roughness 0.6, linear");
                    }
                }
            }
            // env_map/<key>.exr: the rotated environment in float.
            var turned = ExrReader.Read(Path.Combine(_r3dg, "env_map", "sunset_090.exr"));
            for (var y = 0; y < 8; y++)
                for (var x = 0; x < 16; x++)
                    Assert.That(turned.Channel("B")[y * 16 + x], Is.EqualTo(InverseRenderingFixture.Map((x + 4) % 16, y)[2]));
            Assert.That(Directory.Exists(Path.Combine(_r3dg, "val")), Is.False);
            Assert.That(_r3dgResult.Warnings.Select(w => w.Field), Has.Member("eval_relighting_syn4.py"));
            Assert.That(_r3dgResult.Warnings.Select(w => w.Field), Has.No.Member("output"), "the path holds Synthetic4Relight");
        }

        [Test]
        public void R3dgRefusesNonSquareImagesAndMissingHdrBeforeWritingAndWarnsWithoutItsPathWord()
        {
            var wide = InverseRenderingFixture.Write(_temp.Path, "wide", 40, 32, relighting: false);
            var output = _temp.Combine("Synthetic4Relight", "wide");
            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(wide, ExportTarget.R3dg, output));
            Assert.That(e.Problems.Select(p => p.Field), Has.Member("resolution"));
            Assert.That(e.Problems.First(p => p.Field == "resolution").Reason, Does.Contain("dataset_readers.py:557"));
            Assert.That(Directory.Exists(output), Is.False);

            var plain = InverseRenderingFixture.Write(_temp.Path, "nohdr", relighting: false, hdr: false);
            e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(plain, ExportTarget.R3dg, _temp.Combine("Synthetic4Relight", "nohdr")));
            Assert.That(e.Problems.Select(p => p.Field), Has.Member(HdrKeys.HdrPath));

            var elsewhere = DatasetConverter.Convert(_dataset, ExportTarget.R3dg, _temp.Combine("r3dg-out"));
            Assert.That(elsewhere.Warnings.Select(w => w.Field), Has.Member("output"));
        }

        [Test]
        public void ADatasetWithoutMaterialsOrRelightingStillExportsAndSaysWhatIsMissing()
        {
            var plain = InverseRenderingFixture.Write(_temp.Path, "plain", materials: false, relighting: false);
            var result = DatasetConverter.Convert(plain, ExportTarget.Tensoir, _temp.Combine("plain-tensoir"));
            Assert.That(result.Warnings.Select(w => w.Field), Has.Member(MaterialKeys.AlbedoPath));
            Assert.That(result.Warnings.Select(w => w.Field), Has.Member(RelightingKeys.RelitPaths));
            Assert.That(File.Exists(_temp.Combine("plain-tensoir", "test_000", "albedo.png")), Is.False);
            Assert.That(File.Exists(_temp.Combine("plain-tensoir", "test_000", "normal.png")), Is.True);
            Assert.That(File.Exists(_temp.Combine("plain-tensoir", "test_000", "rgba.png")), Is.True);
        }

        [Test]
        public void ALensIsRefusedForEveryInverseRenderingTarget()
        {
            foreach (var target in new[] { ExportTarget.Tensoir, ExportTarget.GsIr, ExportTarget.R3dg })
            {
                var problem = LensExports.Refusal(new LensDistortion(LensModel.OpenCv, -0.1, 0.01, 0, 0, 0, 0), target);
                Assert.That(problem, Is.Not.Null, target.ToString());
                Assert.That(problem.Reason, Does.Contain("pinhole focal"));
            }
        }

        [Test]
        public void MoreThanAThousandViewsInASplitAreRefusedNamingNerfactorsGlob()
        {
            List<InverseRenderingView> Views(int test) => Enumerable.Range(0, test).Select(i => new InverseRenderingView { Split = "test", Index = i })
                .Append(new InverseRenderingView { Split = "train" }).ToList();
            Assert.DoesNotThrow(() => TensoIRExport.Refusals(Views(1000), "tensoir"));
            var e = Assert.Throws<InvalidParameterException>(() => TensoIRExport.Refusals(Views(1001), "tensoir"));
            Assert.That(e.Problems[0].Field, Is.EqualTo("test"));
            Assert.That(e.Problems[0].Reason, Does.Contain("'%s_???'"));
        }
    }
}
