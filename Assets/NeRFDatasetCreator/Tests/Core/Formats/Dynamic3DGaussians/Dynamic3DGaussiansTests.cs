using System;
using System.IO;
using System.IO.Compression;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// convert --to dynamic3dgs read back through Dynamic 3D Gaussians' own formulas (JonathonLuiten/Dynamic3DGaussians
    /// 7dbbd4d): train.py get_dataset (lines 15–26), initialize_params (37–55), helpers.py setup_camera (8–31) with
    /// 3DGS's ndc2Pix, against hand-derived poses and NeRF's ray formula.
    /// </summary>
    public class Dynamic3DGaussiansTests
    {
        /// <summary>helpers.py:13–17 and the rasterizer: q = P·w2c·p (row-vector form there), ndc = q.xy / q.w, pixel = ((ndc + 1)·S − 1) / 2.</summary>
        static double[] LoaderPixel(double[][] w2c, double[][] k, int w, int h, Vector3d p, double near = 1.0, double far = 100)
        {
            double fx = k[0][0], fy = k[1][1], cx = k[0][2], cy = k[1][2];
            var proj = new[]
            {
                new[] { 2 * fx / w, 0.0, -(w - 2 * cx) / w, 0.0 },
                new[] { 0.0, 2 * fy / h, -(h - 2 * cy) / h, 0.0 },
                new[] { 0.0, 0.0, far / (far - near), -(far * near) / (far - near) },
                new[] { 0.0, 0.0, 1.0, 0.0 },
            };
            var v = new[] { p.X, p.Y, p.Z, 1 };
            var cam = new double[4];
            var q = new double[4];
            for (var r = 0; r < 4; r++) for (var c = 0; c < 4; c++) cam[r] += w2c[r][c] * v[c];
            for (var r = 0; r < 4; r++) for (var c = 0; c < 4; c++) q[r] += proj[r][c] * cam[c];
            return new[] { ((q[0] / q[3] + 1) * w - 1) / 2, ((q[1] / q[3] + 1) * h - 1) / 2 };
        }

        static void AssertClose(Matrix4x4d expected, Matrix4x4d actual, double tolerance)
        {
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++)
                    Assert.That(actual[r, c], Is.EqualTo(expected[r, c]).Within(tolerance), "[" + r + ", " + c + "]");
        }

        static void AssertClose(Vector3d expected, Vector3d actual, double tolerance) =>
            PoseAssert.Close(new[] { actual.X, actual.Y, actual.Z }, new[] { expected.X, expected.Y, expected.Z }, tolerance, "point");

        static Matrix4x4d FromJson(JToken rows) => Matrix4x4d.FromRows(rows.Select(r => r.Select(v => (double)v).ToArray()).ToArray());

        [Test]
        public void WorldToCameraOfACameraOnMinusYLookingAtTheOrigin()
        {
            // Blender world, OpenGL axes: at (0, −4, 0), looking along +Y (its −Z), up +Z.
            var c2w = Matrix4x4d.FromRowMajor(
                1, 0, 0, 0,
                0, 0, -1, -4,
                0, 1, 0, 0,
                0, 0, 0, 1);
            // Floor at z = −1: p_d = (x, −(z + 1), y). Centre (0, −4, 0) → (0, −1, −4); OpenCV axes x = (1, 0, 0)_b → (1, 0, 0),
            // y = −Y_gl = (0, 0, −1)_b → (0, 1, 0), z = −Z_gl = (0, 1, 0)_b → (0, 0, 1): c2w_cv = [I | (0, −1, −4)], w2c = [I | (0, 1, 4)].
            var w2c = Dynamic3DGaussians.WorldToCamera(c2w, Dynamic3DGaussians.World(-1));
            var expected = Matrix4x4d.FromRowMajor(
                1, 0, 0, 0,
                0, 1, 0, 1,
                0, 0, 1, 4,
                0, 0, 0, 1);
            AssertClose(expected, w2c, 1e-12);

            // The target's top (0, 0, 0.5)_b is above the image centre: y < cy in OpenCV pixels.
            var k = Dynamic3DGaussians.K(CameraIntrinsics.FromVerticalFov(60, 40, 30));
            var top = LoaderPixel(w2c.ToRows(), k, 40, 30, Dynamic3DGaussians.World(-1).MultiplyPoint(new Vector3d(0, 0, 0.5)));
            var centre = LoaderPixel(w2c.ToRows(), k, 40, 30, Dynamic3DGaussians.World(-1).MultiplyPoint(Vector3d.Zero));
            Assert.That(centre[0], Is.EqualTo(19.5).Within(1e-9));
            Assert.That(centre[1], Is.EqualTo(14.5).Within(1e-9));
            Assert.That(top[1], Is.EqualTo(14.5 - k[1][1] * 0.5 / 4).Within(1e-9));
        }

        [Test]
        public void KHoldsTheFocalLengthsAndPrincipalPoint()
        {
            // fl = (H/2) / tan(vfov/2): 15 / tan(30°) for 60° over 30 rows.
            var k = Dynamic3DGaussians.K(CameraIntrinsics.FromVerticalFov(60, 40, 30));
            var f = 15 / Math.Tan(Math.PI / 6);
            Assert.That(k[0], Is.EqualTo(new[] { f, 0, 20 }).Within(1e-9));
            Assert.That(k[1], Is.EqualTo(new[] { 0, f, 15 }).Within(1e-9));
            Assert.That(k[2], Is.EqualTo(new[] { 0.0, 0, 1 }));
        }

        [Test]
        public void PixelCentresOfTheLegoCamerasProjectToTheirPixelsThroughTheLoadersCamera()
        {
            // NeRF's ray through the centre of pixel (i, j) — at i + ½, j + ½ — lands on pixel (i, j) in 3DGS's convention.
            var json = JObject.Parse(File.ReadAllText(Fixtures.LegoTrainPath));
            var angle = (double)json["camera_angle_x"];
            var intrinsics = CameraIntrinsics.FromVerticalFov(CameraIntrinsics.VerticalFovDegreesFromHorizontal(angle, 800, 800), 800, 800);
            var world = Dynamic3DGaussians.World(-2);
            foreach (var frame in ((JArray)json["frames"]).Take(5))
            {
                var c2w = FromJson(frame["transform_matrix"]);
                var w2c = Dynamic3DGaussians.WorldToCamera(c2w, world);
                Assert.That(w2c.Determinant3x3, Is.EqualTo(1).Within(1e-6)); // lego's matrices are float32-exact only
                // train.py:55 and helpers.py:11 take the camera centre as inverse(w2c)[:3, 3].
                AssertClose(world.MultiplyPoint(c2w.Translation), w2c.InverseRigid().Translation, 1e-5);
                foreach (var (i, j) in new[] { (0, 0), (123, 456), (799, 10), (400, 799) })
                {
                    NerfRays.Ray(c2w.ToRows(), angle, 800, 800, i + 0.5, j + 0.5, out var o, out var d);
                    var p = new Vector3d(o[0] + 2.5 * d[0], o[1] + 2.5 * d[1], o[2] + 2.5 * d[2]);
                    var pixel = LoaderPixel(w2c.ToRows(), Dynamic3DGaussians.K(intrinsics), 800, 800, world.MultiplyPoint(p));
                    // 1e-3 px: lego's rotations are orthonormal to float32 only (a half-pixel error would be 0.5).
                    Assert.That(pixel[0], Is.EqualTo(i).Within(1e-3));
                    Assert.That(pixel[1], Is.EqualTo(j).Within(1e-3));
                }
            }
        }

        [Test]
        public void WorldIsARotationThatPutsEverythingAboveTheFloorAtNonPositiveY()
        {
            var world = Dynamic3DGaussians.World(Dynamic3DGaussians.FloorUnder(1.5));
            Assert.That(world.Determinant3x3, Is.EqualTo(1));
            // train.py:114: clamp(fg_pts[:, 1], min=0) — zero for y ≤ 0. Output +Z (up) becomes −Y (up in Panoptic's world).
            Assert.That(world.MultiplyPoint(new Vector3d(0.3, -1.5, -1.5)).Y, Is.EqualTo(0));
            Assert.That(world.MultiplyPoint(new Vector3d(0, 0, 1.5)).Y, Is.EqualTo(-3));
            Assert.That(world.MultiplyVector(Vector3d.UnitZ), Is.EqualTo(new Vector3d(0, -1, 0)));
        }

        [Test]
        public void ImagesAreRgbOverBlackAndSegmentationIsZeroOrOne()
        {
            var rgba = new PngImage(3, 1, 8, PngInfo.ColorTypeRgba, new byte[] { 200, 100, 50, 128, 10, 20, 30, 255, 255, 255, 255, 127 });
            // c·a/255 rounded: 200·128/255 = 100.4, 100·128/255 = 50.2, 50·128/255 = 25.1; 255·127/255 = 127.
            Assert.That(Dynamic3DGaussians.RgbOverBlack(rgba), Is.EqualTo(new byte[] { 100, 50, 25, 10, 20, 30, 127, 127, 127 }));
            Assert.That(Dynamic3DGaussians.Segmentation(rgba), Is.EqualTo(new byte[] { 1, 1, 0 }));
            var mask = new PngImage(3, 1, 8, PngInfo.ColorTypeGray, new byte[] { 255, 0, 128 });
            Assert.That(Dynamic3DGaussians.Segmentation(mask), Is.EqualTo(new byte[] { 1, 0, 1 }));
        }

        static DatasetSettings MultiView(int train, int test, int steps)
        {
            var s = new DatasetSettings { Seed = 3, Width = 16, Height = 12 };
            s.Train.Count = train;
            s.Val.Count = 1;
            s.Test.Count = test;
            s.Time.Mode = TimeMode.MultiView;
            s.Time.StartSeconds = 0;
            s.Time.EndSeconds = 2;
            s.Time.Steps = steps;
            return s;
        }

        /// <summary>A multi-view dataset on disk with a recorded points3d.ply of two points.</summary>
        static CloudPoint[] Dataset(string folder, DatasetSettings settings)
        {
            TestDatasets.FromPlan(folder, CapturePlan.Build(settings, new PlanTarget(Vector3d.Zero, 0.5)));
            var cloud = new[]
            {
                new CloudPoint(new Vector3d(0.1, 0.2, 0.3), Vector3d.UnitZ, 255, 0, 51),
                new CloudPoint(new Vector3d(0, 0, -0.5), Vector3d.UnitZ, 0, 255, 0),
            };
            var ply = Path.Combine(folder, PointCloudOwnership.FileName);
            PlyWriter.Write(ply, cloud);
            var configPath = Path.Combine(folder, DatasetLayout.ConfigFileName);
            var config = JObject.Parse(File.ReadAllText(configPath));
            config[PointCloudRecord.Key] = PointCloudRecord.Of(ply, PointCloudOwnership.FileName, cloud.Length).ToJson();
            File.WriteAllText(configPath, config.ToString());
            return cloud;
        }

        static float[] ReadNpz(string path, out string header)
        {
            using (var zip = new ZipArchive(File.OpenRead(path), ZipArchiveMode.Read))
            using (var s = zip.GetEntry("data.npy").Open())
            using (var copy = new MemoryStream())
            {
                s.CopyTo(copy);
                var (h, values) = NumpyFilesTests.ParseNpy(copy.ToArray());
                header = h;
                return values;
            }
        }

        [Test]
        public void AMultiViewCaptureConvertsToTheLayoutTrainPyReads()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                var settings = MultiView(3, 2, 4);
                var cloud = Dataset(folder, settings);
                // Train frame r_(k·C + c) is camera c at step k: give camera 2 at step 1 known pixels.
                var pixels = new byte[16 * 12 * 4];
                pixels[0] = 200; pixels[1] = 100; pixels[2] = 50; pixels[3] = 128;
                File.WriteAllBytes(Path.Combine(folder, "train", "r_5.png"), PngWriter.Encode(pixels, 16, 12, PngPixelFormat.Rgba8));

                var result = DatasetConverter.Convert(folder, ExportTarget.Dynamic3dgs);
                var outDir = Path.Combine(folder, Dynamic3DGaussians.FolderName);
                Assert.That(result.MainFile, Is.EqualTo(Path.Combine(Path.GetFullPath(outDir), "train_meta.json")));
                Assert.That(result.Warnings.Select(w => w.Field), Has.Member("val"));

                // train.py:17–23: md['w'], md['h'], md['k'][t][c], md['w2c'][t][c], md['fn'][t][c]; ims/{fn}, seg/{fn}.
                var md = JObject.Parse(File.ReadAllText(result.MainFile));
                Assert.That((int)md["w"], Is.EqualTo(16));
                Assert.That((int)md["h"], Is.EqualTo(12));
                var train = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")))["frames"];
                var reach = DatasetTargetReach.Read(folder).Value;
                var world = Dynamic3DGaussians.World(-reach);
                foreach (var key in new[] { "k", "w2c", "fn", "cam_id" })
                {
                    Assert.That(md[key].Count(), Is.EqualTo(4), key + " per step");
                    Assert.That(md[key].All(step => step.Count() == 3), Is.True, key + " per camera");
                }
                for (var t = 0; t < 4; t++)
                    for (var c = 0; c < 3; c++)
                    {
                        var frame = train[t * 3 + c];
                        Assert.That((int)frame["time_step"], Is.EqualTo(t));
                        var c2w = FromJson(frame["transform_matrix"]);
                        AssertClose(world.MultiplyPoint(c2w.Translation), FromJson(md["w2c"][t][c]).InverseRigid().Translation, 1e-9);
                        Assert.That((string)md["fn"][t][c], Is.EqualTo(c + "/00000" + t + ".png"));
                        Assert.That((int)md["cam_id"][t][c], Is.EqualTo(c));
                        var k = md["k"][t][c];
                        Assert.That((double)k[0][2], Is.EqualTo(8));
                        Assert.That((double)k[1][2], Is.EqualTo(6));
                        var fn = (string)md["fn"][t][c];
                        var im = PngReader.Read(Path.Combine(outDir, "ims", fn));
                        Assert.That(im.ColorType, Is.EqualTo(PngInfo.ColorTypeRgb), "3 channels for the 3-channel loss");
                        var seg = PngReader.Read(Path.Combine(outDir, "seg", fn.Replace(".jpg", ".png")));
                        Assert.That(seg.ColorType, Is.EqualTo(PngInfo.ColorTypeGray));
                        Assert.That(seg.Samples.All(v => v <= 1), Is.True);
                    }
                var known = PngReader.Read(Path.Combine(outDir, "ims", "2", "000001.png"));
                Assert.That(known.Samples.Take(4), Is.EqualTo(new byte[] { 100, 50, 25, 0 }));
                Assert.That(PngReader.Read(Path.Combine(outDir, "seg", "2", "000001.png")).Samples.Take(2), Is.EqualTo(new byte[] { 1, 0 }));

                // The test split in the same form, its cameras numbered after train's.
                var testMeta = JObject.Parse(File.ReadAllText(Path.Combine(outDir, "test_meta.json")));
                Assert.That(testMeta["cam_id"][0].Select(v => (int)v), Is.EqualTo(new[] { 3, 4 }));
                Assert.That(File.Exists(Path.Combine(outDir, "ims", "4", "000003.png")), Is.True);

                // train.py:38–46: N × 7, seg in column 6, the target's points first (moved into the layout's world, colour / 255).
                var data = ReadNpz(Path.Combine(outDir, "init_pt_cld.npz"), out var header);
                var rows = cloud.Length + Dynamic3DGaussians.ShellPoints;
                Assert.That(header, Does.Contain("'shape': (" + rows + ", 7)"));
                Assert.That(data.Length, Is.EqualTo(rows * 7));
                var first = world.MultiplyPoint(cloud[0].Position);
                Assert.That(data.Take(7), Is.EqualTo(new[] { (float)first.X, (float)first.Y, (float)first.Z, 1f, 0f, 0.2f, 1f }).Within(1e-6));
                for (var r = 0; r < cloud.Length; r++) Assert.That(data[r * 7 + 1], Is.LessThanOrEqualTo(0), "no floor loss (train.py:114)");
                var background = Enumerable.Range(cloud.Length, Dynamic3DGaussians.ShellPoints).ToList();
                Assert.That(background.All(r => data[r * 7 + 6] == 0 && data[r * 7 + 3] == 0), Is.True, "black background points, seg 0");
                // The shell lies beyond every camera: each camera sees background points behind the target.
                var centres = Enumerable.Range(0, 3).Select(c => FromJson(md["w2c"][0][c]).InverseRigid().Translation).ToList();
                var mean = centres.Aggregate(Vector3d.Zero, (a, b) => a + b) / 3;
                var nearestShell = background.Min(r => Vector3d.Distance(new Vector3d(data[r * 7], data[r * 7 + 1], data[r * 7 + 2]), mean));
                Assert.That(nearestShell, Is.GreaterThan(centres.Max(c => Vector3d.Distance(c, mean)) * 1.99));

                Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Dynamic3dgs), "never overwrites");
            }
        }

        [Test]
        public void MonocularCapturesAreRefused()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                var settings = MultiView(3, 2, 3);
                settings.Time.Mode = TimeMode.Monocular;
                Dataset(folder, settings);
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Dynamic3dgs));
                Assert.That(e.Problems[0].Field, Is.EqualTo("dataset_config.json: time.mode"));
                Assert.That(Directory.Exists(Path.Combine(folder, Dynamic3DGaussians.FolderName)), Is.False, "nothing written");
            }
        }

        [Test]
        public void AStaticCaptureIsCalledStaticNotNone()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                var settings = MultiView(3, 2, 3);
                settings.Time.Mode = TimeMode.Static;
                Dataset(folder, settings);
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Dynamic3dgs));
                Assert.That(e.Problems[0].Field, Is.EqualTo("dataset_config.json: time.mode"));
                Assert.That(e.Problems[0].Value, Does.StartWith("\"static\""), "the mode's own name, as a config writes it; \"none\" is no mode");
                Assert.That(TimeModes.Name(TimeMode.Static), Is.EqualTo("static"));
            }
        }

        [Test]
        public void AMissingPointCloudNamesTheSettingThatWritesIt()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                TestDatasets.FromPlan(folder, CapturePlan.Build(MultiView(3, 2, 3), new PlanTarget(Vector3d.Zero, 0.5)));
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Dynamic3dgs));
                Assert.That(e.Problems[0].Field, Is.EqualTo("points3d.ply"));
                Assert.That(e.Problems[0].Fix, Does.Contain("pointCloudPoints"));
                // The key the fix names is one the settings reader knows (no "unknown key" warning for it).
                Assert.That(DatasetSettingsJson.Read("{ \"pointCloudPoints\": 100000 }").Warnings, Is.Empty);
            }
        }

        [Test]
        public void MoreThanFiftyTrainCamerasAreRefused()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                Dataset(folder, MultiView(51, 1, 2));
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Dynamic3dgs));
                Assert.That(e.Problems[0].Reason, Does.Contain("max_cams"));
            }
        }
    }
}
