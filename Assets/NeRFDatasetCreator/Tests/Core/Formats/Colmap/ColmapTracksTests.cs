using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Exact tracks (issue 25) on an analytically rendered dataset with self-occlusion: two spheres, the small one
    /// hiding part of the big one from +x and hidden behind it from −x, a close view with points behind the camera,
    /// and one mask with a hole. Every point is projected with COLMAP's own PINHOLE formulas (derived in
    /// <see cref="ColmapTestModel.Project"/>) into every image of the model as a trainer reads it: a listed image must
    /// see the point (the scene's own ray cast from the camera reaches it) at the written pixel; an unlisted one must
    /// not — behind the camera, outside the image or occluded — or be one of the documented conservative misses
    /// (ColmapVisibility: within half a pixel of the border, edge-on, or a depth/mask edge among the four nearest
    /// pixel centres).
    /// </summary>
    public class ColmapTracksTests
    {
        const int Width = 256, Height = 192, Points = 6000;
        const int MaskedView = 1;

        TempFolder _temp;
        SphereScene _scene;
        CameraIntrinsics _k;
        List<(string Split, Matrix4x4d CameraToWorld)> _views;
        List<CloudPoint> _cloud;
        readonly Dictionary<int, byte[]> _masks = new Dictionary<int, byte[]>();
        string _dataset, _text, _binary;
        ColmapTestModel _model;

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _scene = SphereScene.TwoSpheres();
            // Off-centre principal point and a non-square image: a swapped axis or a half-pixel slip shows.
            _k = CameraIntrinsics.FromVerticalFov(40, Width, Height, 0.031, -0.022);
            _views = new List<(string, Matrix4x4d)>();
            for (var i = 0; i < 10; i++)
            {
                var azimuth = 2 * Math.PI * i / 10;
                var eye = new Vector3d(4.5 * Math.Cos(azimuth) * Math.Cos(0.3), 4.5 * Math.Sin(azimuth) * Math.Cos(0.3), 4.5 * Math.Sin(0.3));
                _views.Add((i < 7 ? "train" : i < 9 ? "val" : "test", SphereScene.LookAt(eye, new Vector3d(0.2, 0, 0))));
            }
            _views.Add(("train", SphereScene.LookAt(new Vector3d(0.6, 0.4, 4.4), Vector3d.Zero)));
            // Close to the big sphere, looking past it at the small one: much of the cloud is behind this camera.
            _views.Add(("train", SphereScene.LookAt(new Vector3d(0, -1.15, 0.3), new Vector3d(1.45, -0.6, 0.3))));
            _cloud = _scene.Sample(Points, 25);
            _dataset = Path.Combine(_temp.Path, "spheres");
            _scene.WriteDataset(_dataset, _views, _k, _cloud, alterMask: (v, mask) =>
            {
                if (v == MaskedView)
                    for (var j = 0; j < Height; j++)
                        for (var i = 0; i < Width / 2; i++) mask[j * Width + i] = 0;
                _masks[v] = (byte[])mask.Clone();
            });
            _text = Path.Combine(_temp.Path, "text");
            _binary = Path.Combine(_temp.Path, "binary");
            DatasetConverter.Convert(_dataset, ExportTarget.Colmap, _text, colmap: new ColmapOptions(minTrackLength: 0));
            DatasetConverter.Convert(_dataset, ExportTarget.Colmap, _binary, colmap: new ColmapOptions(binary: true, minTrackLength: 0));
            _model = ColmapTestModel.ReadText(Path.Combine(_text, "sparse", "0"));
        }

        [OneTimeTearDown]
        public void Clean() => _temp.Dispose();

        /// <summary>The model's image index of dataset view v: images are listed in frame order, train, val, test.</summary>
        int ViewOfImage(int image)
        {
            var order = _views.Select((v, i) => (v.Split, i)).OrderBy(v => Array.IndexOf(new[] { "train", "val", "test" }, v.Split)).ThenBy(v => v.i).ToList();
            return order[image].i;
        }

        [Test]
        public void EveryPointIsListedInExactlyTheImagesThatSeeIt()
        {
            Assert.That(_model.Points.Count, Is.EqualTo(Points), "--min-track 0 keeps every point of the cloud, in order");
            Assert.That(_model.Images.Count, Is.EqualTo(_views.Count));
            var camera = _model.Cameras[1];
            Assert.That(camera.Model, Is.EqualTo("PINHOLE"));
            int listed = 0, behind = 0, outside = 0, occludedByOther = 0, occludedBySelf = 0, conservative = 0;
            var misses = new Dictionary<string, int>();
            for (var m = 0; m < _model.Images.Count; m++)
            {
                var image = _model.Images[m];
                var view = ViewOfImage(m);
                var c2w = _views[view].CameraToWorld;
                var centre = ColmapTestModel.Centre(image);
                Assert.That(Vector3d.Distance(centre, c2w.Translation), Is.LessThan(1e-9), image.Name);
                var seen = new Dictionary<long, int>();
                for (var k = 0; k < image.PointIds.Length; k++) seen[image.PointIds[k]] = k;
                Assert.That(seen.Count, Is.EqualTo(image.PointIds.Length), "a point is listed once per image");
                Assert.That(image.PointIds.Length, Is.GreaterThan(50), image.Name + " sees a good share of the cloud");

                for (var p = 0; p < _model.Points.Count; p++)
                {
                    var point = _model.Points[p];
                    var position = new Vector3d(point.X, point.Y, point.Z);
                    var z = _model.Project(image, point.X, point.Y, point.Z, out var x, out var y);
                    var isListed = seen.TryGetValue(point.Id, out var index);
                    // The track names this image at this POINTS2D index exactly when the image lists the point.
                    var inTrack = Array.IndexOf(point.ImageIds, image.Id);
                    Assert.That(inTrack >= 0, Is.EqualTo(isListed), "track and POINTS2D agree, point " + point.Id + " in " + image.Name);
                    if (isListed) Assert.That(point.Point2DIndices[inTrack], Is.EqualTo(index));

                    if (!(z > 0))
                    {
                        Assert.That(isListed, Is.False, "point " + point.Id + " is behind " + image.Name);
                        behind++;
                        continue;
                    }
                    if (x < 0 || x >= camera.Width || y < 0 || y >= camera.Height)
                    {
                        Assert.That(isListed, Is.False, "point " + point.Id + " projects outside " + image.Name);
                        outside++;
                        continue;
                    }
                    // The scene's own ray cast: the first surface from the camera towards the point is the point itself.
                    var first = _scene.Hit(centre, position - centre, out var s);
                    var visible = s >= 1 - 1e-6;
                    if (isListed)
                    {
                        listed++;
                        Assert.That(visible, Is.True, "point " + point.Id + " is hidden in " + image.Name + " but listed");
                        Assert.That(Math.Sqrt(Math.Pow(image.Xs[index] - x, 2) + Math.Pow(image.Ys[index] - y, 2)), Is.LessThan(1e-6),
                            "the written 2D point is the projection of point " + point.Id + " in " + image.Name);
                        continue;
                    }
                    if (!visible)
                    {
                        if (_scene.Spheres[first].Centre.Equals(NearestSphere(position).Centre)) occludedBySelf++;
                        else occludedByOther++;
                        continue;
                    }
                    var miss = ConservativeMiss(view, position, new Vector3d(_cloud[p].Normal.X, _cloud[p].Normal.Y, _cloud[p].Normal.Z), x, y, z);
                    Assert.That(miss, Is.Not.Null,
                        "point " + point.Id + " is visible in " + image.Name + " at (" + x + ", " + y + ") away from any edge, but not listed");
                    misses[miss] = misses.TryGetValue(miss, out var n) ? n + 1 : 1;
                    conservative++;
                }
            }
            TestContext.WriteLine($"listed {listed}, behind {behind}, outside {outside}, occluded by the other sphere {occludedByOther}, by its own {occludedBySelf}, conservative misses {conservative} ({string.Join(", ", misses.Select(e => e.Key + " " + e.Value))})");
            Assert.That(behind, Is.GreaterThan(0), "the close view has points behind it");
            Assert.That(occludedByOther, Is.GreaterThan(0), "one sphere hides part of the other");
            Assert.That(outside, Is.GreaterThan(0), "the close view cuts the big sphere off");
            // Edge-on points (|cos θ| < 0.1: a tenth of a sphere's visible area) and the masked-out half are refused by
            // design; what is left — a pixel band along silhouettes and the border — must stay a small part.
            var band = conservative - Count(misses, "edge-on") - Count(misses, "masked out");
            Assert.That(Count(misses, "masked out"), Is.GreaterThan(100));
            Assert.That(band, Is.LessThan(0.15 * (listed + conservative)), "misses are the edge cases, not the rule");
        }

        static int Count(Dictionary<string, int> misses, string reason) => misses.TryGetValue(reason, out var n) ? n : 0;

        SphereScene.Sphere NearestSphere(Vector3d p) =>
            _scene.Spheres.OrderBy(s => Math.Abs(Vector3d.Distance(p, s.Centre) - s.Radius)).First();

        /// <summary>
        /// The documented misses, recomputed from the scene: the four pixel centres around (x, y) are not all inside,
        /// the point is seen edge-on (|cos θ| &lt; 0.1), or at one of those centres the mask is not 255 or the true depth
        /// is off the point's tangent plane by more than half the pixel footprint Z/(f·|cos θ|) (the tolerance beyond
        /// the 0.5 mm quantisation, which the true depth does not have).
        /// </summary>
        string ConservativeMiss(int view, Vector3d p, Vector3d normal, double x, double y, double z)
        {
            if (x < 0.5 || x >= Width - 0.5 || y < 0.5 || y >= Height - 0.5) return "border";
            if (view == MaskedView && x < Width / 2 + 0.5) return "masked out";
            var c2w = _views[view].CameraToWorld;
            var toPoint = p - c2w.Translation;
            var cosine = Math.Abs(Vector3d.Dot(normal, toPoint)) / toPoint.Length;
            if (cosine < 0.1) return "edge-on";
            var footprint = z / Math.Min(_k.FlX, _k.FlY) / cosine;
            int i0 = (int)Math.Floor(x - 0.5), j0 = (int)Math.Floor(y - 0.5);
            for (var c = 0; c < 4; c++)
            {
                int i = i0 + (c & 1), j = j0 + (c >> 1);
                if (_masks[view][j * Width + i] != 255) return "mask";
                var ray = SphereScene.Ray(c2w, _k, i + 0.5, j + 0.5);
                var trueDepth = _scene.DepthAt(c2w, _k, i + 0.5, j + 0.5);
                var planeDepth = Vector3d.Dot(normal, toPoint) / Vector3d.Dot(normal, ray);
                if (trueDepth == 0) return "background";
                if (Math.Abs(trueDepth - planeDepth) > 0.5 * footprint) return "depth edge";
            }
            return null;
        }

        [Test]
        public void TheMaskedHalfOfAViewListsNothing()
        {
            var m = Enumerable.Range(0, _views.Count).First(i => ViewOfImage(i) == MaskedView);
            var image = _model.Images[m];
            Assert.That(image.Xs, Has.All.GreaterThanOrEqualTo(Width / 2 + 0.5), "mask 0 on the left half");
            Assert.That(image.Xs.Length, Is.GreaterThan(50));
        }

        [Test]
        public void ErrorIsTheTrueMeanReprojectionError()
        {
            foreach (var point in _model.Points.Where(p => p.ImageIds.Length > 0))
            {
                double sum = 0;
                for (var e = 0; e < point.ImageIds.Length; e++)
                {
                    var image = _model.Images.Single(i => i.Id == point.ImageIds[e]);
                    _model.Project(image, point.X, point.Y, point.Z, out var x, out var y);
                    var k = point.Point2DIndices[e];
                    sum += Math.Sqrt(Math.Pow(image.Xs[k] - x, 2) + Math.Pow(image.Ys[k] - y, 2));
                }
                Assert.That(Math.Abs(point.Error - sum / point.ImageIds.Length), Is.LessThan(1e-9), "point " + point.Id);
            }
        }

        [Test]
        public void TextAndBinaryHoldTheSameModel()
        {
            var binary = ColmapTestModel.ReadBinary(Path.Combine(_binary, "sparse", "0"));
            Assert.That(File.Exists(Path.Combine(_binary, "sparse", "0", "images.txt")), Is.False, "--binary writes the binary model instead");
            Assert.That(binary.Cameras.Keys, Is.EqualTo(_model.Cameras.Keys));
            var a = _model.Cameras[1];
            var b = binary.Cameras[1];
            Assert.That((b.Model, b.Width, b.Height), Is.EqualTo((a.Model, a.Width, a.Height)));
            Assert.That(b.Params, Is.EqualTo(a.Params).Within(1e-12));
            Assert.That(binary.Images.Count, Is.EqualTo(_model.Images.Count));
            for (var i = 0; i < binary.Images.Count; i++)
            {
                ColmapTestModel.Image t = _model.Images[i], u = binary.Images[i];
                Assert.That((u.Id, u.CameraId, u.Name), Is.EqualTo((t.Id, t.CameraId, t.Name)));
                Assert.That(new[] { u.QW, u.QX, u.QY, u.QZ, u.TX, u.TY, u.TZ }, Is.EqualTo(new[] { t.QW, t.QX, t.QY, t.QZ, t.TX, t.TY, t.TZ }).Within(1e-12));
                Assert.That(u.PointIds, Is.EqualTo(t.PointIds), t.Name);
                Assert.That(u.Xs, Is.EqualTo(t.Xs).Within(1e-9), t.Name);
                Assert.That(u.Ys, Is.EqualTo(t.Ys).Within(1e-9), t.Name);
            }
            Assert.That(binary.Points.Count, Is.EqualTo(_model.Points.Count));
            for (var p = 0; p < binary.Points.Count; p++)
            {
                ColmapTestModel.Point t = _model.Points[p], u = binary.Points[p];
                Assert.That((u.Id, u.R, u.G, u.B), Is.EqualTo((t.Id, t.R, t.G, t.B)));
                Assert.That(new[] { u.X, u.Y, u.Z, u.Error }, Is.EqualTo(new[] { t.X, t.Y, t.Z, t.Error }).Within(1e-12));
                Assert.That(u.ImageIds, Is.EqualTo(t.ImageIds));
                Assert.That(u.Point2DIndices, Is.EqualTo(t.Point2DIndices));
            }
            // The points are the cloud's (float32 positions, its colours).
            Assert.That(_model.Points.Select(p => (p.X, p.Y, p.Z)), Is.EqualTo(_cloud.Select(c => (c.Position.X, c.Position.Y, c.Position.Z))));
        }

        [Test]
        public void CoresReaderReadsThePosesBack()
        {
            var poses = ColmapModelReader.ReadFolder(Path.Combine(_text, "sparse", "0"));
            Assert.That(poses.Cameras.Count, Is.EqualTo(_views.Count));
            for (var m = 0; m < poses.Cameras.Count; m++)
                Assert.That(Vector3d.Distance(poses.Cameras[m].FileCameraToWorld.Translation, _views[ViewOfImage(m)].CameraToWorld.Translation), Is.LessThan(1e-9));
        }

        [Test]
        public void TheDefaultMinimumTrackLengthKeepsThePointsSeenTwiceWithTheirTracks()
        {
            var output = Path.Combine(_temp.Path, "default");
            var result = DatasetConverter.Convert(_dataset, ExportTarget.Colmap, output);
            var model = ColmapTestModel.ReadText(Path.Combine(output, "sparse", "0"));
            var expected = _model.Points.Where(p => p.ImageIds.Length >= ColmapOptions.DefaultMinTrackLength).ToList();
            Assert.That(expected.Count, Is.LessThan(Points).And.GreaterThan(Points / 3), "some points are seen by fewer than two views");
            Assert.That(model.Points.Select(p => (p.X, p.Y, p.Z)), Is.EqualTo(expected.Select(p => (p.X, p.Y, p.Z))));
            Assert.That(model.Points.Select(p => p.Id), Is.EqualTo(Enumerable.Range(1, expected.Count).Select(i => (long)i)), "ids renumbered 1…N");
            Assert.That(model.Points.Select(p => p.ImageIds), Is.EqualTo(expected.Select(p => p.ImageIds)));
            var newId = expected.Select((p, i) => (p.Id, New: i + 1L)).ToDictionary(e => e.Id, e => e.New);
            for (var m = 0; m < model.Images.Count; m++)
            {
                var kept = Enumerable.Range(0, _model.Images[m].PointIds.Length).Where(k => newId.ContainsKey(_model.Images[m].PointIds[k])).ToList();
                Assert.That(model.Images[m].PointIds, Is.EqualTo(kept.Select(k => newId[_model.Images[m].PointIds[k]])));
                Assert.That(model.Images[m].Xs, Is.EqualTo(kept.Select(k => _model.Images[m].Xs[k])));
            }
            Assert.That(result.TrainCommands, Has.Some.StartWith("python simple_trainer.py default --data_dir " + Path.GetFullPath(output) + " --data_factor 1 --depth_loss"));
        }

        [Test]
        public void PointsTakesTheFirstPointsOfTheCloud()
        {
            var output = Path.Combine(_temp.Path, "first-1000");
            DatasetConverter.Convert(_dataset, ExportTarget.Colmap, output, colmap: new ColmapOptions(maxPoints: 1000, minTrackLength: 0));
            var model = ColmapTestModel.ReadText(Path.Combine(output, "sparse", "0"));
            Assert.That(model.Points.Select(p => (p.X, p.Y, p.Z, p.ImageIds.Length)), Is.EqualTo(_model.Points.Take(1000).Select(p => (p.X, p.Y, p.Z, p.ImageIds.Length))));
        }

        [Test]
        public void WithoutDepthMapsTheTracksAreEmptyAndItSaysSo()
        {
            var dataset = Path.Combine(_temp.Path, "no-depth");
            _scene.WriteDataset(dataset, new[] { _views[0], _views[7], _views[9] }, _k, _cloud.Take(200).ToList(), withDepth: false);
            var output = Path.Combine(_temp.Path, "no-depth-colmap");
            var result = DatasetConverter.Convert(dataset, ExportTarget.Colmap, output);
            Assert.That(result.Warnings.Select(w => w.ToString()), Has.Some.Contains("points3D tracks").And.Contains("this dataset has none"));
            var model = ColmapTestModel.ReadText(Path.Combine(output, "sparse", "0"));
            Assert.That(model.Points.Count, Is.EqualTo(200), "every point kept, as before tracks existed");
            Assert.That(model.Points.Select(p => p.ImageIds.Length), Has.All.EqualTo(0));
            Assert.That(model.Images.Select(i => i.PointIds.Length), Has.All.EqualTo(0));
            Assert.That(result.TrainCommands, Has.None.Contains("simple_trainer"));
        }

        [Test]
        public void AForeignCloudGetsNoTracks()
        {
            var dataset = Path.Combine(_temp.Path, "foreign");
            _scene.WriteDataset(dataset, new[] { _views[0], _views[7], _views[9] }, _k, _cloud.Take(300).ToList());
            File.WriteAllText(Path.Combine(dataset, DatasetLayout.ConfigFileName), "{}"); // no record: the ply is not ours
            var output = Path.Combine(_temp.Path, "foreign-colmap");
            var result = DatasetConverter.Convert(dataset, ExportTarget.Colmap, output);
            var model = ColmapTestModel.ReadText(Path.Combine(output, "sparse", "0"));
            Assert.That(model.Points.Count, Is.EqualTo(RandomInitCloud.DefaultCount), "the random stand-in, not the foreign file");
            Assert.That(model.Points.Select(p => p.ImageIds.Length), Has.All.EqualTo(0));
            Assert.That(result.Warnings.Select(w => w.ToString()), Has.Some.Contains("foreign"));
        }
    }
}
