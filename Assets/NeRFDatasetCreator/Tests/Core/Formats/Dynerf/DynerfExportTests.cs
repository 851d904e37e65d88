using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// convert --to dynerf read back through 4DGaussians' N3DV reader (hustvl/4DGaussians 843d5ac
    /// scene/neural_3D_dataset_NDC.py): load_meta (lines 262–273: poses_bounds.npy, sorted cam*.mp4 and the count
    /// assert, hwf of camera 0 with focal / (2704 / 1352), the axis swap), load_images_path (308–357: eval_index 0 for
    /// test, video_path.split('.')[0] + "/images", at most 300 sorted images, R = −R, R[:, 0] = −R[:, 0],
    /// T = −c·R, time idx / 300), scene/dataset.py:26–27 (FovX from the focal and the 1352-wide image) and
    /// dataset_readers.py fetchPly (124–130), against the dataset's transform_matrix, camera_angle_x and the analytic depth.
    /// </summary>
    public class DynerfExportTests
    {
        sealed class LoadedImage
        {
            public string Path;
            public double[,] R;
            public double[] T;
            public double Time;
            public int Camera;
        }

        /// <summary>The reader's steps for one split ("train" or "test"), returning the images and the (focal, near_fars).</summary>
        static List<LoadedImage> Load(string root, string split, out double focal, out double[,] nearFars)
        {
            var (rows, columns, arr) = NumpyFloat64Tests.ParseFloat64(File.ReadAllBytes(Path.Combine(root, "poses_bounds.npy")));
            Assert.That(columns, Is.EqualTo(17));
            nearFars = new double[rows, 2];
            for (var n = 0; n < rows; n++)
            {
                nearFars[n, 0] = arr[17 * n + 15];
                nearFars[n, 1] = arr[17 * n + 16];
            }
            // glob(os.path.join(root_dir, "cam*.mp4")), sorted; assert len(videos) == poses_arr.shape[0].
            var videos = Directory.GetFiles(root, "cam*.mp4").OrderBy(f => f, StringComparer.Ordinal).ToList();
            Assert.That(videos.Count, Is.EqualTo(rows), "line 268");
            focal = arr[14] / (2704.0 / 1352); // H, W, focal = poses[0, :, -1]; focal / self.downsample
            var images = new List<LoadedImage>();
            for (var index = 0; index < videos.Count; index++)
            {
                if ((index == 0) != (split == "test")) continue; // eval_index = 0
                var imagePath = Path.Combine(videos[index].Split('.')[0], "images");
                var names = Directory.GetFiles(imagePath).Select(Path.GetFileName).OrderBy(f => f, StringComparer.Ordinal).Take(300).ToList();
                double P(int r, int c) => arr[17 * index + 5 * r + c];
                // poses = [c1, −c0, c2, c3] (line 273), then R = −pose[:3, :3], R[:, 0] = −R[:, 0], T = −pose[:3, 3]·R.
                var pose = new double[3, 4];
                for (var r = 0; r < 3; r++)
                {
                    pose[r, 0] = P(r, 1);
                    pose[r, 1] = -P(r, 0);
                    pose[r, 2] = P(r, 2);
                    pose[r, 3] = P(r, 3);
                }
                var rot = new double[3, 3];
                for (var r = 0; r < 3; r++) for (var c = 0; c < 3; c++) rot[r, c] = -pose[r, c];
                for (var r = 0; r < 3; r++) rot[r, 0] = -rot[r, 0];
                var t = new double[3];
                for (var c = 0; c < 3; c++) for (var r = 0; r < 3; r++) t[c] -= pose[r, 3] * rot[r, c];
                for (var idx = 0; idx < names.Count; idx++)
                    images.Add(new LoadedImage { Path = Path.Combine(imagePath, names[idx]), R = rot, T = t, Time = idx / 300.0, Camera = index });
            }
            return images;
        }

        static Matrix4x4d FromJson(JToken rows) => Matrix4x4d.FromRows(rows.Select(r => r.Select(v => (double)v).ToArray()).ToArray());

        static byte[] OverWhite(PngImage source)
        {
            var n = source.Width * source.Height;
            var rgb = new byte[n * 3];
            for (var q = 0; q < n; q++)
                for (var c = 0; c < 3; c++)
                {
                    var a = source.Samples[4 * q + 3];
                    rgb[3 * q + c] = (byte)Math.Round((source.Samples[4 * q + c] * a + 255.0 * (255 - a)) / 255);
                }
            return rgb;
        }

        [Test]
        public void AMultiViewCaptureReadsBackThroughTheN3dvReader()
        {
            using (var temp = new TempFolder())
            {
                var truth = new AnalyticDepthBounds();
                const int w = 48, h = 36, steps = 3;
                var folder = AnalyticDataset.Write(temp.Path, "moving", new AnalyticDataset.Options
                {
                    Width = w, Height = h, Train = 3, Val = 1, Test = 2, TimeSteps = steps,
                    OutputRays = (view, scene, rays) => truth.Record(view, scene, rays, w, h),
                });
                var result = DatasetConverter.Convert(folder, ExportTarget.Dynerf);
                var outDir = Path.Combine(folder, "dynerf");
                Assume.That(outDir.IndexOf('.') < 0, "the reader cuts the path at its first '.'");
                Assert.That(result.MainFile, Is.EqualTo(Path.Combine(outDir, "poses_bounds.npy")));
                Assert.That(result.Warnings.Select(p => p.Field), Is.SupersetOf(new[] { "splits.test", "val", "time", "width × height" }));
                // The time is carried (as 4DGaussians reads it), not dropped as the static formats' warning says.
                Assert.That(result.Warnings.Where(p => p.Field == "time").Select(p => p.Reason), Has.All.Contains("k / 300").And.None.Contains("are dropped"));

                var train = Load(outDir, "train", out var focal, out var nearFars);
                var test = Load(outDir, "test", out _, out _);
                Assert.That(train.Count, Is.EqualTo(3 * steps));
                Assert.That(test.Count, Is.EqualTo(steps));
                Assert.That(Directory.GetFiles(outDir, "cam*.mp4").Select(f => new FileInfo(f).Length), Is.All.EqualTo(0), "placeholders");

                var trainJson = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")));
                var testJson = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_test.json")));
                var angle = (double)trainJson["camera_angle_x"];
                // scene/dataset.py:26: FovX = focal2fov(focal, 1352) — the image as resized.
                Assert.That(2 * Math.Atan(1352 / (2 * focal)), Is.EqualTo(angle).Within(1e-12));
                Assert.That(2 * Math.Atan(1014 / (2 * focal)), Is.EqualTo(2 * Math.Atan(Math.Tan(angle / 2) * h / w)).Within(1e-12), "FovY");

                var step = ExportScene.DefaultDepthUnitScale;
                foreach (var image in train.Concat(test))
                {
                    // cam00 is test camera 0; cam0c (c ≥ 1) is train camera c − 1.
                    var json = image.Camera == 0 ? testJson : trainJson;
                    var camera = image.Camera == 0 ? 0 : image.Camera - 1;
                    var stepIndex = (int)Math.Round(image.Time * 300);
                    Assert.That(image.Time, Is.EqualTo(stepIndex / 300.0));
                    var frame = json["frames"].Single(f => (int)f["camera_id"] == camera && (int)f["time_step"] == stepIndex);
                    var c2w = FromJson(frame["transform_matrix"]);
                    // getWorld2View2: w2c = [Rᵀ | T]; expected: the inverse of c2w with OpenCV axes (x, −y, −z).
                    var cv = c2w * Matrix4x4d.FromRowMajor(1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1);
                    var w2c = cv.InverseRigid();
                    for (var r = 0; r < 3; r++)
                    {
                        Assert.That(image.T[r], Is.EqualTo(w2c[r, 3]).Within(1e-9), "T");
                        for (var c = 0; c < 3; c++) Assert.That(image.R[c, r], Is.EqualTo(w2c[r, c]).Within(1e-12), "Rᵀ");
                    }
                    var source = (string)frame["file_path"];
                    var sourcePng = PngReader.Read(Path.Combine(folder, source.TrimStart('.', '/') + ".png"));
                    var written = PngReader.Read(image.Path);
                    Assert.That(written.ColorType, Is.EqualTo(PngInfo.ColorTypeRgb), "ToTensor of an RGB image: 3 channels");
                    Assert.That(written.Samples, Is.EqualTo(OverWhite(sourcePng)), image.Path);
                }
                // Bounds per camera: min / max over its time steps of the analytic truth, within one depth step.
                for (var cam = 0; cam < 4; cam++)
                {
                    var json = cam == 0 ? testJson : trainJson;
                    var frames = json["frames"].Where(f => (int)f["camera_id"] == (cam == 0 ? 0 : cam - 1)).Select(f => ((string)f["file_path"]).TrimStart('.', '/') + ".png").ToList();
                    Assert.That(frames.Count, Is.EqualTo(steps));
                    Assert.That(nearFars[cam, 0], Is.EqualTo(frames.Min(f => truth.Of(f).Near)).Within(step), "near of cam " + cam);
                    Assert.That(nearFars[cam, 1], Is.EqualTo(frames.Max(f => truth.Of(f).Far)).Within(step), "far of cam " + cam);
                }
                // fetchPly reads x, y, z, red, green, blue, nx, ny, nz: the capture's own points3d.ply.
                var ply = File.ReadAllBytes(Path.Combine(outDir, "points3D_downsample2.ply"));
                Assert.That(ply, Is.EqualTo(File.ReadAllBytes(Path.Combine(folder, "points3d.ply"))));
                var header = Encoding.ASCII.GetString(ply, 0, 400);
                foreach (var property in new[] { "x", "y", "z", "nx", "ny", "nz", "red", "green", "blue" })
                    Assert.That(header, Does.Contain("property float " + property + "\n").Or.Contain("property uchar " + property + "\n"));
                Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Dynerf), "never overwrites");
            }
        }

        static DatasetSettings MultiView(int train, int test, int steps, int width = 16, int height = 12)
        {
            var s = new DatasetSettings { Seed = 3, Width = width, Height = height };
            s.Train.Count = train;
            s.Val.Count = 1;
            s.Test.Count = test;
            s.Time.Mode = TimeMode.MultiView;
            s.Time.StartSeconds = 0;
            s.Time.EndSeconds = 2;
            s.Time.Steps = steps;
            return s;
        }

        static ValidationProblem Refusal(DatasetSettings settings)
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                TestDatasets.FromPlan(folder, CapturePlan.Build(settings, new PlanTarget(Vector3d.Zero, 0.5)));
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(folder, ExportTarget.Dynerf));
                Assert.That(e.Problems.Count, Is.EqualTo(1), "one clear line");
                Assert.That(Directory.Exists(Path.Combine(folder, "dynerf")), Is.False, "nothing is left behind");
                return e.Problems[0];
            }
        }

        [Test]
        public void AStillDatasetIsRefusedNamingTheTimeMode()
        {
            var problem = Refusal(new DatasetSettings { Seed = 3, Width = 16, Height = 12 });
            Assert.That(problem.Field, Is.EqualTo("dataset_config.json: time.mode"));
            Assert.That(problem.Reason, Does.Contain("not a multi-view capture"));
        }

        [Test]
        public void AnAspectOtherThanFourByThreeIsRefusedWithTheReason()
        {
            var problem = Refusal(MultiView(2, 1, 2, 16, 10));
            Assert.That(problem.Field, Is.EqualTo("width × height"));
            Assert.That(problem.Reason, Does.Contain("1352 × 1014"));
        }

        [Test]
        public void WithoutATestCameraItIsRefusedNamingTheSplit()
        {
            var settings = MultiView(2, 0, 2);
            settings.Loaders = TargetLoaders.InstantNgp; // a loader that needs no test split
            var problem = Refusal(settings);
            Assert.That(problem.Field, Is.EqualTo("splits.test"));
            Assert.That(problem.Reason, Does.Contain("camera 0"));
        }

        [Test]
        public void MoreThanThreeHundredTimeStepsAreRefusedNotDropped()
        {
            var problem = Refusal(MultiView(1, 1, 301));
            Assert.That(problem.Field, Is.EqualTo("dataset_config.json: time.steps"));
            Assert.That(problem.Value, Is.EqualTo("301"));
        }
    }
}
