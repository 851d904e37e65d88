using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A dataset with "relighting" written through the capture's own plan, <see cref="ViewPipeline"/> and
    /// <see cref="DatasetRun"/> from analytic renders (<see cref="AnalyticDataset"/>, <see cref="AnalyticLighting"/>): the
    /// files and keys read back through <see cref="DatasetFolder"/>, the record, lights/, the check passing on it, and
    /// planted faults it fails.
    /// </summary>
    [TestFixture]
    public class RelightDatasetTests
    {
        TempFolder _temp;
        string _dataset;
        int _copies;
        static readonly string[] Keys = { "sky_000", "sky_090", "olat-00" };

        static RelightingSettings Relighting() => new RelightingSettings
        {
            On = true,
            Conditions =
            {
                new LightingCondition { Name = "sky", Kind = LightingKind.Environment, File = "Assets/HDRI/sky.exr", Rotations = new double[] { 0, 90 } },
                new LightingCondition { Name = "olat-00", Kind = LightingKind.Point, Position = new double[] { 2, -2, 3 }, Intensity = 25 },
            },
        };

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _dataset = AnalyticDataset.Write(_temp.Path, "relight", new AnalyticDataset.Options
            {
                Train = 3, Val = 1, Test = 1, PointCloud = 0,
                Configure = s =>
                {
                    s.Relighting = Relighting();
                    s.Hdr.On = true;
                    s.Hdr.Val = s.Hdr.Test = false;
                },
            });
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        static DatasetCheckResult Relight(string folder, out DatasetCheckReport report)
        {
            report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            TestContext.WriteLine(string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(8)));
            return report.Results.Single(r => r.Name == "relight");
        }

        [Test]
        public void EveryViewNamesAnImagePerKeyAndTheyReadBackThroughTheFrame()
        {
            foreach (var split in new[] { "train", "val", "test" })
            {
                var file = DatasetFolder.ReadSplit(_dataset, split, DatasetReadMode.Strict);
                Assert.That(file.Frames, Is.Not.Empty);
                foreach (var frame in file.Frames)
                {
                    Assert.That(frame.Relit.Paths.Select(p => p.Key), Is.EqualTo(Keys));
                    Assert.That(frame.Relit.Problem, Is.Null);
                    foreach (var key in Keys)
                    {
                        Assert.That(frame.Relit.PathOf(key), Is.EqualTo(frame.FilePath + "_light_" + key + ".png"));
                        Assert.That(frame.RelitFile(key).Exists, Is.True, key);
                        Assert.That(File.Exists(Path.Combine(_dataset, RelightingKeys.HdrPathOf(frame.RelitFile(key).Relative))), Is.EqualTo(split == "train"), key + " HDR");
                    }
                }
            }
            var config = DatasetConfig.Read(_dataset).Config;
            Assert.That(config.Relighting.Keys, Is.EqualTo(Keys));
            Assert.That(config.Relighting.LightsFile, Is.EqualTo("lights/lights.json"));
        }

        [Test]
        public void TheRelitImagesHaveTheViewsAlphaAndTheirConditionsLight()
        {
            var own = PngReader.Read(Path.Combine(_dataset, "train", "r_0.png"));
            var images = Keys.Select(k => PngReader.Read(Path.Combine(_dataset, "train", "r_0_light_" + k + ".png"))).ToList();
            for (var i = 0; i < own.Width * own.Height; i++)
                foreach (var image in images) Assert.That(image.Samples[i * 4 + 3], Is.EqualTo(own.Samples[i * 4 + 3]), "pixel " + i);
            int Differing(PngImage a, PngImage b) => Enumerable.Range(0, a.Samples.Length).Count(i => i % 4 != 3 && a.Samples[i] != b.Samples[i]);
            Assert.That(Differing(images[0], images[1]), Is.GreaterThan(own.Width * own.Height / 20), "a quarter turn of the sky relights the scene");
            Assert.That(Differing(images[0], own), Is.GreaterThan(own.Width * own.Height / 20), "the sky is not the scene's own light");
        }

        [Test]
        public void AConditionLightsTheDiffuseColourBaseTimesOneMinusMetallic()
        {
            // One white sphere (the ball, instance 1: metallic 0.6) filling the view; a shading that returns the albedo it is given.
            var scene = AnalyticScene.OneSphere(Vector3d.Zero, 10);
            AnalyticDataset.RayOf rays = (double i, double j, out Vector3d origin, out Vector3d direction) =>
            {
                origin = new Vector3d(0, 0, 20);
                direction = new Vector3d((i - 2) * 0.01, (j - 2) * 0.01, -1);
            };
            var frame = AnalyticDataset.RenderColour(scene, rays, 4, 4, 1, (point, normal, albedo, result) => { for (var c = 0; c < 3; c++) result[c] = albedo[c]; });
            var centre = 4 * (2 * 4 + 2);
            for (var c = 0; c < 3; c++)
                Assert.That(HalfFloat.ToFloat(frame.ColorOverBlack[centre + c]), Is.EqualTo(1 - AnalyticMaterials.Metallic(1)).Within(1e-3), "channel " + c);
        }

        [Test]
        public void TheLightsFileDescribesEachConditionAndItsConversions()
        {
            var lights = JObject.Parse(File.ReadAllText(Path.Combine(_dataset, "lights", "lights.json")));
            Assert.That((string)lights["format"], Is.EqualTo("nerf-dataset-lights"));
            Assert.That((string)lights["equirect"]["u"], Is.EqualTo("0.5 - atan2(y, x) / (2 pi)"));
            var sky = lights["conditions"][0];
            Assert.That((string)sky["file"], Is.EqualTo("lights/sky.exr"));
            Assert.That((string)sky["source"], Is.EqualTo("Assets/HDRI/sky.exr"));
            Assert.That(sky["keys"].Values<string>(), Is.EqualTo(new[] { "sky_000", "sky_090" }));
            Assert.That(sky["conversions"]["tensoir"]["config_lines"].Values<string>(), Is.EqualTo(new[] { "light_name = sky", "light_rotation = [000, 090]" }));
            Assert.That(sky["conversions"]["nerfactor"]["hdr_files"].Values<string>(), Is.EqualTo(new[] { "sky_000.hdr", "sky_090.hdr" }));
            Assert.That(sky["conversions"]["r3dg"]["envmap_paths"].Values<string>(), Is.EqualTo(new[] { "env_map/sky_000.exr", "env_map/sky_090.exr" }));
            Assert.That((int)sky["conversions"]["stanford_orb"]["roll_columns"], Is.EqualTo(32));
            var olat = lights["conditions"][1];
            Assert.That(olat["conversions"]["nerfactor"]["olat_json"]["point_location"].Values<double>(), Is.EqualTo(new[] { 2.0, -2, 3 }));
            Assert.That(olat["conversions"]["tensoir"].Type, Is.EqualTo(JTokenType.Null));
            // The environment as written: AnalyticSky's map, float32 RGB, 2:1, top row first.
            var exr = ExrReader.Read(Path.Combine(_dataset, "lights", "sky.exr"));
            var expected = AnalyticSky.Map();
            Assert.That((exr.Width, exr.Height), Is.EqualTo((128, 64)));
            Assert.That(exr.Channels.Keys.OrderBy(k => k), Is.EqualTo(new[] { "B", "G", "R" }));
            var red = exr.Channel("R");
            for (var i = 0; i < red.Length; i++) Assert.That(red[i], Is.EqualTo(expected.Rgb[i * 3]), "pixel " + i);
        }

        [Test]
        public void TheCheckPasses()
        {
            var relight = Relight(_dataset, out var report);
            Assert.That(relight.Status, Is.EqualTo(DatasetCheckStatus.Passed), relight.Reason);
            Assert.That(relight.Figure, Does.StartWith("15 relit images of 5 views"));
            Assert.That(report.Problems, Is.Empty);
        }

        [Test]
        public void ADatasetWithoutRelightingSkipsTheCheck()
        {
            var plain = AnalyticDataset.Write(_temp.Path, "plain", new AnalyticDataset.Options { Train = 2, Val = 1, Test = 1, PointCloud = 0 });
            Assert.That(Relight(plain, out _).Status, Is.EqualTo(DatasetCheckStatus.Skipped));
            Assert.That(Directory.Exists(Path.Combine(plain, "lights")), Is.False);
        }

        [Test]
        public void ARelightDatasetIsProvablyOursAndAStrayFileInLightsIsNot()
        {
            // "overwrite": "replace" deletes only what the plugin provably wrote (OwnDataset): the relit images and lights/ are.
            Assert.That(OwnDataset.WhyNotOurs(_dataset), Is.Null);
            var copy = Copy();
            File.WriteAllText(Path.Combine(copy, "lights", "notes.txt"), "mine");
            Assert.That(OwnDataset.WhyNotOurs(copy), Does.Contain("notes.txt").And.Contain("was not written by this plugin"));
            var other = Copy();
            File.WriteAllText(Path.Combine(other, "train", "r_0_light_Sky.png"), "not a key");
            Assert.That(OwnDataset.WhyNotOurs(other), Does.Contain("r_0_light_Sky.png"));
        }

        [Test]
        public void ThroughALensEachConditionIsResampledLikeTheView()
        {
            // The capture's lens path: a wide pinhole render resampled into the distorted frame (ViewPipeline); the relit
            // renders go through the same resampler, so they keep the view's size and alpha.
            var lens = AnalyticDataset.Write(_temp.Path, "relight-lens", new AnalyticDataset.Options
            {
                Train = 2, Val = 1, Test = 1, PointCloud = 0,
                Lens = new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.02 }, ThroughWideRender = true, DataAtOutputSize = false,
                Configure = s => s.Relighting = new RelightingSettings
                {
                    On = true, Conditions = { new LightingCondition { Name = "olat-00", Kind = LightingKind.Point, Position = new double[] { 2, -2, 3 }, Intensity = 25 } },
                },
            });
            var own = PngReader.Read(Path.Combine(lens, "train", "r_1.png"));
            var relit = PngReader.Read(Path.Combine(lens, "train", "r_1_light_olat-00.png"));
            Assert.That((relit.Width, relit.Height), Is.EqualTo((own.Width, own.Height)));
            var largest = Enumerable.Range(0, own.Width * own.Height).Max(i => Math.Abs(relit.Samples[i * 4 + 3] - own.Samples[i * 4 + 3]));
            Assert.That(largest, Is.LessThanOrEqualTo(RelightCheck.ToleranceCodes));
            Assert.That(Relight(lens, out _).Status, Is.EqualTo(DatasetCheckStatus.Passed));
        }

        string Copy() => DatasetFaults.Copy(_dataset, _temp.Combine("fault-" + ++_copies));

        void Fails(string folder, string message)
        {
            var relight = Relight(folder, out var report);
            Assert.That(relight.Status, Is.EqualTo(DatasetCheckStatus.Failed));
            Assert.That(report.Problems.Where(p => p.Check == "relight").Select(p => p.Message), Has.Some.Contains(message));
        }

        [Test]
        public void AMissingRelitImageFails()
        {
            var copy = Copy();
            File.Delete(Path.Combine(copy, "test", "r_0_light_sky_090.png"));
            Fails(copy, "which is not a file inside the dataset");
        }

        [Test]
        public void ARelitImageWithoutTheViewsAlphaFails()
        {
            var copy = Copy();
            DatasetFaults.EditImages(copy, f => f.EndsWith("r_1_light_olat-00.png", StringComparison.Ordinal), (png, samples, _) =>
            {
                for (var i = 3; i < samples.Length; i += 4) samples[i] = 255;
            });
            Fails(copy, "alpha differs from the view's image");
        }

        [Test]
        public void AFrameWithoutOneOfTheRecordedKeysFails()
        {
            var copy = Copy();
            var path = Path.Combine(copy, "transforms_val.json");
            var json = JObject.Parse(File.ReadAllText(path));
            ((JObject)json["frames"][0]["relit_paths"]).Remove("olat-00");
            File.WriteAllText(path, json.ToString());
            Fails(copy, "relit_paths has no \"olat-00\"");
        }

        [Test]
        public void ALightsFileThatDisagreesWithTheRecordFails()
        {
            var copy = Copy();
            var path = Path.Combine(copy, "lights", "lights.json");
            var json = JObject.Parse(File.ReadAllText(path));
            ((JArray)json["conditions"]).RemoveAt(1);
            File.WriteAllText(path, json.ToString());
            Fails(copy, "lists the keys sky_000, sky_090, but the relighting record");
        }

        [Test]
        public void AnEnvironmentThatIsNotTwoToOneFails()
        {
            var copy = Copy();
            File.WriteAllBytes(Path.Combine(copy, "lights", "sky.exr"), ExrWriter.Encode(new float[16 * 16 * 3], 16, 16, 3));
            Fails(copy, "is 16×16; an equirect map is twice as wide as it is high");
            File.Delete(Path.Combine(copy, "lights", "lights.json"));
            Fails(copy, "cannot be read as JSON");
        }
    }
}
