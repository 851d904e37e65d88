using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// 3DGS's depth supervision, reproduced here from graphdeco-inria/gaussian-splatting (54c035f), not from Core:
    /// utils/camera_utils.py:28 <c>invdepthmap = png / 2**16</c>; scene/cameras.py:65 negatives to 0, :69 unreliable when
    /// <c>scale &lt; 0.2·med_scale or scale &gt; 5·med_scale</c>, :73–74 <c>if scale &gt; 0: invdepth·scale + offset</c>;
    /// scene/dataset_readers.py:164–170 <c>med_scale</c> = median of the positive scales; the target is the rendered
    /// Σ(1/z)·α·T, i.e. 1/z for an opaque surface at z-depth z.
    /// </summary>
    public class GaussianSplattingDepthsTests
    {
        static double Read3dgs(int png, double scale, double offset)
        {
            var inv = Math.Max(0.0, png / 65536.0);
            return scale > 0 ? inv * scale + offset : inv;
        }

        // z (output units) → value = round(65536 / z) by hand.
        [TestCase(4.0, 16384)]   // 1/4 exactly
        [TestCase(2.0, 32768)]
        [TestCase(6.0, 10923)]   // 10922.67
        [TestCase(3.0, 21845)]   // 21845.33
        [TestCase(1.0000153, 65535)]
        public void AtScaleOne_3dgsReadsBackOneOverZ(double z, int expected)
        {
            Assert.That(GaussianSplattingDepths.ScaleFor(z), Is.EqualTo(1.0));
            var v = GaussianSplattingDepths.Encode(z, 1);
            Assert.That(v, Is.EqualTo(expected));
            // Rounding costs at most half a step of 1/65536.
            Assert.That(Read3dgs(v, 1, 0), Is.EqualTo(1 / z).Within(0.5 / 65536 + 1e-15));
            Assert.That(GaussianSplattingDepths.InverseDepth3dgs(v, 1, 0), Is.EqualTo(Read3dgs(v, 1, 0)));
        }

        [Test]
        public void NoSurfaceIsZero_TheInverseDepthOfEmptySpace() =>
            Assert.That(GaussianSplattingDepths.Encode(0, 1), Is.EqualTo(0));

        [Test]
        public void ANearSurfaceRaisesTheSharedScaleByPowersOfTwo()
        {
            // z = 0.5: 65536/0.5 = 131072 > 65535; ×2 → 65536 still > 65535; ×4 → 32768 fits.
            Assert.That(GaussianSplattingDepths.ScaleFor(0.5), Is.EqualTo(4.0));
            var v = GaussianSplattingDepths.Encode(0.5, 4);
            Assert.That(v, Is.EqualTo(32768));
            Assert.That(Read3dgs(v, 4, 0), Is.EqualTo(2.0), "32768/65536·4 = 2 = 1/0.5");
        }

        [Test]
        public void StemsAreTheNameWithoutItsLastExtension() // dataset_readers.py:100: n_remove = len(ext) + 1
        {
            Assert.That(GaussianSplattingDepths.Stem("train_r_0.png"), Is.EqualTo("train_r_0"));
            Assert.That(GaussianSplattingDepths.Stem("a.b.jpeg"), Is.EqualTo("a.b"));
        }

        [Test]
        public void StemsThatCollideAreAProblem()
        {
            var frames = new[]
            {
                new ExportFrame("train", "train/r_0.png", Matrix4x4d.Identity, "train/r_0_depth_0000.png"),
                new ExportFrame("train", "train/r_0.jpg", Matrix4x4d.Identity, "train/r_0_depth_0000.png"),
            };
            var problems = GaussianSplattingDepths.Check(frames, new[] { "train_r_0.png", "train_r_0.jpg" });
            Assert.That(problems.Single().Reason, Does.Contain("train_r_0"));
        }

        /// <summary>A 4×2 Blender dataset, 2 views per split; train and test have depth PNGs, val has none.</summary>
        sealed class SmallDataset : IDisposable
        {
            public const int W = 4, H = 2;
            readonly TempFolder _temp = new TempFolder();
            public string Root => _temp.Path;

            // Millimetre steps (output units × 1000): 4.000, 2.000, 0 = no hit, 6.000, and 1.000 (→ 65536 > 65535 at scale 1).
            public static readonly ushort[] Depth = { 4000, 2000, 0, 6000, 3000, 2500, 5000, 4000 };

            public SmallDataset(bool near = false)
            {
                foreach (var split in new[] { "train", "val", "test" })
                {
                    var frames = new JArray();
                    for (var i = 0; i < 2; i++)
                    {
                        var m = Matrix4x4d.Identity;
                        frames.Add(new JObject
                        {
                            ["file_path"] = "./" + split + "/r_" + i,
                            ["transform_matrix"] = new JArray(
                                new JArray(1.0, 0, 0, i), new JArray(0.0, 1, 0, 0), new JArray(0.0, 0, 1, 4), new JArray(0.0, 0, 0, 1)),
                        });
                        TestPng.Write(Path.Combine(Root, split, "r_" + i + ".png"), W, H);
                        if (split == "val") continue;
                        var samples = (ushort[])Depth.Clone();
                        if (near && split == "test" && i == 1) samples[0] = 500; // 0.5 output units
                        File.WriteAllBytes(Path.Combine(Root, split, "r_" + i + "_depth_0000.png"), PngWriter.EncodeGray16(samples, W, H));
                        ((JObject)frames[frames.Count - 1])["depth_path"] = "./" + split + "/r_" + i + "_depth_0000.png";
                    }
                    File.WriteAllText(Path.Combine(Root, "transforms_" + split + ".json"),
                        new JObject { ["camera_angle_x"] = 0.69, ["frames"] = frames }.ToString());
                }
            }

            public void Dispose() => _temp.Dispose();
        }

        static int[] Samples(string path)
        {
            var png = ReferencePngDecoder.Decode(File.ReadAllBytes(path));
            Assert.That(png.BitDepth, Is.EqualTo(16));
            Assert.That(png.ColorType, Is.EqualTo(0));
            return Enumerable.Range(0, png.Width * png.Height).Select(p => png.Pixels[2 * p] << 8 | png.Pixels[2 * p + 1]).ToArray();
        }

        [Test]
        public void ConvertToColmapWithDepths_WritesWhat3dgsReadsAsOneOverZ()
        {
            using (var data = new SmallDataset())
            {
                var result = DatasetConverter.Convert(data.Root, ExportTarget.Colmap, depths: true);

                var names = File.ReadAllLines(Path.Combine(result.OutputDirectory, "sparse", "0", "images.txt"))
                    .Where(l => l.Length > 0 && !l.StartsWith("#")).Select(l => l.Split(' ')[9]).ToList();
                Assert.That(names, Does.Contain("train_r_0.png").And.Contain("test_r_0.png"), "split folders flattened: no stem collision");
                var parameters = JObject.Parse(File.ReadAllText(Path.Combine(result.OutputDirectory, "sparse", "0", "depth_params.json")));
                Assert.That(parameters.Properties().Select(p => p.Name), Is.EquivalentTo(names.Select(n => n.Substring(0, n.Length - 4))));

                // The median of the positive scales, then the reliability test, as 3DGS computes them.
                var scales = parameters.Properties().Select(p => (double)p.Value["scale"]).ToList();
                var positive = scales.Where(s => s > 0).OrderBy(s => s).ToList();
                var median = positive.Count % 2 == 1 ? positive[positive.Count / 2] : 0.5 * (positive[positive.Count / 2 - 1] + positive[positive.Count / 2]);
                foreach (var name in names)
                {
                    var stem = name.Substring(0, name.Length - 4);
                    var scale = (double)parameters[stem]["scale"];
                    var offset = (double)parameters[stem]["offset"];
                    var reliable = !(scale < 0.2 * median || scale > 5 * median);
                    var samples = Samples(Path.Combine(result.OutputDirectory, "depths", stem + ".png"));
                    if (name.StartsWith("val_"))
                    {
                        Assert.That(reliable, Is.False, name + ": no depth, so 3DGS must skip its depth loss");
                        Assert.That(samples, Is.All.EqualTo(0));
                        continue;
                    }
                    Assert.That(scale, Is.EqualTo(1.0));
                    Assert.That(offset, Is.EqualTo(0.0));
                    Assert.That(reliable, Is.True, name);
                    for (var p = 0; p < samples.Length; p++)
                    {
                        var z = SmallDataset.Depth[p] / 1000.0;
                        var expected = z == 0 ? 0 : 1 / z;
                        Assert.That(Read3dgs(samples[p], scale, offset), Is.EqualTo(expected).Within(0.5 / 65536), name + " pixel " + p);
                    }
                }
                Assert.That(result.Warnings.Select(w => w.Field), Does.Contain("depth_params.json"), "the images without depth are named");
            }
        }

        [Test]
        public void ANearSurface_GivesEveryImageTheSameLargerScale()
        {
            using (var data = new SmallDataset(near: true))
            {
                var scene = BlenderDatasetLoader.Load(data.Root);
                var withDepth = new ExportScene(scene.RootDirectory, scene.Intrinsics,
                    scene.Frames.Where(f => f.Split != "val").Select(f => new ExportFrame(f.Split, f.ImagePath, f.CameraToWorld, f.ImagePath.Replace(".png", "_depth_0000.png"))));
                var result = DatasetConverter.Export(withDepth, ExportTarget.Colmap, depths: true);

                var parameters = JObject.Parse(File.ReadAllText(Path.Combine(result.OutputDirectory, "sparse", "0", "depth_params.json")));
                Assert.That(parameters.Properties().Select(p => (double)p.Value["scale"]), Is.All.EqualTo(4.0));
                var near = Samples(Path.Combine(result.OutputDirectory, "depths", "test_r_1.png"));
                Assert.That(Read3dgs(near[0], 4, 0), Is.EqualTo(2.0), "z = 0.5");
                Assert.That(Read3dgs(near[1], 4, 0), Is.EqualTo(0.5).Within(2 / 65536.0), "z = 2");
                Assert.That(result.Warnings.Select(w => w.Field), Does.Contain("depth_params.json: scale"));
            }
        }

        [Test]
        public void WithoutAnyDepth_DepthsIsRefusedBeforeWriting()
        {
            using (var lego = new LegoDataset())
            {
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(lego.Root, ExportTarget.Colmap, depths: true));
                Assert.That(e.Problems[0].Field, Is.EqualTo("--depths"));
                Assert.That(Directory.Exists(Path.Combine(lego.Root, "colmap")), Is.False);
            }
        }

        [Test]
        public void DepthsIsOnlyForColmap() =>
            Assert.Throws<InvalidParameterException>(() => DatasetConverter.Export(
                new ExportScene("/tmp", CameraIntrinsics.FromVerticalFov(40, 4, 2), new ExportFrame[0]), ExportTarget.Ngp, depths: true));
    }
}
