using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// convert --to neus read back through NeuS's loader (Totoro97/NeuS 6e0a230 models/dataset.py): the sorted
    /// image/*.png and mask/*.png (lines 53–57), world_mat_i and scale_mat_i cast to float32 (60, 65),
    /// P = world_mat @ scale_mat (71–72), load_K_Rt_from_P (13–34: cv.decomposeProjectionMatrix → K / K[2, 2],
    /// pose = [Rᵀ | centre]) and its rays through integer pixels (116–124), against the dataset's transform_matrix,
    /// NeRF's ray through each pixel centre and the analytic target's bounding sphere.
    /// </summary>
    public class NeusExportTests
    {
        /// <summary>
        /// cv.decomposeProjectionMatrix of P = [M | p4]: M = K·R, K upper triangular with a positive diagonal, R a rotation
        /// (an RQ decomposition, here by Gram–Schmidt from the last row), and the homogeneous camera centre t with
        /// P·t = 0, whose t[:3] / t[3] is −M⁻¹·p4. Returns K / K[2, 2] and the pose [Rᵀ | centre] as load_K_Rt_from_P does.
        /// </summary>
        static (double[,] K, double[,] Pose) LoadKRtFromP(double[,] p)
        {
            Vector3d Row(int r) => new Vector3d(p[r, 0], p[r, 1], p[r, 2]);
            var k = new double[3, 3];
            var r3 = Row(2);
            k[2, 2] = r3.Length;
            r3 /= k[2, 2];
            k[1, 2] = Vector3d.Dot(Row(1), r3);
            var r2 = Row(1) - k[1, 2] * r3;
            k[1, 1] = r2.Length;
            r2 /= k[1, 1];
            k[0, 2] = Vector3d.Dot(Row(0), r3);
            k[0, 1] = Vector3d.Dot(Row(0), r2);
            var r1 = Row(0) - k[0, 1] * r2 - k[0, 2] * r3;
            k[0, 0] = r1.Length;
            r1 /= k[0, 0];
            var m = Matrix4x4d.FromRowMajor(p[0, 0], p[0, 1], p[0, 2], 0, p[1, 0], p[1, 1], p[1, 2], 0, p[2, 0], p[2, 1], p[2, 2], 0, 0, 0, 0, 1);
            var centre = -Inverse3(m).MultiplyVector(new Vector3d(p[0, 3], p[1, 3], p[2, 3]));
            var scale = k[2, 2];
            for (var a = 0; a < 3; a++) for (var b = 0; b < 3; b++) k[a, b] /= scale;
            var rows = new[] { r1, r2, r3 };
            var pose = new double[3, 4];
            for (var a = 0; a < 3; a++)
            {
                for (var b = 0; b < 3; b++) pose[a, b] = Get(rows[b], a); // Rᵀ
                pose[a, 3] = Get(centre, a);
            }
            return (k, pose);
        }

        static double Get(Vector3d v, int i) => i == 0 ? v.X : i == 1 ? v.Y : v.Z;

        static Matrix4x4d Inverse3(Matrix4x4d m)
        {
            double a = m[0, 0], b = m[0, 1], c = m[0, 2], d = m[1, 0], e = m[1, 1], f = m[1, 2], g = m[2, 0], h = m[2, 1], i = m[2, 2];
            var det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
            return Matrix4x4d.FromRowMajor(
                (e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det, 0,
                (f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det, 0,
                (d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det, 0,
                0, 0, 0, 1);
        }

        /// <summary>An npz entry as a 4 × 4 matrix, optionally rounded to float32 as the loader's <c>.astype(np.float32)</c>.</summary>
        static double[,] Mat(Dictionary<string, byte[]> npz, string key, bool float32)
        {
            var (rows, columns, values) = NumpyFloat64Tests.ParseFloat64(npz[key]);
            Assert.That((rows, columns), Is.EqualTo((4, 4)), key);
            var m = new double[4, 4];
            for (var r = 0; r < 4; r++) for (var c = 0; c < 4; c++) m[r, c] = float32 ? (float)values[4 * r + c] : values[4 * r + c];
            return m;
        }

        static double[,] Multiply(double[,] a, double[,] b)
        {
            var m = new double[4, 4];
            for (var r = 0; r < 4; r++) for (var c = 0; c < 4; c++) for (var k = 0; k < 4; k++) m[r, c] += a[r, k] * b[k, c];
            return m;
        }

        static Matrix4x4d FromJson(JToken rows) => Matrix4x4d.FromRows(rows.Select(r => r.Select(v => (double)v).ToArray()).ToArray());

        [Test]
        public void WorldMatProjectsAPixelCentreToItsIntegerIndex()
        {
            // A camera at the origin looking along −Z (OpenGL: identity c2w), 40 × 30, vertical fov 60°.
            var k = CameraIntrinsics.FromVerticalFov(60, 40, 30);
            var world = Neus.WorldMat(Matrix4x4d.Identity, k);
            var f = 15 / Math.Tan(Math.PI / 6);
            // The point seen through our pixel (3, 7)'s centre, (3.5, 7.5): x = (3.5 − 20)/f, y = −(7.5 − 15)/f at z = −1.
            var p = new Vector3d((3.5 - 20) / f, -(7.5 - 15) / f, -1);
            var q = world.MultiplyPoint(p); // rows 0–2 of K·[R | t]·(p, 1); the last row of K is (0, 0, 1, 0)
            Assert.That(q.X / q.Z, Is.EqualTo(3).Within(1e-12));
            Assert.That(q.Y / q.Z, Is.EqualTo(7).Within(1e-12));
            Assert.That(Neus.K(k)[0, 2], Is.EqualTo(19.5));
            Assert.That(Neus.K(k)[1, 2], Is.EqualTo(14.5));
        }

        [Test]
        public void FileNamesSortInCameraOrder()
        {
            Assert.That(Neus.FileName(7, 49), Is.EqualTo("007.png"));
            Assert.That(Neus.FileName(999, 1001), Is.EqualTo("0999.png"));
            var names = Enumerable.Range(0, 1200).Select(i => Neus.FileName(i, 1200)).ToList();
            Assert.That(names.OrderBy(n => n, StringComparer.Ordinal), Is.EqualTo(names));
        }

        [Test]
        public void AnAnalyticDatasetReadsBackThroughTheLoaderWithExactCamerasSphereAndPixels()
        {
            using (var temp = new TempFolder())
            {
                const int w = 40, h = 30;
                var folder = AnalyticDataset.Write(temp.Path, "neus", new AnalyticDataset.Options { Width = w, Height = h, Train = 5, Val = 1, Test = 2 });
                var result = DatasetConverter.Convert(folder, ExportTarget.Neus);
                var outDir = Path.Combine(folder, "neus");
                Assert.That(result.MainFile, Is.EqualTo(Path.Combine(outDir, "cameras_sphere.npz")));

                // Lines 53–57: sorted glob; n_images from the images.
                var images = Directory.GetFiles(Path.Combine(outDir, "image"), "*.png").OrderBy(f => f, StringComparer.Ordinal).ToList();
                var masks = Directory.GetFiles(Path.Combine(outDir, "mask"), "*.png").OrderBy(f => f, StringComparer.Ordinal).ToList();
                Assert.That(images.Count, Is.EqualTo(8));
                Assert.That(masks.Select(Path.GetFileName), Is.EqualTo(images.Select(Path.GetFileName)));
                var npz = NumpyFloat64Tests.ReadNpz(result.MainFile);
                var splits = JObject.Parse(File.ReadAllText(Path.Combine(outDir, "splits.json")));
                var sources = splits["source"].Select(s => (string)s).ToList();
                Assert.That(splits["i_test"].Select(v => (int)v), Is.EqualTo(new[] { 6, 7 }));

                // The target's bounding sphere: AnalyticDataset's target, radius 1.2, recentred on the output origin at
                // scale 1 (the default normalisation, recorded in dataset_config.json).
                var recorded = JObject.Parse(File.ReadAllText(Path.Combine(folder, "dataset_config.json")));
                Assert.That((double)recorded["scene_normalisation"]["scale"], Is.EqualTo(1));
                Assert.That(recorded["scene_normalisation"]["centre"].Select(v => (double)v), Is.EqualTo(new[] { 1.0, 3, 2 }), "Unity (1, 2, 3) as (x, z, y)");
                var scale = Mat(npz, "scale_mat_0", false);
                Assert.That(new[] { scale[0, 0], scale[1, 1], scale[2, 2], scale[0, 3], scale[1, 3], scale[2, 3] }, Is.EqualTo(new[] { 1.2, 1.2, 1.2, 0, 0, 0 }).Within(1e-12));
                Assert.That((double)recorded["target"]["boundingRadius"], Is.EqualTo(1.2), "the recorded bounding radius");

                for (var n = 0; n < images.Count; n++)
                {
                    var split = sources[n].Split('/')[0];
                    var json = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_" + split + ".json")));
                    var frame = json["frames"].Single(fr => ((string)fr["file_path"]).TrimStart('.', '/') + ".png" == sources[n]);
                    var c2w = FromJson(frame["transform_matrix"]);
                    var angle = (double)json["camera_angle_x"];
                    var focal = 0.5 * w / Math.Tan(0.5 * angle);
                    // Expected in NeuS's unit-sphere frame: centre (C − c)/r; rotation the OpenCV axes x, −y, −z of the OpenGL c2w.
                    var centre = (c2w.Translation - Vector3d.Zero) / 1.2;
                    var axes = new[] { c2w.Column(0), -c2w.Column(1), -c2w.Column(2) };

                    foreach (var float32 in new[] { false, true })
                    {
                        var p = Multiply(Mat(npz, "world_mat_" + n, float32), Mat(npz, "scale_mat_" + n, float32));
                        var (k, pose) = LoadKRtFromP(p);
                        // The file's values are exact (1e-9); the loader's float32 cast costs it about 1e-7 relative.
                        var tolerance = float32 ? 1e-6 : 1e-9;
                        Assert.That(k[0, 0], Is.EqualTo(focal).Within(tolerance * focal), "fx");
                        Assert.That(k[1, 1], Is.EqualTo(focal).Within(tolerance * focal), "fy");
                        Assert.That(k[0, 2], Is.EqualTo(w / 2.0 - 0.5).Within(tolerance * w), "cx = W/2 − ½");
                        Assert.That(k[1, 2], Is.EqualTo(h / 2.0 - 0.5).Within(tolerance * h), "cy = H/2 − ½");
                        Assert.That(k[0, 1], Is.EqualTo(0).Within(tolerance * focal), "no skew");
                        for (var a = 0; a < 3; a++)
                        {
                            Assert.That(pose[a, 3], Is.EqualTo(Get(centre, a)).Within(tolerance), sources[n] + " centre");
                            for (var b = 0; b < 3; b++) Assert.That(pose[a, b], Is.EqualTo(Get(axes[b], a)).Within(tolerance), sources[n] + " R");
                        }
                        if (float32) continue;
                        // Lines 120–124: the ray through integer pixel (x, y) is NeRF's ray through our pixel centre (x + ½, y + ½).
                        foreach (var (x, y) in new[] { (0, 0), (39, 0), (17, 11), (39, 29) })
                        {
                            var pix = new Vector3d((x - k[0, 2]) / k[0, 0], (y - k[1, 2]) / k[1, 1], 1); // K⁻¹·(x, y, 1) with no skew
                            pix /= pix.Length;
                            var d = new Vector3d(
                                pose[0, 0] * pix.X + pose[0, 1] * pix.Y + pose[0, 2] * pix.Z,
                                pose[1, 0] * pix.X + pose[1, 1] * pix.Y + pose[1, 2] * pix.Z,
                                pose[2, 0] * pix.X + pose[2, 1] * pix.Y + pose[2, 2] * pix.Z);
                            NerfRays.Ray(c2w.ToRows(), angle, w, h, x + 0.5, y + 0.5, out var o, out var nd);
                            var nerf = new Vector3d(nd[0], nd[1], nd[2]);
                            nerf /= nerf.Length;
                            Assert.That(Vector3d.Distance(d, nerf), Is.LessThan(1e-9), "ray (" + x + ", " + y + ")");
                            Assert.That(Vector3d.Distance(new Vector3d(pose[0, 3], pose[1, 3], pose[2, 3]) * 1.2 + Vector3d.Zero, new Vector3d(o[0], o[1], o[2])), Is.LessThan(1e-9));
                        }
                    }

                    // cv.imread: 3 channels; the file is the source's straight-alpha RGBA over white (the protocol background).
                    var image = PngReader.Read(images[n]);
                    var source = PngReader.Read(Path.Combine(folder, sources[n]));
                    Assert.That(image.ColorType, Is.EqualTo(PngInfo.ColorTypeRgb));
                    var expected = new byte[w * h * 3];
                    for (var q = 0; q < w * h; q++)
                        for (var c = 0; c < 3; c++)
                        {
                            var a = source.Samples[4 * q + 3];
                            expected[3 * q + c] = (byte)Math.Round((source.Samples[4 * q + c] * a + 255.0 * (255 - a)) / 255);
                        }
                    Assert.That(image.Samples, Is.EqualTo(expected), sources[n] + " pixels");
                    // Masks: the dataset's mask (255 on the target), kept where at least half on; NeuS keeps value / 256 > 0.5.
                    var mask = PngReader.Read(masks[n]);
                    var sourceMask = PngReader.Read(Path.Combine(folder, (string)frame["mask_path"] ?? sources[n].Replace(".png", "_mask.png")));
                    Assert.That(mask.ColorType, Is.EqualTo(PngInfo.ColorTypeGray));
                    Assert.That(mask.Samples, Is.EqualTo(sourceMask.Samples.Select(v => v >= 128 ? (byte)255 : (byte)0)));
                    Assert.That(mask.Samples.Count(v => v == 255), Is.GreaterThan(0).And.LessThan(w * h));
                }
                Assert.That(result.Warnings.Select(p => p.Field), Has.Member("splits.json"));
                Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Neus), "never overwrites");
            }
        }

        [Test]
        public void ADatasetThatDoesNotRecordItsTargetIsRefusedInOneLine()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                TestDatasets.FromPlan(folder, CapturePlan.Build(new DatasetSettings { Seed = 3, Width = 16, Height = 12 }, new PlanTarget(Vector3d.Zero, 0.5)));
                var configPath = Path.Combine(folder, DatasetLayout.ConfigFileName);
                var config = JObject.Parse(File.ReadAllText(configPath));
                Assert.That(config["target"], Is.Not.Null, "the capture records it");
                config.Remove("target");
                File.WriteAllText(configPath, config.ToString());
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Neus));
                Assert.That(e.Problems.Select(p => p.Field), Is.EqualTo(new[] { "dataset_config.json: target" }));
                Assert.That(e.Problems[0].Reason, Does.Contain("scale_mat_i"));
                Assert.That(Directory.Exists(Path.Combine(folder, "neus")), Is.False);
            }
        }
    }
}
