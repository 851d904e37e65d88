using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <c>convert --background</c>: the written RGB pixels equal straight alpha over the colour on the sRGB codes,
    /// computed by hand below; the alpha is kept as masks/; random colours follow the documented SHA-256 rule (bytes from
    /// Python's hashlib); the trainers that composite themselves are refused.
    /// </summary>
    public class BackgroundExportTests
    {
        // Five pixels RGBA: half-covered orange, fully transparent, opaque, barely covered red, and fully transparent black.
        static readonly byte[] Pixels = { 200, 100, 50, 128, 10, 20, 30, 0, 10, 20, 30, 255, 255, 0, 0, 1, 0, 0, 0, 0 };
        const int W = 5, H = 1;

        // (c·a + bg·(255 − a)) / 255 to the nearest code, by hand: 200·128 + 255·127 = 57985, /255 = 227.39 → 227; 100·128 + 32385 = 45185 → 177.20 → 177;
        // 50·128 + 32385 = 38785 → 152.10 → 152. a = 0: the background. a = 255: the colour. (255, 0, 0, 1): 255·1 + 255·254 = 64770 → 254.00 is 254 for G and B, 255 for R.
        static readonly byte[] OverWhite = { 227, 177, 152, 255, 255, 255, 10, 20, 30, 255, 254, 254, 255, 255, 255 };
        // Over black: 25600/255 = 100.39 → 100; 12800/255 = 50.20 → 50; 6400/255 = 25.10 → 25; 255·1/255 = 1 → 1.
        static readonly byte[] OverBlack = { 100, 50, 25, 0, 0, 0, 10, 20, 30, 1, 0, 0, 0, 0, 0 };

        static string Dataset(TempFolder temp)
        {
            var root = temp.Combine("d");
            foreach (var (split, count) in new[] { ("train", 2), ("val", 0), ("test", 2) })
            {
                Directory.CreateDirectory(Path.Combine(root, split));
                var frames = new JArray();
                for (var i = 0; i < count; i++)
                {
                    File.WriteAllBytes(Path.Combine(root, split, "r_" + i + ".png"), PngWriter.Encode(Pixels, W, H, PngPixelFormat.Rgba8));
                    var c2w = AnalyticSphereDataset.LookAtOrigin(AnalyticSphereDataset.Eye(i, 2, split == "test" ? 0.5 : 0));
                    frames.Add(new JObject { ["file_path"] = "./" + split + "/r_" + i, ["transform_matrix"] = JArray.FromObject(c2w.ToRows()) });
                }
                File.WriteAllText(Path.Combine(root, "transforms_" + split + ".json"), new JObject { ["camera_angle_x"] = 0.69, ["frames"] = frames }.ToString());
            }
            return root;
        }

        static byte[] Rgb(string path)
        {
            var png = PngReader.Read(path);
            Assert.That((png.Width, png.Height, png.ColorType, png.BitDepth), Is.EqualTo((W, H, PngInfo.ColorTypeRgb, 8)), path);
            return png.Samples;
        }

        [Test]
        public void ColmapCompositesAreStraightAlphaOverTheColourToTheCodeAndKeepTheAlphaAsMasks()
        {
            using (var temp = new TempFolder())
            {
                var root = Dataset(temp);
                var stdout = new StringWriter();
                Assert.That(ToolCommands.Run(new[] { "convert", root, "--to", "colmap", "--background", "white" }, stdout, new StringWriter()), Is.EqualTo(0));
                Assert.That(ToolCommands.Run(new[] { "convert", root, "--to", "3dgs", "--background", "black" }, stdout, new StringWriter()), Is.EqualTo(0));
                var white = Path.Combine(root, "colmap_white");
                Assert.That(Rgb(Path.Combine(white, "images", "train_r_0.png")), Is.EqualTo(OverWhite));
                Assert.That(Rgb(Path.Combine(white, "images", "test_r_1.png")), Is.EqualTo(OverWhite));
                Assert.That(Rgb(Path.Combine(root, "colmap_black", "images", "train_r_1.png")), Is.EqualTo(OverBlack));
                var mask = PngReader.Read(Path.Combine(white, "masks", "train_r_0.png"));
                Assert.That((mask.ColorType, mask.Samples), Is.EqualTo((PngInfo.ColorTypeGray, new byte[] { 128, 0, 255, 1, 0 })));
                Assert.That(Directory.GetFiles(Path.Combine(white, "images")).Select(Path.GetFileName).OrderBy(n => n), Is.EqualTo(new[] { "test_r_0.png", "test_r_1.png", "train_r_0.png", "train_r_1.png" }),
                    "images/ holds the images only (gsplat pairs its files by sorted name)");
                var record = JObject.Parse(File.ReadAllText(Path.Combine(white, "backgrounds.json")));
                Assert.That(record["images"]["test/r_1.png"].Select(t => (int)t), Is.EqualTo(new[] { 255, 255, 255 }));
                Assert.That(stdout.ToString(), Does.Contain("python train.py -s " + white + " --eval -w"), "3DGS renders on white with -w");
                Assert.That(File.ReadAllText(Path.Combine(white, "sparse", "0", "test.txt")), Is.EqualTo("test_r_0.png\ntest_r_1.png\n"));
                // The dataset's own images are untouched.
                Assert.That(PngReader.Read(Path.Combine(root, "train", "r_0.png")).Samples, Is.EqualTo(Pixels));
            }
        }

        [Test]
        public void RandomColoursFollowTheSeedRuleAndAreRecorded()
        {
            // hashlib.sha256(b"7/train/r_0.png").digest()[:3] == [107, 45, 8]; b"7/test/r_1.png" → [131, 190, 149]; b"0/train/r_0.png" → [120, 62, 173].
            Assert.That(ExportBackground.Parse("random", 7, out _).ColourOf("./train/r_0.png"), Is.EqualTo(((byte)107, (byte)45, (byte)8)));
            Assert.That(ExportBackground.Parse("random", 7, out _).ColourOf("test/r_1.png"), Is.EqualTo(((byte)131, (byte)190, (byte)149)));
            Assert.That(ExportBackground.Parse("RANDOM", 0, out _).ColourOf("train/r_0.png"), Is.EqualTo(((byte)120, (byte)62, (byte)173)));
            using (var temp = new TempFolder())
            {
                var root = Dataset(temp);
                Assert.That(ToolCommands.Run(new[] { "convert", root, "--to", "nerfstudio", "--background", "random", "--seed", "7" }, new StringWriter(), new StringWriter()), Is.EqualTo(0));
                var outDir = Path.Combine(root, "nerfstudio_random");
                // Pixel 0 over (107, 45, 8): (25600 + 107·127 = 39189) / 255 = 153.68 → 154; (12800 + 5715 = 18515) / 255 = 72.61 → 73; (6400 + 1016 = 7416) / 255 = 29.08 → 29.
                var samples = Rgb(Path.Combine(outDir, "images", "train", "r_0.png"));
                Assert.That(samples.Take(6), Is.EqualTo(new byte[] { 154, 73, 29, 107, 45, 8 }));
                var record = JObject.Parse(File.ReadAllText(Path.Combine(outDir, "backgrounds.json")));
                Assert.That((long)record["seed"], Is.EqualTo(7));
                Assert.That((string)record["rule"], Does.Contain("SHA-256"));
                Assert.That(record["images"]["test/r_1.png"].Select(t => (int)t), Is.EqualTo(new[] { 131, 190, 149 }));
                var transforms = JObject.Parse(File.ReadAllText(Path.Combine(outDir, "transforms.json")));
                var frame = transforms["frames"][0];
                Assert.That((string)frame["file_path"], Is.EqualTo("images/train/r_0.png"));
                Assert.That(frame["mask_path"], Is.Null, "the alpha is not named as mask_path: nerfstudio would then never sample the background");
                Assert.That(File.Exists(Path.Combine(outDir, "masks", "train", "r_0.png")), Is.True);
            }
        }

        [Test]
        public void ProtocolIsTheDatasetsProtocolBackground()
        {
            using (var temp = new TempFolder())
            {
                var root = Dataset(temp);
                var stdout = new StringWriter();
                // No config and no protocol file: nerf_synthetic's white (ProtocolBackground.For).
                Assert.That(ToolCommands.Run(new[] { "convert", root, "--to", "colmap", "--background", "protocol" }, stdout, new StringWriter()), Is.EqualTo(0));
                var white = Path.Combine(root, "colmap_white");
                Assert.That(Rgb(Path.Combine(white, "images", "train_r_0.png")), Is.EqualTo(OverWhite));
                var record = JObject.Parse(File.ReadAllText(Path.Combine(white, "backgrounds.json")));
                Assert.That((string)record["background"], Is.EqualTo("white"));
                Assert.That((string)record["from"], Does.Contain("protocol"));
                Assert.That(stdout.ToString(), Does.Contain(" --eval -w"));
            }
        }

        [Test]
        public void NerfstudioGetsTheBackgroundFlagAndTheOtherTargetsAreRefused()
        {
            using (var temp = new TempFolder())
            {
                var root = Dataset(temp);
                var stdout = new StringWriter();
                Assert.That(ToolCommands.Run(new[] { "convert", root, "--to", "nerfstudio", "--background", "white" }, stdout, new StringWriter()), Is.EqualTo(0));
                Assert.That(stdout.ToString(), Does.Contain("ns-train splatfacto --pipeline.model.background-color white --data"));
                Assert.That(Rgb(Path.Combine(root, "nerfstudio_white", "images", "test", "r_0.png")), Is.EqualTo(OverWhite));

                var stderr = new StringWriter();
                Assert.That(ToolCommands.Run(new[] { "convert", root, "--to", "ngp", "--background", "white" }, new StringWriter(), stderr), Is.EqualTo(2));
                Assert.That(stderr.ToString(), Does.Contain("instant-ngp composites the RGBA images over a random colour itself"));
                Assert.That(ToolCommands.Run(new[] { "convert", root, "--to", "dynamic3dgs", "--background", "black" }, new StringWriter(), stderr = new StringWriter()), Is.EqualTo(2));
                Assert.That(stderr.ToString(), Does.Contain("is for the colmap and nerfstudio exports"));
                Assert.That(ToolCommands.Run(new[] { "convert", root, "--to", "colmap", "--background", "white", "--seed", "3" }, new StringWriter(), stderr = new StringWriter()), Is.EqualTo(2));
                Assert.That(stderr.ToString(), Does.Contain("--seed picks the colours of --background random"));
                Assert.That(ToolCommands.Run(new[] { "convert", root, "--to", "colmap", "--background", "grey" }, new StringWriter(), stderr = new StringWriter()), Is.EqualTo(2));
                Assert.That(stderr.ToString(), Does.Contain("is not white, black, random or protocol"));
                Assert.That(Directory.Exists(Path.Combine(root, "ngp_white")), Is.False);
            }
        }
    }
}
