using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// convert --to multiscale read back the way its readers read it:
    /// gsplat examples/datasets/colmap.py at nerfstudio-project/gsplat 90d7b4b (Parser: K[:2, :] /= factor at line 169, imsize
    /// cam.width // factor at 176, images_&lt;factor&gt; paired with images/ by sorted position via dict(zip(colmap_files,
    /// image_files)) at 232–239, then K rescaled by the actual image size at 355–358), and google/mipnerf
    /// internal/datasets.py at 84c969e (Multicam: metadata.json[split] at 220, rays through (x + ½, y + ½, 1)·pix2cam[:3, :3]ᵀ
    /// at 266–272), with Tri-MipRF's dataset/parsers/nerf_synthetic_multiscale.py at 5b54a27 (entries grouped by index % 4
    /// at 56, K = inv(pix2cam) at 36–40). Sources: Documentation~/maintainers/layouts-multiscale-hdr.md.
    /// Expected pixels are computed here in doubles from the source images, independently of PremultipliedBox.
    /// </summary>
    public class MultiscaleExportTests
    {
        /// <summary>The block average of <paramref name="src"/> (RGBA rows) at 1/f, composited over bg, in doubles: Σ(c·a + bg·(255 − a)) / (255·n), nearest.</summary>
        static byte[] HandRgbOver(byte[] src, int w, int f, int bg)
        {
            int h = src.Length / 4 / w, ow = w / f, oh = h / f;
            var o = new byte[ow * oh * 3];
            for (var y = 0; y < oh; y++)
                for (var x = 0; x < ow; x++)
                    for (var c = 0; c < 3; c++)
                    {
                        double sum = 0;
                        for (var j = 0; j < f; j++)
                            for (var i = 0; i < f; i++)
                            {
                                var s = ((y * f + j) * w + x * f + i) * 4;
                                sum += (src[s + c] * (double)src[s + 3] + bg * (255.0 - src[s + 3])) / 255;
                            }
                        o[(y * ow + x) * 3 + c] = (byte)Math.Floor(sum / (f * f) + 0.5);
                    }
            return o;
        }

        /// <summary>Premultiplied box in doubles: alpha = mean a, colour = Σ c·a / Σ a (0 where nothing covers), nearest.</summary>
        static byte[] HandRgba(byte[] src, int w, int f)
        {
            int h = src.Length / 4 / w, ow = w / f, oh = h / f;
            var o = new byte[ow * oh * 4];
            for (var y = 0; y < oh; y++)
                for (var x = 0; x < ow; x++)
                {
                    double a = 0;
                    var p = new double[3];
                    for (var j = 0; j < f; j++)
                        for (var i = 0; i < f; i++)
                        {
                            var s = ((y * f + j) * w + x * f + i) * 4;
                            a += src[s + 3];
                            for (var c = 0; c < 3; c++) p[c] += src[s + c] * (double)src[s + 3];
                        }
                    var d = (y * ow + x) * 4;
                    for (var c = 0; c < 3; c++) o[d + c] = a == 0 ? (byte)0 : (byte)Math.Floor(p[c] / a + 0.5);
                    o[d + 3] = (byte)Math.Floor(a / (f * f) + 0.5);
                }
            return o;
        }

        /// <summary>
        /// google/mipnerf convert_blender_data.py <c>down2</c> (mean of straight RGBA over 2×2) then <c>np.uint8(img * 255)</c>
        /// (truncation), and Mip-Splatting's readMultiScale composite over white (<c>rgb·a + bg·(1 − a)</c>, then
        /// <c>np.array(arr * 255, dtype=np.byte)</c>: truncation).
        /// </summary>
        static int[] StraightConverterOverWhite(byte[][] block)
        {
            var mean = new double[4];
            foreach (var px in block) for (var c = 0; c < 4; c++) mean[c] += px[c] / 255.0 / block.Length;
            var stored = mean.Select(v => (int)(v * 255)).ToArray();
            double alpha = stored[3] / 255.0;
            return Enumerable.Range(0, 3).Select(c => (int)((stored[c] / 255.0 * alpha + (1 - alpha)) * 255)).ToArray();
        }

        [Test]
        public void AHalfCoveredBlockKeepsItsColourWhereStraightAveragingDarkensIt()
        {
            // 2×2: two opaque red pixels, two transparent black ones (what a capture stores outside the target).
            var src = new byte[] { 255, 0, 0, 255, 0, 0, 0, 0, 0, 0, 0, 0, 255, 0, 0, 255 };
            Assert.That(PremultipliedBox.Rgba(src, 2, 2, 4, 2), Is.EqualTo(new byte[] { 255, 0, 0, 128 }), "colour of the covered half, alpha ½ (127.5 rounded up)");
            Assert.That(PremultipliedBox.RgbOver(src, 2, 2, 4, 2, 255, 255, 255), Is.EqualTo(new byte[] { 255, 128, 128 }), "the mean of the composites, (255, 127.5, 127.5), rounded up");
            // The loader composites our RGBA over white: 255·128/255 + 255·127/255 = 255 red, 255·127/255 = 127 green.
            var ours = new[] { 255, 0, 0 }.Select(c => (int)Math.Floor((c * 128 + 255 * 127) / 255.0 + 0.5)).ToArray();
            Assert.That(ours, Is.EqualTo(new[] { 255, 127, 127 }));
            var straight = StraightConverterOverWhite(new[] { new byte[] { 255, 0, 0, 255 }, new byte[4], new byte[4], new byte[] { 255, 0, 0, 255 } });
            TestContext.WriteLine("half-covered red block over white: premultiplied " + string.Join(",", ours) + ", straight-alpha converter " + string.Join(",", straight) + ", truth 255,127.5,127.5");
            Assert.That(straight, Is.EqualTo(new[] { 191, 128, 128 }), "the straight average stores (127, 0, 0) at alpha 127: the edge is 64 codes darker in red");
        }

        [Test]
        public void LevelOneIsTheCompositeAndTheRemainderIsDropped()
        {
            var random = new Random(7);
            var src = new byte[11 * 9 * 4];
            random.NextBytes(src);
            var rgb = new byte[11 * 9 * 3];
            AlphaCompositing.OverSolid(src, rgb, 11 * 9, 10, 200, 30);
            Assert.That(PremultipliedBox.RgbOver(src, 11, 9, 4, 1, 10, 200, 30), Is.EqualTo(rgb), "factor 1 rounds as AlphaCompositing.Over");
            Assert.That(PremultipliedBox.Rgba(src, 11, 9, 4, 1).Where((b, i) => src[i - i % 4 + 3] != 0), Is.EqualTo(src.Where((b, i) => src[i - i % 4 + 3] != 0)), "factor 1 keeps every covered pixel");
            // 11×9 at 1/4: 2×2 pixels from the 8×8 top-left; columns 8–10 and row 8 are dropped.
            var cropped = new byte[8 * 8 * 4];
            for (var y = 0; y < 8; y++) Array.Copy(src, y * 11 * 4, cropped, y * 8 * 4, 8 * 4);
            Assert.That(PremultipliedBox.Rgba(src, 11, 9, 4, 4), Is.EqualTo(HandRgba(cropped, 8, 4)));
            Assert.That(PremultipliedBox.RgbOver(src, 11, 9, 4, 4, 255, 255, 255), Is.EqualTo(HandRgbOver(cropped, 8, 4, 255)));
        }

        static double D(JToken t) => (double)t;

        static Dictionary<string, (string Split, double[][] Pose)> TruthPoses(string dataset)
        {
            var poses = new Dictionary<string, (string, double[][])>();
            foreach (var split in new[] { "train", "val", "test" })
            {
                var json = JObject.Parse(File.ReadAllText(Path.Combine(dataset, "transforms_" + split + ".json")));
                foreach (var frame in json["frames"])
                {
                    var path = (string)frame["file_path"];
                    if (!path.EndsWith(".png", StringComparison.Ordinal)) path += ".png";
                    poses[path.TrimStart('.', '/')] = (split, frame["transform_matrix"].Select(r => r.Select(D).ToArray()).ToArray());
                }
            }
            return poses;
        }

        [Test]
        public void AnAnalyticDatasetReadsBackThroughGsplatAndMipNerf()
        {
            using (var temp = new TempFolder())
            {
                var dataset = AnalyticDataset.Write(temp.Path, "ms", new AnalyticDataset.Options { Width = 48, Height = 40, Train = 4, Val = 1, Test = 2, PointCloud = 200 });
                var truth = TruthPoses(dataset);
                var train = JObject.Parse(File.ReadAllText(Path.Combine(dataset, "transforms_train.json")));
                double fx = D(train["fl_x"]), fy = D(train["fl_y"]), cx = D(train["cx"]), cy = D(train["cy"]);

                var result = DatasetConverter.Convert(dataset, ExportTarget.Multiscale);
                var colmap = Path.Combine(dataset, "multiscale", "colmap");
                var mip = Path.Combine(dataset, "multiscale", "mipnerf");
                Assert.That(result.MainFile, Is.EqualTo(Path.Combine(mip, "metadata.json")));
                foreach (var line in result.TrainCommands) TestContext.WriteLine(line);

                // gsplat Parser, factor 4: K from cameras.txt divided by 4, imsize W // 4, images_4 paired by sorted position.
                var model = ColmapTestModel.ReadText(Path.Combine(colmap, "sparse", "0"));
                var camera = model.Cameras.Values.Single();
                Assert.That(camera.Model, Is.EqualTo("PINHOLE"));
                Assert.That(camera.Params, Is.EqualTo(new[] { fx, fy, cx, cy }), "intrinsics exactly");
                foreach (var factor in new[] { 2, 4, 8 })
                {
                    var colmapFiles = Directory.GetFiles(Path.Combine(colmap, "images")).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal).ToList();
                    var imageFiles = Directory.GetFiles(Path.Combine(colmap, "images_" + factor)).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal).ToList();
                    Assert.That(imageFiles, Is.EqualTo(colmapFiles), "zip(sorted, sorted) pairs every image with its own name");
                    foreach (var image in model.Images)
                    {
                        var png = PngReader.Read(Path.Combine(colmap, "images_" + factor, image.Name));
                        Assert.That((png.Width, png.Height), Is.EqualTo((camera.Width / factor, camera.Height / factor)), "s_width = s_height = 1: K stays K / factor");
                        Assert.That(png.ColorType, Is.EqualTo(PngInfo.ColorTypeRgb));
                        var source = PngReader.Read(Path.Combine(dataset, image.Name.Replace("train_", "train/").Replace("val_", "val/").Replace("test_", "test/")));
                        Assert.That(png.Samples, Is.EqualTo(HandRgbOver(source.Samples, source.Width, factor, 255)), image.Name + " at 1/" + factor + " over white");
                    }
                }
                double worst = 0;
                foreach (var image in model.Images)
                {
                    // qvec2rotmat, world-to-camera; c2w = inv(w2c) with OpenCV axes = the Blender c2w with its y and z columns negated.
                    double qw = image.QW, qx = image.QX, qy = image.QY, qz = image.QZ;
                    var r = new[]
                    {
                        new[] { 1 - 2 * qy * qy - 2 * qz * qz, 2 * qx * qy - 2 * qw * qz, 2 * qz * qx + 2 * qw * qy },
                        new[] { 2 * qx * qy + 2 * qw * qz, 1 - 2 * qx * qx - 2 * qz * qz, 2 * qy * qz - 2 * qw * qx },
                        new[] { 2 * qz * qx - 2 * qw * qy, 2 * qy * qz + 2 * qw * qx, 1 - 2 * qx * qx - 2 * qy * qy },
                    };
                    var t = new[] { image.TX, image.TY, image.TZ };
                    var pose = truth[image.Name.Substring(0, image.Name.IndexOf('_')) + "/" + image.Name.Substring(image.Name.IndexOf('_') + 1)].Pose;
                    for (var row = 0; row < 3; row++)
                    {
                        for (var col = 0; col < 3; col++)
                        {
                            var expected = pose[row][col] * (col == 0 ? 1 : -1);
                            worst = Math.Max(worst, Math.Abs(r[col][row] - expected));
                        }
                        var centre = -(r[0][row] * t[0] + r[1][row] * t[1] + r[2][row] * t[2]);
                        worst = Math.Max(worst, Math.Abs(centre - pose[row][3]));
                    }
                }
                TestContext.WriteLine("gsplat pose round trip, worst error " + worst.ToString("R", CultureInfo.InvariantCulture));
                Assert.That(worst, Is.LessThan(1e-6));

                // mip-NeRF Multicam and Tri-MipRF on metadata.json.
                var meta = JObject.Parse(File.ReadAllText(result.MainFile));
                Assert.That(meta.Properties().Select(p => p.Name), Is.EqualTo(new[] { "train", "val", "test" }));
                foreach (var split in new[] { "train", "val", "test" })
                {
                    var m = meta[split];
                    var files = m["file_path"].Select(v => (string)v).ToList();
                    Assert.That(files.Count, Is.EqualTo(truth.Values.Count(v => v.Split == split) * 4));
                    if (files.Count > 4) Assert.That(m["pix2cam"][0].ToString(), Is.EqualTo(m["pix2cam"][4].ToString()), "Tri-MipRF asserts pix2cam[0] == pix2cam[cam_num]");
                    for (var e = 0; e < files.Count; e++)
                    {
                        var level = e % 4;
                        var factor = 1 << level;
                        Assert.That(files[e], Does.EndWith("_d" + level + ".png"), "frame-major levels d0…d3");
                        var source = files[e].Substring(0, files[e].Length - "_d0.png".Length).Replace(split + "/" + split + "_", split + "/") + ".png";
                        Assert.That(truth[source].Split, Is.EqualTo(split));
                        var c2w = m["cam2world"][e].Select(row => row.Select(D).ToArray()).ToArray();
                        for (var row = 0; row < 3; row++) for (var col = 0; col < 4; col++) Assert.That(c2w[row][col], Is.EqualTo(truth[source].Pose[row][col]).Within(1e-6));
                        Assert.That((int)m["width"][e], Is.EqualTo(48 / factor));
                        Assert.That((int)m["height"][e], Is.EqualTo(40 / factor));
                        Assert.That(D(m["focal"][e]), Is.EqualTo(fx / factor), "focal exactly");
                        Assert.That(D(m["lossmult"][e]), Is.EqualTo(factor * factor));
                        // Multicam._generate_rays: (x + ½, y + ½, 1)·pix2camᵀ is the camera ray; at level j it must be the source ray
                        // through (2ʲ(x + ½), 2ʲ(y + ½)): ((u − cx)/fx, −(v − cy)/fy, −1).
                        var p2c = m["pix2cam"][e].Select(row => row.Select(D).ToArray()).ToArray();
                        foreach (var (x, y) in new[] { (0, 0), (48 / factor - 1, 40 / factor - 1), (3 % (48 / factor), 2) })
                        {
                            var px = new[] { x + 0.5, y + 0.5, 1.0 };
                            var dir = Enumerable.Range(0, 3).Select(row => p2c[row][0] * px[0] + p2c[row][1] * px[1] + p2c[row][2] * px[2]).ToArray();
                            Assert.That(dir[0], Is.EqualTo((factor * (x + 0.5) - cx) / fx).Within(1e-12));
                            Assert.That(dir[1], Is.EqualTo(-(factor * (y + 0.5) - cy) / fy).Within(1e-12));
                            Assert.That(dir[2], Is.EqualTo(-1.0));
                        }
                        // Tri-MipRF: k = inv(pix2cam); fx = k[0,0], fy = −k[1,1], cx = −k[0,2], cy = −k[1,2].
                        Assert.That(1 / p2c[0][0], Is.EqualTo(fx / factor).Within(1e-9));
                        Assert.That(-1 / p2c[1][1], Is.EqualTo(fy / factor).Within(1e-9));
                        Assert.That(-p2c[0][2] / p2c[0][0], Is.EqualTo(cx / factor).Within(1e-9));
                        Assert.That(p2c[1][2] / -p2c[1][1], Is.EqualTo(cy / factor).Within(1e-9));
                        Assert.That(D(m["near"][e]), Is.GreaterThan(0).And.LessThan(D(m["far"][e])));

                        var png = PngReader.Read(Path.Combine(mip, files[e]));
                        Assert.That((png.Width, png.Height, png.ColorType), Is.EqualTo((48 / factor, 40 / factor, PngInfo.ColorTypeRgba)));
                        var original = PngReader.Read(Path.Combine(dataset, source));
                        if (level == 0) Assert.That(Covered(png.Samples), Is.EqualTo(Covered(original.Samples)), "d0 keeps every covered pixel");
                        else Assert.That(png.Samples, Is.EqualTo(HandRgba(original.Samples, 48, factor)), files[e]);
                    }
                }
            }
        }

        /// <summary>RGBA with the colour of uncovered pixels zeroed (it carries nothing).</summary>
        static byte[] Covered(byte[] rgba)
        {
            var o = (byte[])rgba.Clone();
            for (var i = 0; i < o.Length; i += 4)
                if (o[i + 3] == 0) o[i] = o[i + 1] = o[i + 2] = 0;
            return o;
        }

        /// <summary>A nerf_synthetic-style dataset by hand: <paramref name="w"/>×<paramref name="h"/> RGBA images, one per split.</summary>
        static string HandDataset(string root, int w, int h, string extra = "")
        {
            Directory.CreateDirectory(root);
            foreach (var split in new[] { "train", "val", "test" })
            {
                TestPng.Write(Path.Combine(root, split, "r_0.png"), w, h);
                File.WriteAllText(Path.Combine(root, "transforms_" + split + ".json"),
                    "{\"camera_angle_x\": 0.69, " + extra + "\"frames\": [{\"file_path\": \"./" + split + "/r_0\", \"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]]}]}");
            }
            return root;
        }

        [Test]
        public void SizesNotDivisibleByEightAreWarnedAndTinyOnesRefused()
        {
            using (var temp = new TempFolder())
            {
                var dataset = HandDataset(temp.Combine("odd"), 12, 10);
                var result = DatasetConverter.Convert(dataset, ExportTarget.Multiscale);
                Assert.That(result.Warnings.Select(w => w.Reason), Has.Some.Contains("is not divisible by 8").And.Some.Contains("nerf_synthetic's bounds"));
                var meta = JObject.Parse(File.ReadAllText(result.MainFile));
                Assert.That(meta["train"]["width"].Select(v => (int)v), Is.EqualTo(new[] { 12, 6, 3, 1 }));
                Assert.That(meta["train"]["height"].Select(v => (int)v), Is.EqualTo(new[] { 10, 5, 2, 1 }));
                var png = PngReader.Read(Path.Combine(dataset, "multiscale", "colmap", "images_8", "train_r_0.png"));
                Assert.That((png.Width, png.Height), Is.EqualTo((1, 1)));

                var tiny = HandDataset(temp.Combine("tiny"), 12, 6);
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(tiny, ExportTarget.Multiscale));
                Assert.That(e.Message, Does.Contain("12×6").And.Contain("1/8 level"));
                Assert.That(Directory.Exists(Path.Combine(tiny, "multiscale")), Is.False, "nothing written");
            }
        }

        [Test]
        public void ALensIsRefusedAndGsplatsHoldOutIsNamed()
        {
            using (var temp = new TempFolder())
            {
                var plain = DatasetConverter.Convert(HandDataset(temp.Combine("plain"), 16, 16), ExportTarget.Multiscale);
                Assert.That(plain.Warnings.Select(w => w.Reason), Has.Some.Contains("every 8th image in name order"));
                var lens = HandDataset(temp.Combine("lens"), 16, 16, "\"camera_model\": \"OPENCV\", \"k1\": -0.1, ");
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(lens, ExportTarget.Multiscale));
                Assert.That(e.Message, Does.Contain("cannot hold lens distortion").And.Contain("pix2cam"));
                Assert.That(Directory.Exists(Path.Combine(lens, "multiscale")), Is.False, "nothing written");
            }
        }

        [Test]
        public void ConvertRefusesToOverwrite()
        {
            using (var temp = new TempFolder())
            {
                var dataset = AnalyticDataset.Write(temp.Path, "ms", new AnalyticDataset.Options { Width = 16, Height = 8, Train = 2, Val = 1, Test = 1, PointCloud = 50 });
                Directory.CreateDirectory(Path.Combine(dataset, "multiscale", "mipnerf"));
                File.WriteAllText(Path.Combine(dataset, "multiscale", "mipnerf", "metadata.json"), "mine");
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(dataset, ExportTarget.Multiscale));
                Assert.That(e.Message, Does.Contain("metadata.json").And.Contain("never overwrites"));
                Assert.That(File.ReadAllText(Path.Combine(dataset, "multiscale", "mipnerf", "metadata.json")), Is.EqualTo("mine"));
                Assert.That(Directory.Exists(Path.Combine(dataset, "multiscale", "colmap")), Is.False, "nothing written");
            }
        }

        [Test]
        public void TheTargetIsNamedMultiscale()
        {
            Assert.That(ExportTargets.Parse("multiscale", out var problem), Is.EqualTo(ExportTarget.Multiscale));
            Assert.That(problem, Is.Null);
        }
    }
}
