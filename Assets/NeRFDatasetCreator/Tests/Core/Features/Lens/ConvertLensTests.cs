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
    /// <c>convert</c> of a distorted Blender-layout dataset: the lens keys of its transforms files (nerfstudio /
    /// instant-ngp names) reach every target that can hold them, exactly, and a world point projected through the
    /// written COLMAP camera with COLMAP's own formula (written out below, models.h OpenCVCameraModel /
    /// OpenCVFisheyeCameraModel) lands where our model puts it; targets that cannot hold the lens refuse.
    /// </summary>
    public class ConvertLensTests
    {
        const int Width = 64, Height = 48;
        const double AngleX = 1.1;

        // Awkward values on purpose: the files must carry them bit for bit.
        const double K1 = -0.12345678901234567, K2 = 0.031415926535897934, P1 = 0.00071828182845904523, P2 = -0.00041421356237309515;
        const double FK1 = 0.0273, FK2 = -0.0041, FK3 = 0.00062, FK4 = -0.000113;

        string _root;

        [SetUp]
        public void SetUp()
        {
            _root = Path.Combine(Path.GetTempPath(), "nerf-lens-tests-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_root);
        }

        [TearDown]
        public void TearDown()
        {
            if (Directory.Exists(_root)) Directory.Delete(_root, true);
        }

        /// <summary>Camera centres per split; each camera looks at the origin with +Z up (exactly orthonormal c2w).</summary>
        static readonly Dictionary<string, Vector3d[]> Centres = new Dictionary<string, Vector3d[]>
        {
            ["train"] = new[] { new Vector3d(4, 0, 1), new Vector3d(0, 4, 1.5), new Vector3d(-3, -2, 2) },
            ["val"] = new[] { new Vector3d(2, -3, 0.5) },
            ["test"] = new[] { new Vector3d(-1, 3, -1) },
        };

        static Matrix4x4d LookAtOrigin(Vector3d centre)
        {
            var z = centre.Normalized(); // OpenGL: the camera looks along −z
            var x = Vector3d.Cross(new Vector3d(0, 0, 1), z).Normalized();
            var y = Vector3d.Cross(z, x);
            return Matrix4x4d.FromRowMajor(new[]
            {
                x.X, y.X, z.X, centre.X,
                x.Y, y.Y, z.Y, centre.Y,
                x.Z, y.Z, z.Z, centre.Z,
                0, 0, 0, 1,
            });
        }

        /// <summary>Writes the dataset; <paramref name="lens"/> goes at the top of each split file (or per frame).</summary>
        void WriteDataset(JObject lens, bool perFrame = false, Action<string, int, JObject> editFrame = null)
        {
            var png = TestPng.Encode(Width, Height, 8, PngInfo.ColorTypeRgba);
            foreach (var split in Centres.Keys)
            {
                var frames = new JArray();
                for (var i = 0; i < Centres[split].Length; i++)
                {
                    var m = LookAtOrigin(Centres[split][i]);
                    var frame = new JObject
                    {
                        ["file_path"] = "./" + split + "/r_" + i,
                        ["transform_matrix"] = new JArray(Enumerable.Range(0, 4).Select(r => new JArray(m[r, 0], m[r, 1], m[r, 2], m[r, 3]))),
                    };
                    if (perFrame) foreach (var p in lens.Properties()) frame[p.Name] = p.Value.DeepClone();
                    editFrame?.Invoke(split, i, frame);
                    frames.Add(frame);
                    Directory.CreateDirectory(Path.Combine(_root, split));
                    File.WriteAllBytes(Path.Combine(_root, split, "r_" + i + ".png"), png);
                }
                var json = new JObject { ["camera_angle_x"] = AngleX };
                if (!perFrame) foreach (var p in lens.Properties()) json[p.Name] = p.Value.DeepClone();
                json["frames"] = frames;
                File.WriteAllText(Path.Combine(_root, "transforms_" + split + ".json"), json.ToString());
            }
        }

        static JObject OpenCvKeys(double k3 = 0)
        {
            var json = new JObject { ["camera_model"] = "OPENCV", ["k1"] = K1, ["k2"] = K2, ["p1"] = P1, ["p2"] = P2 };
            if (k3 != 0) json["k3"] = k3;
            return json;
        }

        static JObject FisheyeKeys() => new JObject { ["camera_model"] = "OPENCV_FISHEYE", ["k1"] = FK1, ["k2"] = FK2, ["k3"] = FK3, ["k4"] = FK4 };

        // ---- what lands in each file -------------------------------------------------------------------------------

        [Test]
        public void Nerfstudio_CarriesTheModelAndEveryCoefficientExactly()
        {
            WriteDataset(OpenCvKeys());
            var json = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_root, ExportTarget.Nerfstudio).MainFile));
            Assert.That((string)json["camera_model"], Is.EqualTo("OPENCV"));
            Assert.That(new[] { (double)json["k1"], (double)json["k2"], (double)json["k3"], (double)json["k4"], (double)json["p1"], (double)json["p2"] },
                Is.EqualTo(new[] { K1, K2, 0, 0, P1, P2 }));
        }

        [Test]
        public void Nerfstudio_CarriesAFisheye()
        {
            WriteDataset(FisheyeKeys());
            var json = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_root, ExportTarget.Nerfstudio).MainFile));
            Assert.That((string)json["camera_model"], Is.EqualTo("OPENCV_FISHEYE"));
            Assert.That(new[] { (double)json["k1"], (double)json["k2"], (double)json["k3"], (double)json["k4"] }, Is.EqualTo(new[] { FK1, FK2, FK3, FK4 }));
        }

        [Test]
        public void Ngp_CarriesOpenCv_AsK1K2P1P2()
        {
            WriteDataset(OpenCvKeys());
            var json = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_root, ExportTarget.Ngp).MainFile));
            Assert.That(new[] { (double)json["k1"], (double)json["k2"], (double)json["p1"], (double)json["p2"] }, Is.EqualTo(new[] { K1, K2, P1, P2 }));
            // nerf_loader.cu read_lens: k3 and p1 share lens.params[2]; no is_fisheye means OpenCV.
            Assert.That(json["k3"], Is.Null);
            Assert.That(json["is_fisheye"], Is.Null);
        }

        [Test]
        public void Ngp_CarriesAFisheye_WithIsFisheyeAndNoP1P2()
        {
            WriteDataset(FisheyeKeys());
            var json = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_root, ExportTarget.Ngp).MainFile));
            Assert.That((bool)json["is_fisheye"], Is.True);
            Assert.That(new[] { (double)json["k1"], (double)json["k2"], (double)json["k3"], (double)json["k4"] }, Is.EqualTo(new[] { FK1, FK2, FK3, FK4 }));
            // p1/p2 would overwrite k3/k4 in lens.params[2..3].
            Assert.That(json["p1"], Is.Null);
            Assert.That(json["p2"], Is.Null);
        }

        [Test]
        public void InstantNgpStyleKeys_AreRead_IsFisheyeWithoutCameraModel()
        {
            WriteDataset(new JObject { ["is_fisheye"] = true, ["k1"] = FK1, ["k2"] = FK2, ["k3"] = FK3, ["k4"] = FK4 });
            var json = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_root, ExportTarget.Nerfstudio).MainFile));
            Assert.That((string)json["camera_model"], Is.EqualTo("OPENCV_FISHEYE"));
            Assert.That((double)json["k4"], Is.EqualTo(FK4));
        }

        [Test]
        public void CoefficientsWithoutAModel_AreOpenCv()
        {
            // instant-ngp's default: k1…p2 without is_fisheye is its OpenCV lens.
            WriteDataset(new JObject { ["k1"] = K1, ["p2"] = P2 });
            var json = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_root, ExportTarget.Nerfstudio).MainFile));
            Assert.That((string)json["camera_model"], Is.EqualTo("OPENCV"));
            Assert.That(new[] { (double)json["k1"], (double)json["k2"], (double)json["p1"], (double)json["p2"] }, Is.EqualTo(new[] { K1, 0, 0, P2 }));
        }

        [Test]
        public void PerFrameKeys_ThatAgree_AreCarried()
        {
            WriteDataset(OpenCvKeys(), perFrame: true);
            var json = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_root, ExportTarget.Nerfstudio).MainFile));
            Assert.That((string)json["camera_model"], Is.EqualTo("OPENCV"));
            Assert.That((double)json["p1"], Is.EqualTo(P1));
        }

        [Test]
        public void ColmapText_WritesOpenCv_InModelsHOrder_AndWarnsFor3dgs()
        {
            WriteDataset(OpenCvKeys());
            var result = DatasetConverter.Convert(_root, ExportTarget.Colmap);
            var camera = CameraLine(File.ReadAllText(Path.Combine(result.OutputDirectory, "sparse", "0", "cameras.txt")));
            var f = 0.5 * Width / Math.Tan(0.5 * AngleX);
            Assert.That(camera.model, Is.EqualTo("OPENCV"));
            Assert.That(camera.width, Is.EqualTo(Width));
            Assert.That(camera.height, Is.EqualTo(Height));
            // fx fy cx cy k1 k2 p1 p2
            Assert.That(camera.p, Is.EqualTo(new[] { f, f, Width / 2.0, Height / 2.0, K1, K2, P1, P2 }).Within(1e-12));
            Assert.That(camera.p.Skip(4).ToArray(), Is.EqualTo(new[] { K1, K2, P1, P2 }), "the coefficients bit for bit");
            var warning = result.Warnings.Single(w => w.Field == "cameras");
            Assert.That(warning.Value, Does.Contain("OPENCV"));
            Assert.That(warning.Reason, Does.Contain("PINHOLE and SIMPLE_PINHOLE"));
        }

        [Test]
        public void ColmapText_WritesFullOpenCv_WhenK3IsSet()
        {
            const double k3 = 0.0123;
            WriteDataset(OpenCvKeys(k3));
            var result = DatasetConverter.Convert(_root, ExportTarget.Colmap);
            var camera = CameraLine(File.ReadAllText(Path.Combine(result.OutputDirectory, "sparse", "0", "cameras.txt")));
            Assert.That(camera.model, Is.EqualTo("FULL_OPENCV"));
            // fx fy cx cy k1 k2 p1 p2 k3 k4 k5 k6
            Assert.That(camera.p.Skip(4).ToArray(), Is.EqualTo(new[] { K1, K2, P1, P2, k3, 0, 0, 0 }));
        }

        [Test]
        public void ColmapBinary_WritesTheModelIdAndParameters()
        {
            WriteDataset(FisheyeKeys());
            var result = DatasetConverter.Convert(_root, ExportTarget.Colmap, colmap: new ColmapOptions(binary: true));
            using (var r = new BinaryReader(File.OpenRead(Path.Combine(result.OutputDirectory, "sparse", "0", "cameras.bin"))))
            {
                Assert.That(r.ReadUInt64(), Is.EqualTo(1UL));
                Assert.That(r.ReadUInt32(), Is.EqualTo(1U));
                Assert.That(r.ReadInt32(), Is.EqualTo(5), "OPENCV_FISHEYE's model id");
                Assert.That(r.ReadUInt64(), Is.EqualTo((ulong)Width));
                Assert.That(r.ReadUInt64(), Is.EqualTo((ulong)Height));
                var p = Enumerable.Range(0, 8).Select(_ => r.ReadDouble()).ToArray();
                Assert.That(p.Skip(4).ToArray(), Is.EqualTo(new[] { FK1, FK2, FK3, FK4 }));
                Assert.That(r.BaseStream.Position, Is.EqualTo(r.BaseStream.Length));
            }
        }

        // ---- the written COLMAP camera images a world point where our model does ----------------------------------

        [TestCase(false)]
        [TestCase(true)]
        public void AWorldPoint_ProjectsThroughTheWrittenColmapCamera_WhereOurModelPutsIt(bool fisheye)
        {
            WriteDataset(fisheye ? FisheyeKeys() : OpenCvKeys());
            var lens = fisheye ? LensDistortion.Fisheye(FK1, FK2, FK3, FK4) : LensDistortion.OpenCv(K1, K2, P1, P2);
            var result = DatasetConverter.Convert(_root, ExportTarget.Colmap);
            var sparse = Path.Combine(result.OutputDirectory, "sparse", "0");
            var camera = CameraLine(File.ReadAllText(Path.Combine(sparse, "cameras.txt")));
            var poses = ImagePoses(File.ReadAllText(Path.Combine(sparse, "images.txt")));
            var f = 0.5 * Width / Math.Tan(0.5 * AngleX);
            var points = new[] { new Vector3d(0.3, -0.2, 0.1), new Vector3d(-0.5, 0.4, -0.3), new Vector3d(0.6, 0.5, 0.45), new Vector3d(0, 0, 0) };
            var checkedCount = 0;
            foreach (var split in Centres.Keys)
                for (var i = 0; i < Centres[split].Length; i++)
                {
                    var (q, t) = poses[split + "_r_" + i + ".png"];
                    var c2w = LookAtOrigin(Centres[split][i]);
                    foreach (var point in points)
                    {
                        var colmap = ColmapProjects(camera.model, camera.p, q, t, point);
                        // Ours: the OpenGL camera frame from the source pose, OpenCV's normalised coordinates, the lens, the pinhole.
                        var d = point - c2w.Translation;
                        double xc = Vector3d.Dot(d, c2w.Column(0)), yc = Vector3d.Dot(d, c2w.Column(1)), zc = Vector3d.Dot(d, c2w.Column(2));
                        lens.Distort(xc / -zc, yc / zc, out var xd, out var yd);
                        var ours = (x: f * xd + Width / 2.0, y: f * yd + Height / 2.0);
                        Assert.That(colmap.x, Is.EqualTo(ours.x).Within(1e-9), split + " " + i);
                        Assert.That(colmap.y, Is.EqualTo(ours.y).Within(1e-9), split + " " + i);
                        checkedCount++;
                    }
                }
            Assert.That(checkedCount, Is.EqualTo(20));
        }

        /// <summary>
        /// COLMAP's ImgFromCam written out from models.h (not our code): X_cam = R(q)·X + t, (u, v) = (X/Z, Y/Z); OPENCV:
        /// r² = u² + v², radial = k1 r² + k2 r⁴, du = u·radial + 2 p1 u v + p2 (r² + 2u²), dv = v·radial + 2 p2 u v + p1 (r² + 2v²);
        /// OPENCV_FISHEYE: θ = atan r, (uu, vv) = (u, v)·θ/r (unscaled when r ≤ ε), θ² = uu² + vv², radial = k1 θ² + k2 θ⁴ + k3 θ⁶ + k4 θ⁸,
        /// du = uu·radial; then x = fx (·+d·) + cx.
        /// </summary>
        internal static (double x, double y) ColmapProjects(string model, double[] p, double[] q, double[] t, Vector3d X)
        {
            double w = q[0], a = q[1], b = q[2], c = q[3];
            var R = new[,]
            {
                { 1 - 2 * (b * b + c * c), 2 * (a * b - w * c), 2 * (a * c + w * b) },
                { 2 * (a * b + w * c), 1 - 2 * (a * a + c * c), 2 * (b * c - w * a) },
                { 2 * (a * c - w * b), 2 * (b * c + w * a), 1 - 2 * (a * a + b * b) },
            };
            var cam = new double[3];
            for (var i = 0; i < 3; i++) cam[i] = R[i, 0] * X.X + R[i, 1] * X.Y + R[i, 2] * X.Z + t[i];
            double u = cam[0] / cam[2], v = cam[1] / cam[2];
            if (model == "OPENCV")
            {
                double k1 = p[4], k2 = p[5], p1 = p[6], p2 = p[7];
                var r2 = u * u + v * v;
                var radial = k1 * r2 + k2 * r2 * r2;
                var du = u * radial + 2 * p1 * u * v + p2 * (r2 + 2 * u * u);
                var dv = v * radial + 2 * p2 * u * v + p1 * (r2 + 2 * v * v);
                return (p[0] * (u + du) + p[2], p[1] * (v + dv) + p[3]);
            }
            Assert.That(model, Is.EqualTo("OPENCV_FISHEYE"));
            {
                var r = Math.Sqrt(u * u + v * v);
                // FisheyeFromNormal scales only when r > machine epsilon (the optical axis stays put).
                var scale = r > 2.220446049250313e-16 ? Math.Atan(r) / r : 1;
                double uu = u * scale, vv = v * scale;
                var th2 = uu * uu + vv * vv;
                var radial = p[4] * th2 + p[5] * th2 * th2 + p[6] * th2 * th2 * th2 + p[7] * th2 * th2 * th2 * th2;
                return (p[0] * (uu + uu * radial) + p[2], p[1] * (vv + vv * radial) + p[3]);
            }
        }

        // ---- refusals ----------------------------------------------------------------------------------------------

        [Test]
        public void Dynamic3dgs_Refuses_NamingTheLens_AndWritesNothing()
        {
            WriteDataset(OpenCvKeys());
            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_root, ExportTarget.Dynamic3dgs));
            Assert.That(e.Problems[0].Field, Is.EqualTo("--to"));
            Assert.That(e.Problems[0].Reason, Does.Contain("OPENCV"));
            Assert.That(Directory.Exists(Path.Combine(_root, Dynamic3DGaussians.FolderName)), Is.False);
        }

        [Test]
        public void Ngp_RefusesK3_WhichItsOpenCvLensHasNot()
        {
            WriteDataset(OpenCvKeys(0.01));
            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_root, ExportTarget.Ngp));
            Assert.That(e.Problems[0].Field, Is.EqualTo("k3"));
            Assert.That(Directory.Exists(Path.Combine(_root, NgpWriter.FolderName)), Is.False);
        }

        [Test]
        public void Ngp_RefusesAnEquidistantFisheye_ItWouldReadAsAPinhole()
        {
            // read_lens switches to the fisheye only when some coefficient is non-zero.
            WriteDataset(new JObject { ["camera_model"] = "OPENCV_FISHEYE" });
            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_root, ExportTarget.Ngp));
            Assert.That(e.Problems[0].Field, Is.EqualTo("camera_model"));
            // nerfstudio and COLMAP hold it.
            var json = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_root, ExportTarget.Nerfstudio).MainFile));
            Assert.That((string)json["camera_model"], Is.EqualTo("OPENCV_FISHEYE"));
            Assert.That((double)json["k1"], Is.EqualTo(0));
        }

        [Test]
        public void APinholeDataset_KeepsItsPinholeFiles_WithoutLensKeys()
        {
            WriteDataset(new JObject());
            var nerfstudio = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_root, ExportTarget.Nerfstudio).MainFile));
            Assert.That((string)nerfstudio["camera_model"], Is.EqualTo("PINHOLE"));
            var ngp = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_root, ExportTarget.Ngp).MainFile));
            foreach (var key in TransformsLens.CoefficientKeys.Concat(new[] { "is_fisheye" }))
            {
                Assert.That(nerfstudio[key], Is.Null, key);
                Assert.That(ngp[key], Is.Null, key);
            }
        }

        [Test]
        public void ColmapDepths_AreRefused_For3dgsCannotReadTheCamera()
        {
            WriteDataset(OpenCvKeys());
            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_root, ExportTarget.Colmap, depths: true));
            Assert.That(e.Problems[0].Field, Is.EqualTo("--depths"));
            Assert.That(Directory.Exists(Path.Combine(_root, DatasetConverter.ColmapFolderName)), Is.False);
        }

        [Test]
        public void FramesWithDifferentLenses_AreRefused()
        {
            WriteDataset(OpenCvKeys(), perFrame: true, editFrame: (split, i, frame) => { if (split == "train" && i == 2) frame["k1"] = K1 / 2; });
            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_root, ExportTarget.Nerfstudio));
            Assert.That(e.Problems[0].Field, Does.Contain("frames[2]"));
            Assert.That(e.Problems[0].Reason, Does.Contain("another lens"));
        }

        [Test]
        public void SplitsWithDifferentLenses_AreRefused()
        {
            WriteDataset(OpenCvKeys());
            var path = Path.Combine(_root, "transforms_test.json");
            var json = JObject.Parse(File.ReadAllText(path));
            json["p2"] = 0;
            File.WriteAllText(path, json.ToString());
            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_root, ExportTarget.Colmap));
            Assert.That(e.Problems.Single().Field, Is.EqualTo("transforms_test.json"));
        }

        [Test]
        public void PinholeWithCoefficients_IsRefused_AndAnUnknownModelToo()
        {
            WriteDataset(new JObject { ["camera_model"] = "PINHOLE", ["k1"] = K1 });
            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_root, ExportTarget.Nerfstudio));
            Assert.That(e.Problems[0].Field, Does.EndWith("camera_model"));
            TearDown(); SetUp();
            WriteDataset(new JObject { ["camera_model"] = "FOV", ["k1"] = K1 });
            e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_root, ExportTarget.Nerfstudio));
            Assert.That(e.Problems[0].Value, Does.Contain("FOV"));
        }

        [Test]
        public void AllZeroOpenCvCoefficients_StayAPinhole()
        {
            WriteDataset(new JObject { ["camera_model"] = "OPENCV", ["k1"] = 0, ["k2"] = 0, ["p1"] = 0, ["p2"] = 0 });
            var result = DatasetConverter.Convert(_root, ExportTarget.Colmap);
            Assert.That(CameraLine(File.ReadAllText(Path.Combine(result.OutputDirectory, "sparse", "0", "cameras.txt"))).model, Is.EqualTo("PINHOLE"));
            Assert.That(result.Warnings.Select(w => w.Field), Does.Not.Contain("cameras"));
        }

        // ---- reading COLMAP's text model back --------------------------------------------------------------------

        static (string model, int width, int height, double[] p) CameraLine(string text)
        {
            var line = text.Split('\n').Single(l => l.Length > 0 && l[0] != '#');
            var e = line.Split(' ');
            Assert.That(e[0], Is.EqualTo("1"));
            return (e[1], int.Parse(e[2], CultureInfo.InvariantCulture), int.Parse(e[3], CultureInfo.InvariantCulture),
                e.Skip(4).Select(s => double.Parse(s, CultureInfo.InvariantCulture)).ToArray());
        }

        static Dictionary<string, (double[] q, double[] t)> ImagePoses(string text)
        {
            var lines = text.Split('\n').Where(l => !l.StartsWith("#", StringComparison.Ordinal)).ToList();
            var poses = new Dictionary<string, (double[] q, double[] t)>();
            for (var i = 0; i + 1 < lines.Count; i += 2) // each image line is followed by its POINTS2D line
            {
                var e = lines[i].Split(' ');
                var n = e.Skip(1).Take(7).Select(s => double.Parse(s, CultureInfo.InvariantCulture)).ToArray();
                poses[e[9]] = (n.Take(4).ToArray(), n.Skip(4).ToArray());
            }
            return poses;
        }
    }
}
