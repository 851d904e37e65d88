using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// D-NeRF's and 4DGaussians' limits (issue 23), checked on our own output with the loaders' own formulas, and the
    /// plan warnings that name them under "Made for" (loaders).
    /// </summary>
    [TestFixture]
    public class DynamicLoaderLimitsTests
    {
        static DatasetSettings Dynamic(int width, int height, TimeMode mode, TargetLoaders loaders)
        {
            var s = new DatasetSettings { Width = width, Height = height, Loaders = loaders };
            s.Train.Count = 5;
            s.Val.Count = 3;
            s.Test.Count = 3;
            s.Time.Mode = mode;
            s.Time.StartSeconds = 0;
            s.Time.EndSeconds = 2;
            if (mode == TimeMode.MultiView) s.Time.Steps = 3;
            return s;
        }

        static string[] LoaderWarnings(DatasetSettings s) =>
            CapturePlan.Build(s, new PlanTarget(Vector3d.Zero, 0.5)).Warnings.Where(w => w.Field == "loaders").Select(w => w.Value).ToArray();

        [Test]
        public void DNerfsHalfResCannotFitANonSquareImageOfOurs()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                TestDatasets.FromPlan(folder, CapturePlan.Build(Dynamic(16, 12, TimeMode.Monocular, TargetLoaders.Nerf), new PlanTarget(Vector3d.Zero, 0.5)));
                var first = (string)JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")))["frames"][0]["file_path"];
                var png = PngReader.Read(Path.Combine(folder, first + ".png"));
                // load_blender.py:131–137: H = H//2; W = W//2; imgs_half_res = zeros((n, H, W, 4));
                // imgs_half_res[i] = cv2.resize(img, (H, W)) — OpenCV's dsize is (width, height): rows W, columns H.
                int h = png.Height / 2, w = png.Width / 2;
                var slot = (Rows: h, Columns: w);
                var resized = (Rows: w, Columns: h);
                Assert.That((png.Width, png.Height), Is.EqualTo((16, 12)));
                Assert.That(resized, Is.Not.EqualTo(slot), "numpy cannot assign an 8×6 image into a 6×8 slot: D-NeRF stops");
            }
            Assert.That(LoaderWarnings(Dynamic(16, 12, TimeMode.Monocular, TargetLoaders.Nerf)), Is.EqualTo(new[] { "nerf (D-NeRF)" }));
            Assert.That(LoaderWarnings(Dynamic(16, 16, TimeMode.Monocular, TargetLoaders.Nerf)), Is.Empty, "square: the swap does no harm");
        }

        [Test]
        public void FourDGaussiansGivesANonSquareImageOfOursTheWrongVerticalFieldOfView()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                var settings = Dynamic(16, 12, TimeMode.MultiView, TargetLoaders.GaussianSplatting);
                TestDatasets.FromPlan(folder, CapturePlan.Build(settings, new PlanTarget(Vector3d.Zero, 0.5)));
                var fovx = (double)JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")))["camera_angle_x"];
                // dataset_readers.py:288–289: image resized to 800×800; fovy = focal2fov(fov2focal(fovx, 800), 800) (graphics_utils.py:73–77).
                double Fov2Focal(double fov, double pixels) => pixels / (2 * Math.Tan(fov / 2));
                double Focal2Fov(double focal, double pixels) => 2 * Math.Atan(pixels / (2 * focal));
                var theirs = Focal2Fov(Fov2Focal(fovx, 800), 800);
                var ours = settings.Camera.VerticalFovDegrees * Math.PI / 180;
                Assert.That(theirs, Is.EqualTo(fovx).Within(1e-12), "4DGaussians' vertical FOV is the horizontal one");
                Assert.That(2 * Math.Atan(Math.Tan(fovx / 2) * 12 / 16), Is.EqualTo(ours).Within(1e-9), "our images' true vertical FOV");
                Assert.That(theirs - ours, Is.GreaterThan(0.1), "a 16×12 image trains with a vertical FOV wider by more than 5°");
            }
            Assert.That(LoaderWarnings(Dynamic(16, 12, TimeMode.MultiView, TargetLoaders.GaussianSplatting)), Is.EqualTo(new[] { "3dgs (4DGaussians)" }));
        }

        [Test]
        public void FourDGaussiansWarnsWhenTheContentNeedNotBeAtTheOrigin()
        {
            var recentred = Dynamic(16, 16, TimeMode.MultiView, TargetLoaders.GaussianSplatting);
            Assert.That(LoaderWarnings(recentred), Is.Empty, "formation cameras aimed at the recentred target");
            var none = Dynamic(16, 16, TimeMode.MultiView, TargetLoaders.GaussianSplatting);
            none.Normalisation = NormalisationMode.None;
            var warning = DynamicLoaderLimits.For(none).Single();
            Assert.That(warning.Reason, Does.Contain("normalisation \"none\"").And.Contain("±1.3"));
            var imported = Dynamic(16, 16, TimeMode.MultiView, TargetLoaders.GaussianSplatting);
            imported.Test.Source = new CameraSourceSettings { Kind = CameraSourceKind.ImportedPoses, Path = "x.json" };
            Assert.That(DynamicLoaderLimits.For(imported).Single().Reason, Does.StartWith("with splits.test.source (imported cameras):"));
        }

        [Test]
        public void DNerfsDefaultTestskipBreaksAnEvenNumberOfOurMonocularTrainViews()
        {
            foreach (var (count, lastKept) in new[] { (6, 0.8), (5, 1.0) })
            {
                using (var temp = new TempFolder())
                {
                    var folder = temp.Combine("d");
                    var s = Dynamic(16, 16, TimeMode.Monocular, TargetLoaders.Nerf);
                    s.Train.Count = count;
                    TestDatasets.FromPlan(folder, CapturePlan.Build(s, new PlanTarget(Vector3d.Zero, 0.5)));
                    var times = ((JArray)JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")))["frames"]).Select(f => (double)f["time"]).ToList();
                    Assert.That(times.Last(), Is.EqualTo(1.0), "our last train view is at time 1");
                    // load_blender.py:90–92 with run_dnerf.py's default testskip 2: meta['frames'][::2], train included;
                    // run_dnerf.py:638 then asserts times[i_train[-1]] == 1.
                    var kept = times.Where((t, i) => i % 2 == 0).ToList();
                    Assert.That(kept.Last(), Is.EqualTo(lastKept).Within(1e-12), count + " train views");
                }
            }
        }

        [Test]
        public void StillCapturesAndOtherLoadersGetNoneOfThese()
        {
            var still = Dynamic(16, 12, TimeMode.Monocular, TargetLoaders.All);
            still.Time.Mode = TimeMode.Static;
            Assert.That(DynamicLoaderLimits.For(still), Is.Empty);
            Assert.That(DynamicLoaderLimits.For(Dynamic(16, 12, TimeMode.Monocular, TargetLoaders.Nerfstudio | TargetLoaders.InstantNgp)), Is.Empty);
        }
    }
}
