using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Dynamic capture on a cube moved and turned by a legacy clip: x goes 0 → 2 and the yaw 0 → 90° over 2 s.
    /// ContentClock poses the copies by time alone; captures show the cube where the clip puts it, never move the
    /// user's cube, and repeat byte for byte.
    /// </summary>
    [TestFixture]
    public class DynamicCaptureTests
    {
        Scene _scene;
        GameObject _cube;
        AnimationClip _clip;
        string _project;

        [SetUp]
        public void SetUp()
        {
            _scene = TestScene.Open();
            _cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
            _cube.name = "Animated cube";
            var light = new GameObject("Animated cube light", typeof(Light));
            light.GetComponent<Light>().type = LightType.Directional;
            _clip = new AnimationClip { name = "slide", legacy = true };
            _clip.SetCurve("", typeof(Transform), "localPosition.x", AnimationCurve.Linear(0, 0, 2, 2));
            _clip.SetCurve("", typeof(Transform), "localEulerAnglesRaw.y", AnimationCurve.Linear(0, 0, 2, 90));
            var animation = _cube.AddComponent<Animation>();
            animation.AddClip(_clip, _clip.name);
            animation.clip = _clip;
            _project = Path.Combine(Path.GetTempPath(), "nerf-dynamic-capture-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_project);
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
            if (_clip != null) UnityEngine.Object.DestroyImmediate(_clip);
            if (_project != null && Directory.Exists(_project)) Directory.Delete(_project, true);
        }

        [Test]
        public void TheClockPosesTheClipAtTheGivenTimeInAnyOrder()
        {
            var clock = new ContentClock(TimeSources.All, 0);
            clock.Show(_cube, 1.5);
            clock.Show(_cube, 0.5);
            Assert.That(_cube.transform.localPosition.x, Is.EqualTo(0.5f).Within(1e-5f));
            Assert.That(_cube.transform.localEulerAngles.y, Is.EqualTo(22.5f).Within(1e-3f));
            Assert.That(ContentClock.ClipLength(_cube, TimeSources.All), Is.EqualTo(2.0).Within(1e-6));
            Assert.That(ContentClock.ClipLength(_cube, TimeSources.Timeline), Is.EqualTo(0.0));
        }

        static DatasetSettings Settings()
        {
            var s = new DatasetSettings { Name = "cube", Width = 64, Height = 64, Supersampling = 1, Distance = 8, Seed = 1 };
            s.Loaders = TargetLoaders.GaussianSplatting;
            s.Train.Count = 5;
            s.Val.Count = 0;
            s.Test.Count = 3;
            s.Time.Mode = TimeMode.Monocular;
            s.Time.EndAtClipLength = true;
            return s;
        }

        [Test]
        public void PreparingMeasuresTheClipAndTheBoundsOverTheWholeRange()
        {
            var prepared = DatasetCapture.Prepare(Settings(), _cube, _project);
            Assert.That(prepared.Problems.Select(p => p.ToString()), Is.Empty);
            Assert.That(prepared.Plan.Time.EndSeconds, Is.EqualTo(2.0).Within(1e-6));
            // The cube sweeps x from 0 to 2: the union of its boxes is centred near x = 1, far from the still cube's 0.
            Assert.That(prepared.Plan.Target.Centre.X, Is.EqualTo(1.0).Within(0.1));
            Assert.That(_cube.transform.position, Is.EqualTo(Vector3.zero), "measuring never moves the user's cube");
        }

        [Test]
        [Category("GPU")]
        public void EachImageShowsTheCubeWhereTheClipPutsItAtThatTime()
        {
            TestScene.RequireRendering();
            var before = SceneSnapshot.Take();
            var prepared = DatasetCapture.Prepare(Settings(), _cube, _project);
            var result = DatasetCapture.RunBlocking(prepared, new SilentProgress());
            Assert.That(result.Succeeded, Is.True, result.Message);
            Assert.That(DatasetValidator.Validate(result.DatasetFolder).Problems.Select(p => p.ToString()), Is.Empty);

            var camera = new GameObject("Expected projection", typeof(Camera)).GetComponent<Camera>();
            var texture = new Texture2D(2, 2);
            try
            {
                camera.fieldOfView = (float)prepared.Plan.Settings.Camera.VerticalFovDegrees;
                camera.aspect = 1;
                foreach (var view in prepared.Plan.Views)
                {
                    // Where the clip puts the cube's centre at this view's time, seen from this view's camera.
                    var seconds = view.Time.Value.Seconds;
                    var centre = new Vector3((float)seconds, 0, 0);
                    view.Pose.ApplyTo(camera.transform);
                    var expected = camera.WorldToViewportPoint(centre) * 64;

                    Assert.That(texture.LoadImage(File.ReadAllBytes(Path.Combine(result.DatasetFolder, view.Files[0].RelativePath))), Is.True);
                    var centroid = AlphaCentroid.Of(texture, out var sa);
                    Assert.That(sa, Is.GreaterThan(0), view.FramePath);
                    // A cube's silhouette centroid is not exactly its projected centre under perspective: 1 px at 64 px.
                    Assert.That(centroid.x, Is.EqualTo(expected.x).Within(1.0), view.FramePath + " x at " + seconds + " s");
                    Assert.That(centroid.y, Is.EqualTo(expected.y).Within(1.0), view.FramePath + " y at " + seconds + " s");
                }
            }
            finally
            {
                UnityEngine.Object.DestroyImmediate(camera.gameObject);
                UnityEngine.Object.DestroyImmediate(texture);
            }
            Assert.That(_cube.transform.position, Is.EqualTo(Vector3.zero));
            Assert.That(SceneSnapshot.Lines(SceneSnapshot.Take()), Is.EqualTo(SceneSnapshot.Lines(before)), "the user's scene is unchanged");
            Assert.That(_scene.isDirty, Is.False, "and not dirty");
        }

        [Test]
        [Category("GPU")]
        public void TwoRunsWriteIdenticalImages()
        {
            TestScene.RequireRendering();
            var first = Settings();
            first.Name = "first";
            var second = Settings();
            second.Name = "second";
            var a = DatasetCapture.RunBlocking(DatasetCapture.Prepare(first, _cube, _project), new SilentProgress());
            var b = DatasetCapture.RunBlocking(DatasetCapture.Prepare(second, _cube, _project), new SilentProgress());
            Assert.That(a.Succeeded && b.Succeeded, Is.True, a.Message + " " + b.Message);
            var files = Directory.GetFiles(a.DatasetFolder, "*.png", SearchOption.AllDirectories).Select(f => f.Substring(a.DatasetFolder.Length)).OrderBy(f => f).ToList();
            Assert.That(files, Has.Count.EqualTo(8));
            foreach (var file in files)
                Assert.That(File.ReadAllBytes(b.DatasetFolder + file), Is.EqualTo(File.ReadAllBytes(a.DatasetFolder + file)), file);
            var times = JObject.Parse(File.ReadAllText(Path.Combine(a.DatasetFolder, "transforms_test.json")))["frames"].Select(f => (double)f["time"]);
            Assert.That(times, Is.EqualTo(new[] { 0, 0.375, 0.875 }));
        }

        [Test]
        [Category("GPU")]
        public void ThePointCloudIsTheSurfaceAtTheFirstTimeStep()
        {
            // From 1 s the clip holds the cube at x = 1 (turned 45°): points3d.ply samples it there, not at rest (x = 0).
            TestScene.RequireRendering();
            var settings = Settings();
            settings.Time.StartSeconds = 1;
            settings.PointCloudPoints = 2000;
            settings.Normalisation = NormalisationMode.None; // output (x, y, z) = Unity (x, z, y)
            var result = DatasetCapture.RunBlocking(DatasetCapture.Prepare(settings, _cube, _project), new SilentProgress());
            Assert.That(result.Succeeded, Is.True, result.Message);
            var points = PlyReader.Read(Path.Combine(result.DatasetFolder, PointCloudOwnership.FileName));
            Assert.That(points.Average(p => p.Position.X), Is.EqualTo(1.0).Within(0.05));
            // Turned 45° about Unity's y: the cube's corners reach √½ from its centre along x.
            Assert.That(points.Max(p => p.Position.X), Is.EqualTo(1 + Math.Sqrt(0.5)).Within(0.05));
            Assert.That(_cube.transform.position, Is.EqualTo(Vector3.zero), "the user's cube stays at rest");
        }

        sealed class SilentProgress : ICaptureProgress
        {
            public void Report(ThroughputMeter meter) { }
            public bool CancelRequested => false;
            public void Close() { }
        }
    }
}
