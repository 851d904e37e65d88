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
    /// Converts a lego dataset to each format and reads the result back with a reader written here from that
    /// format's own documented convention, never from Core: every camera centre and viewing direction must match
    /// the nerf_synthetic source within 1e-6.
    /// </summary>
    public class ConvertLegoTests
    {
        LegoDataset _lego;

        [SetUp]
        public void SetUp() => _lego = new LegoDataset();

        [TearDown]
        public void TearDown() => _lego.Dispose();

        double LegoFocal => 0.5 * LegoDataset.Size / Math.Tan(0.5 * _lego.CameraAngleX);

        [Test]
        public void Nerfstudio_ReadBackAsOpenGlCameraToWorld_GivesTheSameCameras()
        {
            var result = DatasetConverter.Convert(_lego.Root, ExportTarget.Nerfstudio);

            Assert.That(result.MainFile, Is.EqualTo(Path.Combine(_lego.Root, "transforms.json")));
            var json = JObject.Parse(File.ReadAllText(result.MainFile));
            Assert.That((string)json["camera_model"], Is.EqualTo("PINHOLE"));
            Assert.That((double)json["fl_x"], Is.EqualTo(LegoFocal).Within(1e-9));
            Assert.That((double)json["fl_y"], Is.EqualTo(LegoFocal).Within(1e-9));
            Assert.That((double)json["cx"], Is.EqualTo(400.0).Within(1e-9));
            Assert.That((double)json["cy"], Is.EqualTo(400.0).Within(1e-9));
            Assert.That((int)json["w"], Is.EqualTo(800));
            Assert.That((int)json["h"], Is.EqualTo(800));
            Assert.That(json["applied_transform"].ToObject<double[][]>(),
                Is.EqualTo(new[] { new[] { 1.0, 0, 0, 0 }, new[] { 0, 1.0, 0, 0 }, new[] { 0, 0, 1.0, 0 } }));
            Assert.That(json["depth_file_path"], Is.Null);
            Assert.That(json["ply_file_path"], Is.Null, "the lego fixture has no points3d.ply");

            var frames = (JArray)json["frames"];
            Assert.That(frames.Count, Is.EqualTo(_lego.Poses.Count));
            foreach (var frame in frames)
            {
                // nerfstudio: data_dir / file_path as given (extension included); c2w with OpenGL camera axes.
                var filePath = (string)frame["file_path"];
                Assert.That(File.Exists(Path.Combine(_lego.Root, filePath)), Is.True, filePath);
                Assert.That(frame["depth_file_path"], Is.Null);
                Assert.That(frame["mask_path"], Is.Null);
                AssertSameCamera(frame["transform_matrix"].ToObject<double[][]>(), _lego.Poses[filePath], filePath);
            }

            Assert.That(json["train_filenames"].ToObject<string[]>(), Is.EquivalentTo(_lego.Poses.Keys.Where(k => k.StartsWith("train/"))));
            Assert.That(json["val_filenames"].ToObject<string[]>(), Is.EquivalentTo(_lego.Poses.Keys.Where(k => k.StartsWith("val/"))));
            Assert.That(json["test_filenames"].ToObject<string[]>(), Is.EquivalentTo(_lego.Poses.Keys.Where(k => k.StartsWith("test/"))));
            Assert.That(result.Warnings, Is.Empty, string.Join("\n", result.Warnings));
        }

        [Test]
        public void Ngp_IsOneTrainOnlyFileInItsOwnFolder_WithPathsRelativeToIt()
        {
            var result = DatasetConverter.Convert(_lego.Root, ExportTarget.Ngp);

            var folder = Path.Combine(_lego.Root, "ngp");
            Assert.That(result.MainFile, Is.EqualTo(Path.Combine(folder, "transforms.json")));
            Assert.That(Directory.GetFiles(folder, "*.json").Length, Is.EqualTo(1), "instant-ngp loads every json of a folder");
            var json = JObject.Parse(File.ReadAllText(result.MainFile));
            Assert.That((int)json["aabb_scale"], Is.EqualTo(1), "radius 1.5 needs 2·0.33·1.5 = 0.99 ≤ 1");
            Assert.That((double)json["camera_angle_x"], Is.EqualTo(_lego.CameraAngleX).Within(1e-12));
            Assert.That((double)json["fl_x"], Is.EqualTo(LegoFocal).Within(1e-9));
            Assert.That((double)json["cx"] / (double)json["w"], Is.EqualTo(0.5).Within(1e-12), "NGP divides cx by w");
            Assert.That(json["scale"], Is.Null, "NGP's own scale key must keep its default");
            Assert.That(json["offset"], Is.Null, "NGP's own offset key must keep its default");

            var frames = (JArray)json["frames"];
            Assert.That(frames.Count, Is.EqualTo(100));
            foreach (var frame in frames)
            {
                // instant-ngp: base_path (the json's folder) / file_path.
                var filePath = (string)frame["file_path"];
                Assert.That(filePath, Does.StartWith("../train/"));
                var full = Path.GetFullPath(Path.Combine(folder, filePath));
                Assert.That(File.Exists(full), Is.True, full);
                AssertSameCamera(frame["transform_matrix"].ToObject<double[][]>(), _lego.Poses[filePath.Substring(3)], filePath);
            }
        }

        [Test]
        public void Colmap_ReadBackAsWorldToCameraInOpenCvAxes_GivesTheSameCameras()
        {
            var result = DatasetConverter.Convert(_lego.Root, ExportTarget.Colmap);

            var colmap = Path.Combine(_lego.Root, "colmap");
            var cameras = DataLines(Path.Combine(colmap, "sparse", "0", "cameras.txt"));
            Assert.That(cameras.Count, Is.EqualTo(1));
            var camera = cameras[0].Split(' ');
            Assert.That(camera.Take(4), Is.EqualTo(new[] { "1", "PINHOLE", "800", "800" }));
            Assert.That(D(camera[4]), Is.EqualTo(LegoFocal).Within(1e-9));
            Assert.That(D(camera[5]), Is.EqualTo(LegoFocal).Within(1e-9));
            Assert.That(D(camera[6]), Is.EqualTo(400.0).Within(1e-9));
            Assert.That(D(camera[7]), Is.EqualTo(400.0).Within(1e-9));

            // images.txt: two lines per image after the comments; the second (2D points) is empty here.
            var lines = File.ReadAllLines(Path.Combine(colmap, "sparse", "0", "images.txt")).SkipWhile(l => l.StartsWith("#")).ToList();
            Assert.That(lines.Count, Is.EqualTo(2 * _lego.Poses.Count));
            var seen = new HashSet<string>();
            double worstCentre = 0, worstDirection = 0;
            for (var i = 0; i < lines.Count; i += 2)
            {
                Assert.That(lines[i + 1], Is.Empty);
                var e = lines[i].Split(' ');
                Assert.That(e.Length, Is.EqualTo(10));
                Assert.That(e[8], Is.EqualTo("1"));
                var name = e[9];
                Assert.That(File.Exists(Path.Combine(colmap, "images", name)), Is.True, "3DGS opens <source>/images/<name>");
                Assert.That(seen.Add(name), Is.True, "unique names");
                var source = name.Substring(0, name.IndexOf('_')) + "/" + name.Substring(name.IndexOf('_') + 1);

                double qw = D(e[1]), qx = D(e[2]), qy = D(e[3]), qz = D(e[4]);
                var t = new[] { D(e[5]), D(e[6]), D(e[7]) };
                Assert.That(qw * qw + qx * qx + qy * qy + qz * qz, Is.EqualTo(1.0).Within(1e-12));
                // COLMAP's qvec2rotmat (w, x, y, z), world-to-camera; centre = −Rᵀt; OpenCV camera looks along +z = third row of R.
                var r = new[]
                {
                    new[] { 1 - 2 * qy * qy - 2 * qz * qz, 2 * qx * qy - 2 * qw * qz, 2 * qz * qx + 2 * qw * qy },
                    new[] { 2 * qx * qy + 2 * qw * qz, 1 - 2 * qx * qx - 2 * qz * qz, 2 * qy * qz - 2 * qw * qx },
                    new[] { 2 * qz * qx - 2 * qw * qy, 2 * qy * qz + 2 * qw * qx, 1 - 2 * qx * qx - 2 * qy * qy },
                };
                var centre = new double[3];
                for (var k = 0; k < 3; k++) centre[k] = -(r[0][k] * t[0] + r[1][k] * t[1] + r[2][k] * t[2]);
                var pose = _lego.Poses[source];
                worstCentre = Math.Max(worstCentre, PoseAssert.Close(centre, PoseAssert.Centre(pose), 1e-6, name + " centre"));
                worstDirection = Math.Max(worstDirection, PoseAssert.Close(r[2], PoseAssert.Normalised(PoseAssert.ViewDirection(pose)), 1e-6, name + " view direction"));
                // OpenCV's y axis points down the image: the second row of R is minus the OpenGL up column. The
                // float32 source axes are mutually orthogonal only to ~1e-6 and the export re-orthonormalises them
                // around the exact viewing axis, so this roll check (which catches a flipped axis) is looser.
                PoseAssert.Close(r[1], PoseAssert.Normalised(new[] { -pose[0][1], -pose[1][1], -pose[2][1] }), 1e-5, name + " image down");
            }
            Assert.That(seen.Count, Is.EqualTo(_lego.Poses.Count));
            TestContext.WriteLine("COLMAP round trip, worst centre error " + worstCentre.ToString("R", CultureInfo.InvariantCulture) +
                ", worst view-direction error " + worstDirection.ToString("R", CultureInfo.InvariantCulture));
            Assert.That(File.ReadAllLines(Path.Combine(colmap, "sparse", "0", "test.txt")),
                Is.EqualTo(Enumerable.Range(0, LegoDataset.TestCount).Select(i => "test_r_" + i + ".png")));

            var points = DataLines(Path.Combine(colmap, "sparse", "0", "points3D.txt"));
            Assert.That(points.Count, Is.EqualTo(RandomInitCloud.DefaultCount), "3DGS's COLMAP loader fails on an empty points3D.txt");
            foreach (var p in points.Take(1000))
            {
                var e = p.Split(' ');
                Assert.That(e.Length, Is.EqualTo(8));
                for (var k = 1; k <= 3; k++) Assert.That(Math.Abs(D(e[k])), Is.LessThanOrEqualTo(1.3));
            }
            Assert.That(result.Warnings.Select(w => w.Field), Does.Contain("points3D.txt"));
        }

        [Test]
        public void Convert_NeverOverwrites_AndNamesTheFile()
        {
            var existing = Path.Combine(_lego.Root, "transforms.json");
            File.WriteAllText(existing, "user data");

            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_lego.Root, ExportTarget.Nerfstudio));

            Assert.That(e.Problems[0].Field, Is.EqualTo("output"), "the name a user knows the destination by (--out), not a parameter of ours");
            Assert.That(e.Problems[0].Value, Is.EqualTo(existing));
            Assert.That(File.ReadAllText(existing), Is.EqualTo("user data"));
        }

        [Test]
        public void Colmap_ChecksEveryDestinationBeforeWritingAnything()
        {
            var blocker = Path.Combine(_lego.Root, "colmap", "images", "test_r_9.png");
            Directory.CreateDirectory(Path.GetDirectoryName(blocker));
            File.WriteAllText(blocker, "user data");

            Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_lego.Root, ExportTarget.Colmap));

            Assert.That(Directory.GetFiles(Path.Combine(_lego.Root, "colmap"), "*", SearchOption.AllDirectories), Is.EqualTo(new[] { blocker }));
        }

        [Test]
        public void Nerfstudio_IntoAnotherFolder_UsesPathsRelativeToThatFolder()
        {
            var outDir = Path.Combine(_lego.Root, "exports", "ns");

            var result = DatasetConverter.Convert(_lego.Root, ExportTarget.Nerfstudio, outDir);

            var json = JObject.Parse(File.ReadAllText(result.MainFile));
            var first = (string)json["frames"][0]["file_path"];
            Assert.That(first, Does.StartWith("../../"));
            Assert.That(File.Exists(Path.Combine(outDir, first)), Is.True);
        }

        [Test]
        public void Load_MissingTrainFile_NamesTheFolderAndTheFix()
        {
            File.Delete(Path.Combine(_lego.Root, "transforms_train.json"));

            var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(_lego.Root, ExportTarget.Ngp));

            Assert.That(e.Problems[0].Field, Is.EqualTo("datasetDir"));
            Assert.That(e.Problems[0].Reason, Does.Contain("transforms_train.json"));
        }

        [Test]
        public void Load_ImagesOfDifferentSizes_IsAnError()
        {
            TestPng.Write(Path.Combine(_lego.Root, "test", "r_3.png"), 400, 400);

            var e = Assert.Throws<InvalidParameterException>(() => BlenderDatasetLoader.Load(_lego.Root));

            Assert.That(e.Problems[0].Field, Is.EqualTo("test.frames[3].file_path"));
            Assert.That(e.Problems[0].Reason, Does.Contain("400×400"));
        }

        [Test]
        public void Load_PrincipalPointThatIsNotANumber_NamesTheField()
        {
            var path = Path.Combine(_lego.Root, "transforms_train.json");
            var train = JObject.Parse(File.ReadAllText(path));
            train["cx"] = "centre";
            train["cy"] = 400;
            File.WriteAllText(path, train.ToString());

            var e = Assert.Throws<InvalidParameterException>(() => BlenderDatasetLoader.Load(_lego.Root));

            Assert.That(e.Problems.Select(p => p.Field), Is.EqualTo(new[] { "train.cx, cy" }));
            Assert.That(e.Problems[0].Value, Is.EqualTo("\"centre\", 400"));
        }

        [Test]
        public void Load_SceneNormalisationWithATextScale_NamesTheKey()
        {
            var path = Path.Combine(_lego.Root, "transforms_train.json");
            var train = JObject.Parse(File.ReadAllText(path));
            train["scene_normalisation"] = new JObject { ["scale"] = "one", ["centre"] = new JArray(0.0, 0.0, 0.0) };
            File.WriteAllText(path, train.ToString());

            var e = Assert.Throws<InvalidParameterException>(() => BlenderDatasetLoader.Load(_lego.Root));

            Assert.That(e.Problems[0].Field, Is.EqualTo("scene_normalisation"));
        }

        [Test]
        public void Load_ShearedMatrixWithDeterminantOne_IsRefusedLikeValidateRefusesIt()
        {
            // Column 1 += 0.5 · column 0 keeps the determinant at 1 but makes the rotation non-orthonormal: no camera pose.
            var path = Path.Combine(_lego.Root, "transforms_val.json");
            var val = JObject.Parse(File.ReadAllText(path));
            var m = (JArray)val["frames"][1]["transform_matrix"];
            for (var r = 0; r < 3; r++) m[r][1] = (double)m[r][1] + 0.5 * (double)m[r][0];
            File.WriteAllText(path, val.ToString());

            var e = Assert.Throws<InvalidParameterException>(() => BlenderDatasetLoader.Load(_lego.Root));

            Assert.That(e.Problems.Select(p => p.Field), Is.EqualTo(new[] { "val.frames[1].transform_matrix" }));
            Assert.That(e.Problems[0].Reason, Does.Contain("not orthonormal"));
            Assert.That(DatasetValidator.Validate(_lego.Root).Problems.Select(p => p.ToString()), Has.Some.Contains("not orthonormal"), "validate refuses the same matrix");
        }

        [Test]
        public void Load_MissingImage_NamesTheFrame()
        {
            File.Delete(Path.Combine(_lego.Root, "val", "r_2.png"));

            var e = Assert.Throws<InvalidParameterException>(() => BlenderDatasetLoader.Load(_lego.Root));

            Assert.That(e.Problems.Select(p => p.Field), Is.EqualTo(new[] { "val.frames[2].file_path" }));
            Assert.That(e.Problems[0].Value, Is.EqualTo("./val/r_2"));
        }

        [Test]
        public void Load_PicksUpDepthOnlyWhenEveryFrameHasA16BitGreyPng()
        {
            foreach (var image in _lego.Poses.Keys)
                TestPng.Write(Path.Combine(_lego.Root, image.Replace(".png", "_depth_0000.png")), 800, 800, 16, PngInfo.ColorTypeGray);
            // Convert takes the depth a frame's depth_path names (keys only, never guessed from the image's name).
            Assert.That(BlenderDatasetLoader.Load(_lego.Root).HasDepth, Is.False, "unnamed depth files are not guessed");
            foreach (var split in new[] { "train", "val", "test" })
            {
                var path = Path.Combine(_lego.Root, "transforms_" + split + ".json");
                var json = JObject.Parse(File.ReadAllText(path));
                foreach (JObject frame in (JArray)json["frames"]) frame["depth_path"] = (string)frame["file_path"] + "_depth_0000.png";
                File.WriteAllText(path, json.ToString());
            }

            var scene = BlenderDatasetLoader.Load(_lego.Root);
            Assert.That(scene.HasDepth, Is.True);

            var ns = NerfstudioWriter.Build(scene, _lego.Root);
            Assert.That((double)ns["depth_unit_scale_factor"], Is.EqualTo(0.001));
            Assert.That((string)ns["frames"][0]["depth_file_path"], Is.EqualTo(((string)ns["frames"][0]["file_path"]).Replace(".png", "_depth_0000.png")));
            var ngp = NgpWriter.Build(scene, Path.Combine(_lego.Root, "ngp"));
            Assert.That((double)ngp["integer_depth_scale"], Is.EqualTo(0.001));
            Assert.That((string)ngp["frames"][0]["depth_path"], Does.StartWith("../train/").And.EndWith("_depth_0000.png"));

            File.Delete(Path.Combine(_lego.Root, "test", "r_0_depth_0000.png"));
            var warnings = new List<ValidationProblem>();
            Assert.That(BlenderDatasetLoader.Load(_lego.Root, warnings).HasDepth, Is.False);
            Assert.That(warnings.Select(w => w.Field), Does.Contain("depth"));
        }

        [Test]
        public void WithPoints3dPly_NerfstudioReferencesIt_AndColmapListsItsPoints()
        {
            var mesh = new SurfaceMesh(new[] { new Vector3d(-1, -1, 0), new Vector3d(1, -1, 0), new Vector3d(0, 1, 0.5) }, new[] { 0, 1, 2 });
            var cloud = SurfaceSampler.Sample(new[] { mesh }, 300, 4, new Vector3d(0.2, 0.4, 0.6));
            PlyWriter.Write(Path.Combine(_lego.Root, "points3d.ply"), cloud);
            var record = PointCloudRecord.Of(Path.Combine(_lego.Root, "points3d.ply"), "points3d.ply", cloud.Count);
            File.WriteAllText(Path.Combine(_lego.Root, DatasetLayout.ConfigFileName), new JObject { [PointCloudRecord.Key] = record.ToJson() }.ToString());

            var ns = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_lego.Root, ExportTarget.Nerfstudio).MainFile));
            Assert.That((string)ns["ply_file_path"], Is.EqualTo("points3d.ply"));

            var colmap = DatasetConverter.Convert(_lego.Root, ExportTarget.Colmap);
            var sparse = Path.Combine(colmap.OutputDirectory, "sparse", "0");
            Assert.That(File.ReadAllBytes(Path.Combine(sparse, "points3D.ply")), Is.EqualTo(File.ReadAllBytes(Path.Combine(_lego.Root, "points3d.ply"))));
            var points = DataLines(Path.Combine(sparse, "points3D.txt"));
            Assert.That(points.Count, Is.EqualTo(300));
            for (var i = 0; i < points.Count; i++)
            {
                var e = points[i].Split(' ');
                Assert.That(D(e[1]), Is.EqualTo(cloud[i].Position.X).Within(1e-6), "float32 in the PLY");
                Assert.That(D(e[3]), Is.EqualTo(cloud[i].Position.Z).Within(1e-6));
                Assert.That(e.Skip(4).Take(3), Is.EqualTo(new[] { "51", "102", "153" }));
            }
            Assert.That(colmap.Warnings.Select(w => w.Field), Does.Not.Contain("points3D.txt"));
        }

        static List<string> DataLines(string path) =>
            File.ReadAllLines(path).Where(l => l.Length > 0 && !l.StartsWith("#")).ToList();

        static double D(string s) => double.Parse(s, NumberStyles.Float, CultureInfo.InvariantCulture);

        static void AssertSameCamera(double[][] actual, double[][] expected, string what)
        {
            PoseAssert.Close(PoseAssert.Centre(actual), PoseAssert.Centre(expected), 1e-6, what + " centre");
            PoseAssert.Close(PoseAssert.ViewDirection(actual), PoseAssert.ViewDirection(expected), 1e-6, what + " view direction");
        }
    }
}
