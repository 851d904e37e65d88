using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// convert --to llff read back through LLFF's loader as bmild/nerf 14c5556 load_llff.py writes it: _load_data
    /// (lines 64–66 poses_bounds.npy → poses, bds; 96 the sorted image list; 100 the count check; 102 H, W from the image;
    /// 114 <c>imread(f)[..., :3]</c>) and load_llff_data's axis swap (line 250), against the dataset's own
    /// transform_matrix, NeRF's focal and the analytic scene's depth.
    /// </summary>
    public class LlffExportTests
    {
        sealed class LlffView
        {
            public string Name;
            public Matrix4x4d CameraToWorld;
            public double H, W, Focal, Near, Far;
            public PngImage Image;
        }

        /// <summary>load_llff.py _load_data + line 250, with factor None (images/ as it is).</summary>
        static List<LlffView> Load(string basedir)
        {
            var (rows, columns, arr) = NumpyFloat64Tests.ParseFloat64(File.ReadAllBytes(Path.Combine(basedir, "poses_bounds.npy")));
            Assert.That(columns, Is.EqualTo(17));
            var imgdir = Path.Combine(basedir, "images");
            // sorted(os.listdir(imgdir)) keeping names that end with JPG, jpg or png: Python sorts str by code point.
            var imgfiles = Directory.GetFiles(imgdir).Select(Path.GetFileName)
                .Where(f => f.EndsWith("JPG", StringComparison.Ordinal) || f.EndsWith("jpg", StringComparison.Ordinal) || f.EndsWith("png", StringComparison.Ordinal))
                .OrderBy(f => f, StringComparer.Ordinal).ToList();
            Assert.That(imgfiles.Count, Is.EqualTo(rows), "Mismatch between imgs and poses (line 100)");
            var views = new List<LlffView>();
            for (var n = 0; n < rows; n++)
            {
                double P(int r, int c) => arr[17 * n + 5 * r + c]; // reshape([-1, 3, 5])
                // Line 250: [c1, −c0, c2, t] — right, up, back: OpenGL's camera-to-world.
                var c2w = Matrix4x4d.FromRowMajor(
                    P(0, 1), -P(0, 0), P(0, 2), P(0, 3),
                    P(1, 1), -P(1, 0), P(1, 2), P(1, 3),
                    P(2, 1), -P(2, 0), P(2, 2), P(2, 3),
                    0, 0, 0, 1);
                var image = PngReader.Read(Path.Combine(imgdir, imgfiles[n]));
                views.Add(new LlffView
                {
                    Name = imgfiles[n], CameraToWorld = c2w, H = P(0, 4), W = P(1, 4), Focal = P(2, 4),
                    Near = arr[17 * n + 15], Far = arr[17 * n + 16], Image = image,
                });
            }
            return views;
        }

        static Matrix4x4d FromJson(JToken rows) => Matrix4x4d.FromRows(rows.Select(r => r.Select(v => (double)v).ToArray()).ToArray());

        [Test]
        public void ARowIsDownRightBackTranslationAndHwfThenTheBounds()
        {
            // A camera at (1, 2, 3) whose right is +Y, up +Z and back −X (looking along +X).
            var c2w = Matrix4x4d.FromRowMajor(
                0, 0, -1, 1,
                1, 0, 0, 2,
                0, 1, 0, 3,
                0, 0, 0, 1);
            var row = Llff.Row(c2w, 30, 40, 50, 0.5, 7);
            // Columns: down = −up = (0, 0, −1), right = (0, 1, 0), back = (−1, 0, 0), t, then H, W, f down the last column.
            Assert.That(row, Is.EqualTo(new double[]
            {
                0, 0, -1, 1, 30,
                0, 1, 0, 2, 40,
                -1, 0, 0, 3, 50,
                0.5, 7,
            }));
        }

        [Test]
        public void OnlyACentredSquarePixelCameraFitsHwf()
        {
            Assert.That(Llff.CameraRefusal(CameraIntrinsics.FromVerticalFov(60, 40, 30), "llff"), Is.Null);
            // A lens shift of 0.1 moves cx to W/2 − 4: get_rays' (i − W/2)/focal would miss every pixel by 4.
            var shifted = Llff.CameraRefusal(CameraIntrinsics.FromVerticalFov(60, 40, 30, 0.1, 0), "llff");
            Assert.That(shifted.Field, Is.EqualTo("--to"));
            Assert.That(shifted.Reason, Does.Contain("principal point (16, 15)"));
        }

        [Test]
        public void ImageNamesSortInPoseOrder()
        {
            Assert.That(Llff.ImageName(7, 9), Is.EqualTo("0007.png"));
            Assert.That(Llff.ImageName(12345, 20000), Is.EqualTo("12345.png"));
            var names = Enumerable.Range(0, 10001).Select(i => Llff.ImageName(i, 10001)).ToList();
            Assert.That(names.OrderBy(n => n, StringComparer.Ordinal), Is.EqualTo(names));
        }

        [Test]
        public void AnAnalyticDatasetReadsBackThroughTheLoaderWithExactPosesFocalBoundsAndPixels()
        {
            using (var temp = new TempFolder())
            {
                var truth = new AnalyticDepthBounds();
                const int w = 40, h = 30;
                var folder = AnalyticDataset.Write(temp.Path, "llff", new AnalyticDataset.Options
                {
                    Width = w, Height = h, Train = 6, Val = 1, Test = 2,
                    OutputRays = (view, scene, rays) => truth.Record(view, scene, rays, w, h),
                });
                var result = DatasetConverter.Convert(folder, ExportTarget.Llff);
                var outDir = Path.Combine(folder, "llff");
                Assert.That(result.MainFile, Is.EqualTo(Path.Combine(outDir, "poses_bounds.npy")));
                Assert.That(result.Warnings.Select(p => p.Field), Has.Member("splits.json"), "the hold-out convention is said");

                var views = Load(outDir);
                var splits = JObject.Parse(File.ReadAllText(Path.Combine(outDir, "splits.json")));
                var sources = splits["source"].Select(s => (string)s).ToList();
                Assert.That(views.Select(v => v.Name), Is.EqualTo(splits["images"].Select(s => (string)s)));
                Assert.That(sources.Count, Is.EqualTo(9), "every frame of every split");
                Assert.That(splits["i_test"].Select(v => (int)v), Is.EqualTo(new[] { 7, 8 }));
                Assert.That(splits["i_val"].Select(v => (int)v), Is.EqualTo(new[] { 6 }));
                Assert.That((string)splits["background"], Is.EqualTo("white"));

                var step = ExportScene.DefaultDepthUnitScale;
                for (var n = 0; n < views.Count; n++)
                {
                    var v = views[n];
                    var split = sources[n].Split('/')[0];
                    var json = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_" + split + ".json")));
                    var frame = json["frames"].Single(f => ((string)f["file_path"]).TrimStart('.', '/') + ".png" == sources[n]);
                    var expected = FromJson(frame["transform_matrix"]);
                    for (var r = 0; r < 3; r++)
                        for (var c = 0; c < 4; c++)
                            Assert.That(v.CameraToWorld[r, c], Is.EqualTo(expected[r, c]).Within(1e-6), sources[n] + " [" + r + ", " + c + "]");
                    // NeRF's focal from camera_angle_x (bmild/nerf load_blender.py: .5 * W / tan(.5 * camera_angle_x)).
                    var focal = 0.5 * w / Math.Tan(0.5 * (double)json["camera_angle_x"]);
                    Assert.That(v.Focal, Is.EqualTo(focal).Within(1e-9 * focal));
                    Assert.That((v.H, v.W), Is.EqualTo(((double)h, (double)w)));
                    Assert.That((v.Image.Height, v.Image.Width), Is.EqualTo((h, w)), "line 102 takes H and W from the image");
                    var (near, far) = truth.Of(sources[n]);
                    Assert.That(v.Near, Is.EqualTo(near).Within(step), sources[n] + " near");
                    Assert.That(v.Far, Is.EqualTo(far).Within(step), sources[n] + " far");

                    // Line 114 keeps [..., :3]: the file is RGB, the source's straight-alpha RGBA over white, rounded.
                    Assert.That(v.Image.ColorType, Is.EqualTo(PngInfo.ColorTypeRgb));
                    var source = PngReader.Read(Path.Combine(folder, sources[n]));
                    Assert.That(source.ColorType, Is.EqualTo(PngInfo.ColorTypeRgba));
                    var expectedRgb = new byte[w * h * 3];
                    for (var p = 0; p < w * h; p++)
                        for (var c = 0; c < 3; c++)
                        {
                            var a = source.Samples[4 * p + 3];
                            expectedRgb[3 * p + c] = (byte)Math.Round((source.Samples[4 * p + c] * a + 255.0 * (255 - a)) / 255);
                        }
                    Assert.That(v.Image.Samples, Is.EqualTo(expectedRgb), sources[n] + " pixels");
                }
                Assert.That(views.Select(v => v.Far - v.Near).Min(), Is.GreaterThan(0));
                Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Llff), "never overwrites");
            }
        }

        [Test]
        public void ADatasetWithoutDepthIsRefusedInOneLineNamingDepth()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                var settings = new DatasetSettings { Seed = 3, Width = 16, Height = 12 };
                TestDatasets.FromPlan(folder, CapturePlan.Build(settings, new PlanTarget(Vector3d.Zero, 0.5)));
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Llff));
                Assert.That(e.Problems.Count, Is.EqualTo(1));
                Assert.That(e.Problems[0].Field, Is.EqualTo("depth"));
                Assert.That(e.Problems[0].Reason, Does.Contain("poses_bounds.npy"));
                Assert.That(e.Problems[0].Fix, Does.Contain("depth \"png\""));
                Assert.That(Directory.Exists(Path.Combine(folder, "llff")), Is.False, "nothing is left behind");
            }
        }

        [Test]
        public void AViewThatSeesNoSurfaceTakesTheOtherViewsBounds()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "empty", new AnalyticDataset.Options { Width = 16, Height = 12, Train = 3, Val = 1, Test = 1, Supersampling = 1 });
                // Blank train/r_1's depth: no surface in that view.
                var depth = Path.Combine(folder, "train", "r_1_depth_0000.png");
                File.Delete(depth);
                File.WriteAllBytes(depth, PngWriter.EncodeGray16(new ushort[16 * 12], 16, 12));
                var warnings = new List<ValidationProblem>();
                var scene = BlenderDatasetLoader.Load(folder, warnings);
                var bounds = DepthBounds.Of(scene, scene.Frames, "llff", warnings);
                Assert.That(warnings.Select(p => p.Value), Has.Member("1 views"));
                var others = bounds.Where((b, i) => i != 1).ToList();
                Assert.That(bounds[1].Near, Is.EqualTo(others.Min(b => b.Near)));
                Assert.That(bounds[1].Far, Is.EqualTo(others.Max(b => b.Far)));
                Assert.That(others.Select(b => b.Far - b.Near).Distinct().Count(), Is.GreaterThan(1), "the views' own bounds differ");
            }
        }
    }
}
