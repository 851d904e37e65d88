using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The cameras.json place-splat writes equals what graphdeco 3DGS's own code writes for the same cameras, here
    /// re-implemented from its lines (utils/camera_utils.py camera_to_JSON; scene/dataset_readers.py
    /// readCamerasFromTransforms; utils/graphics_utils.py fov2focal / focal2fov), for cameras moved into the PLY's frame
    /// as the trainer moves them; it is written where aras-p's importer looks and never over a file.
    /// </summary>
    [TestFixture]
    public class SplatCamerasJsonTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();

        [TearDown] public void Delete() => _temp.Dispose();

        static double Fov2Focal(double fov, double pixels) => pixels / (2 * Math.Tan(fov / 2));

        static double Focal2Fov(double focal, double pixels) => 2 * Math.Atan(pixels / (2 * focal));

        /// <summary>A general 4×4 inverse (Gauss–Jordan with partial pivoting), numpy.linalg.inv's job in graphdeco's code.</summary>
        static double[,] Inverse(double[,] m)
        {
            var a = new double[4, 8];
            for (var r = 0; r < 4; r++)
            for (var c = 0; c < 4; c++) { a[r, c] = m[r, c]; a[r, c + 4] = r == c ? 1 : 0; }
            for (var col = 0; col < 4; col++)
            {
                var pivot = Enumerable.Range(col, 4 - col).OrderByDescending(r => Math.Abs(a[r, col])).First();
                for (var c = 0; c < 8; c++) { var t = a[col, c]; a[col, c] = a[pivot, c]; a[pivot, c] = t; }
                var p = a[col, col];
                for (var c = 0; c < 8; c++) a[col, c] /= p;
                for (var r = 0; r < 4; r++)
                {
                    if (r == col) continue;
                    var f = a[r, col];
                    for (var c = 0; c < 8; c++) a[r, c] -= f * a[col, c];
                }
            }
            var inv = new double[4, 4];
            for (var r = 0; r < 4; r++)
            for (var c = 0; c < 4; c++) inv[r, c] = a[r, c + 4];
            return inv;
        }

        /// <summary>
        /// graphdeco's chain for one transforms frame: c2w[:3, 1:3] *= −1; w2c = inv(c2w); R = w2c[:3,:3].T; T = w2c[:3, 3];
        /// camera_to_JSON: Rt = [R.T | T]; W2C = inv(Rt); position = W2C[:3, 3]; rotation = W2C[:3, :3] as rows;
        /// fx = fov2focal(FovX, width); FovY = focal2fov(fov2focal(FovX, width), height); fy = fov2focal(FovY, height).
        /// </summary>
        static JObject Graphdeco(int id, string name, double[,] c2wOpenGl, double fovX, int width, int height)
        {
            var c2w = (double[,])c2wOpenGl.Clone();
            for (var r = 0; r < 3; r++) { c2w[r, 1] *= -1; c2w[r, 2] *= -1; }
            var w2c = Inverse(c2w);
            var rt = new double[4, 4];
            for (var r = 0; r < 3; r++)
            {
                for (var c = 0; c < 3; c++) rt[r, c] = w2c[r, c]; // (R.T)[r, c] with R = w2c[:3,:3].T
                rt[r, 3] = w2c[r, 3];
            }
            rt[3, 3] = 1;
            var W2C = Inverse(rt);
            var fovY = Focal2Fov(Fov2Focal(fovX, width), height);
            return new JObject
            {
                ["id"] = id, ["img_name"] = name, ["width"] = width, ["height"] = height,
                ["position"] = new JArray(W2C[0, 3], W2C[1, 3], W2C[2, 3]),
                ["rotation"] = new JArray(Enumerable.Range(0, 3).Select(r => new JArray(W2C[r, 0], W2C[r, 1], W2C[r, 2]))),
                ["fy"] = Fov2Focal(fovY, height), ["fx"] = Fov2Focal(fovX, width),
            };
        }

        static double[,] Array4(Matrix4x4d m)
        {
            var a = new double[4, 4];
            for (var r = 0; r < 4; r++)
            for (var c = 0; c < 4; c++) a[r, c] = m[r, c];
            return a;
        }

        static void AssertSame(JToken written, JToken expected, string where)
        {
            if (expected is JObject eo)
            {
                Assert.That(((JObject)written).Properties().Select(p => p.Name), Is.EqualTo(eo.Properties().Select(p => p.Name)), where + ": graphdeco's keys, in its order");
                foreach (var p in eo.Properties()) AssertSame(written[p.Name], p.Value, where + "." + p.Name);
            }
            else if (expected is JArray ea)
            {
                Assert.That(((JArray)written).Count, Is.EqualTo(ea.Count), where);
                for (var i = 0; i < ea.Count; i++) AssertSame(written[i], ea[i], where + "[" + i + "]");
            }
            else if (expected.Type == JTokenType.Float) Assert.That((double)written, Is.EqualTo((double)expected).Within(1e-12), where);
            else Assert.That(written.ToString(), Is.EqualTo(expected.ToString()), where);
        }

        [Test]
        public void ThreeDgsCamerasAreGraphdecosOwn()
        {
            var dataset = SplatFixtures.WriteDataset(_temp.Combine("dataset"));
            var model = SplatFixtures.GaussianSplattingModel(_temp.Combine("model"), SplatFixtures.SampleOutput());
            var p = SplatPlacer.Place(dataset, model);
            Assert.That(p.CamerasJsonPath, Is.EqualTo(Path.Combine(model, "point_cloud", "iteration_30000", "cameras.json")));
            Assert.That(p.ViewerCamerasJsonPath, Is.EqualTo(p.CamerasJsonPath), "the first cameras.json up from the PLY's folder: ours, before the model folder's");
            var written = JArray.Parse(File.ReadAllText(p.CamerasJsonPath));
            var cameras = SplatFixtures.TrainCameras();
            Assert.That(written, Has.Count.EqualTo(cameras.Count));
            for (var i = 0; i < cameras.Count; i++)
                AssertSame(written[i], Graphdeco(i, "r_" + i, Array4(cameras[i]), SplatFixtures.CameraAngleX, SplatFixtures.Width, SplatFixtures.Height), "camera " + i);
        }

        [Test]
        public void NerfstudioCamerasAreMovedAsItsDataparserMovesThem()
        {
            var dataset = SplatFixtures.WriteDataset(_temp.Combine("dataset"));
            var run = _temp.Combine("run");
            SplatFixtures.NerfstudioRun(run, SplatFixtures.SampleOutput().Select(SplatFixtures.ToNerfstudio).ToList(), Path.Combine(run, "exports"));
            var p = SplatPlacer.Place(dataset, run);
            var written = JArray.Parse(File.ReadAllText(p.CamerasJsonPath));
            var cameras = SplatFixtures.TrainCameras();
            for (var i = 0; i < cameras.Count; i++)
            {
                // nerfstudio_dataparser.py lines 237–249: poses = transform_matrix @ poses, then poses[:, :3, 3] *= scale_factor.
                var moved = Array4(SplatFixtures.NerfstudioTransform * cameras[i]);
                for (var r = 0; r < 3; r++) moved[r, 3] *= SplatFixtures.NerfstudioScale;
                AssertSame(written[i], Graphdeco(i, "r_" + i, moved, SplatFixtures.CameraAngleX, SplatFixtures.Width, SplatFixtures.Height), "camera " + i);
            }
        }

        [Test]
        public void AnExistingCamerasJsonIsNeverReplacedAndTheViewerReadsIt()
        {
            var dataset = SplatFixtures.WriteDataset(_temp.Combine("dataset"));
            var model = SplatFixtures.GaussianSplattingModel(_temp.Combine("model"), SplatFixtures.SampleOutput());
            var mine = Path.Combine(model, "point_cloud", "iteration_30000", "cameras.json");
            File.WriteAllText(mine, "[{\"mine\": 1}]");
            var p = SplatPlacer.Place(dataset, model);
            Assert.That(File.ReadAllText(mine), Is.EqualTo("[{\"mine\": 1}]"));
            Assert.That(p.CamerasJsonPath, Is.Null);
            Assert.That(p.ViewerCamerasJsonPath, Is.EqualTo(mine));
            Assert.That(p.Notes, Has.Some.EqualTo("cameras.json not written: " + mine + " exists and is never replaced."));
        }

        [Test]
        public void ThePlacementWorksOnAPlannedDatasetWithoutImages()
        {
            // SplatFixtures' dataset is a plan (imagesRendered false, no image files): sizes come from w and h.
            var dataset = SplatFixtures.WriteDataset(_temp.Combine("dataset"));
            Assert.That(Directory.Exists(Path.Combine(dataset, "train")), Is.False);
            var model = SplatFixtures.GaussianSplattingModel(_temp.Combine("model"), SplatFixtures.SampleOutput());
            var p = SplatPlacer.Place(dataset, model);
            Assert.That(p.CameraCount, Is.EqualTo(8));
        }
    }
}
