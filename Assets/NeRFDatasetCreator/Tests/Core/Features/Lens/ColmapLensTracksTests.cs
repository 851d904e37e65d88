using System;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// COLMAP tracks through a lens (issue 32 item 20): a distorted capture of the analytic scene, written through the
    /// capture's own lens path, converted to COLMAP with tracks. Every written POINTS2D is where COLMAP's own ImgFromCam
    /// (written out from models.h in <see cref="ConvertLensTests.ColmapProjects"/>, not our code) puts the analytic point
    /// through the written OPENCV camera — not the pinhole projection — and every listed image truly sees the point (the
    /// scene's own ray cast from the camera centre reaches it first).
    /// </summary>
    [TestFixture]
    public class ColmapLensTracksTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();

        [TearDown] public void Delete() => _temp.Dispose();

        [TestCase(false, TestName = "ColmapLensTracks_Text")]
        [TestCase(true, TestName = "ColmapLensTracks_Binary")]
        public void TracksAreTheDistortedProjectionsOfPointsTheImagesSee(bool binary)
        {
            AnalyticScene scene = null;
            var folder = AnalyticDataset.Write(_temp.Path, "lens", new AnalyticDataset.Options
            {
                Lens = new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.02 }, ThroughWideRender = true, DataAtOutputSize = false,
                VerticalFovDegrees = 70, Distance = 1.8, Width = 128, Height = 96, Train = 6, Val = 1, Test = 1, PointCloud = 3000,
                OutputRays = (view, s, rays) => scene = scene ?? s,
            });
            var result = DatasetConverter.Convert(folder, ExportTarget.Colmap, Path.Combine(_temp.Path, "colmap"), colmap: new ColmapOptions(binary: binary));
            Assert.That(result.Warnings.Select(w => w.ToString()), Has.None.Contains("points3D tracks"), "tracks are no longer left out for a lens");
            var sparse = Path.Combine(result.OutputDirectory, "sparse", "0");
            var model = binary ? ColmapTestModel.ReadBinary(sparse) : ColmapTestModel.ReadText(sparse);
            var camera = model.Cameras[1];
            Assert.That(camera.Model, Is.EqualTo("OPENCV"));
            var points = model.Points.ToDictionary(p => p.Id);
            int observations = 0, offPinhole = 0;
            double worst = 0;
            foreach (var image in model.Images)
            {
                Assert.That(image.PointIds.Length, Is.GreaterThan(50), image.Name + " observes points");
                var centre = ColmapTestModel.Centre(image);
                var q = new[] { image.QW, image.QX, image.QY, image.QZ };
                var t = new[] { image.TX, image.TY, image.TZ };
                for (var k = 0; k < image.PointIds.Length; k++)
                {
                    var point = points[image.PointIds[k]];
                    var position = new Vector3d(point.X, point.Y, point.Z);
                    var colmap = ConvertLensTests.ColmapProjects("OPENCV", camera.Params, q, t, position);
                    worst = Math.Max(worst, Math.Max(Math.Abs(colmap.x - image.Xs[k]), Math.Abs(colmap.y - image.Ys[k])));
                    model.Project(image, point.X, point.Y, point.Z, out var px, out var py); // the PINHOLE projection
                    if (Math.Abs(px - image.Xs[k]) + Math.Abs(py - image.Ys[k]) > 0.5) offPinhole++;
                    Assert.That(image.Xs[k] >= 0 && image.Xs[k] < camera.Width && image.Ys[k] >= 0 && image.Ys[k] < camera.Height, Is.True, "inside the image");
                    // The scene's own ray from the camera to the point: nothing (glass included) in front of it.
                    var hit = scene.Trace(centre, position - centre, 0, out var s, out _, out _, out _);
                    Assert.That(hit && s >= 1 - 1e-3, Is.True, "point " + point.Id + " is hidden in " + image.Name + " but listed (s = " + s + ")");
                    observations++;
                }
            }
            TestContext.WriteLine(observations + " observations in " + model.Images.Count + " images; worst distance from COLMAP's projection " + worst + " px; " + offPinhole + " more than 0.5 px from the pinhole projection");
            Assert.That(worst, Is.LessThan(1e-9), "the written 2D points are COLMAP's distorted projections");
            Assert.That(offPinhole, Is.GreaterThan(observations / 10), "the lens moves many points by more than half a pixel: the pinhole projection would be wrong");
        }
    }
}
