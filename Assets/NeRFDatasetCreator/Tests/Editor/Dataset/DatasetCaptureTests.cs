using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// The whole path the window and batch mode use — settings and a scene object in, a validated dataset out —
    /// on Unity's primitive sphere (radius 0.5) at the origin, 32×32.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class DatasetCaptureTests
    {
        Scene _scene;
        GameObject _sphere;
        string _project;

        [SetUp]
        public void SetUp()
        {
            TestScene.RequireRendering();
            _scene = TestScene.Open();
            _sphere = TestScene.LitSphere("Dataset test sphere");
            _project = Path.Combine(Path.GetTempPath(), "nerf-dataset-capture-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_project);
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
            if (_project != null && Directory.Exists(_project)) Directory.Delete(_project, true);
        }

        static DatasetSettings Settings()
        {
            var settings = new DatasetSettings { Name = "sphere", Width = 32, Height = 32, Supersampling = 2, Distance = 3 };
            settings.Train.Count = 4;
            settings.Val.Count = 2;
            settings.Test.Count = 2;
            settings.Test.Depth = ExtraOutput.Png;
            settings.Test.Mask = true;
            return settings;
        }

        [Test]
        public void MeasureTargetGivesTheSpheresBounds()
        {
            var target = DatasetCapture.MeasureTarget(_sphere);
            Assert.That(target.Centre.Length, Is.LessThan(1e-6));
            // The renderer's axis-aligned box has half-size 0.5, so its bounding sphere has radius 0.5·√3.
            Assert.That(target.BoundingRadius, Is.EqualTo(0.5 * Math.Sqrt(3)).Within(1e-5));
        }

        [Test]
        public void ACaptureWritesAValidDatasetWithThePlansMatrices()
        {
            var prepared = DatasetCapture.Prepare(Settings(), _sphere, _project);
            Assert.That(prepared.Problems.Select(p => p.ToString()), Is.Empty);
            var result = DatasetCapture.RunBlocking(prepared, new SilentProgress());
            Assert.That(result.Succeeded, Is.True, result.Message);

            var report = DatasetValidator.Validate(result.DatasetFolder);
            Assert.That(report.Problems.Select(p => p.ToString()), Is.Empty);
            var frames = JObject.Parse(File.ReadAllText(Path.Combine(result.DatasetFolder, "transforms_train.json")))["frames"];
            var planned = prepared.Plan.ViewsOf(DatasetSplit.Train).ToList();
            for (var i = 0; i < planned.Count; i++)
                Assert.That(frames[i]["transform_matrix"][1][3].Value<double>(), Is.EqualTo(planned[i].TransformMatrix[1, 3]));

            var config = JObject.Parse(File.ReadAllText(Path.Combine(result.DatasetFolder, "dataset_config.json")));
            Assert.That(config.ToString(), Does.Contain("viewsPerSecond"), "the run's speed is recorded for comparison");
            Assert.That(result.Message, Does.Contain("views/s").And.Contain("% of it in PNG encoding"),
                "the closing log line gives the writers' busy time and the encoder's share (capture.md)");
        }

        [Test]
        public void TheSphereIsOpaqueAtTheCentreAndTheCornersAreTransparent()
        {
            var result = DatasetCapture.RunBlocking(DatasetCapture.Prepare(Settings(), _sphere, _project), new SilentProgress());
            Assert.That(result.Succeeded, Is.True, result.Message);
            var texture = new Texture2D(2, 2);
            try
            {
                Assert.That(texture.LoadImage(File.ReadAllBytes(Path.Combine(result.DatasetFolder, "train", "r_0.png"))), Is.True);
                Assert.That(texture.GetPixel(16, 16).a, Is.EqualTo(1f).Within(1e-6f));
                Assert.That(texture.GetPixel(0, 0).a, Is.EqualTo(0f));
                Assert.That(texture.GetPixel(31, 31).a, Is.EqualTo(0f));
            }
            finally
            {
                UnityEngine.Object.DestroyImmediate(texture);
            }
        }

        [Test]
        public void ACancelledCaptureLeavesNothingUnderTheFinalName()
        {
            var prepared = DatasetCapture.Prepare(Settings(), _sphere, _project);
            var result = DatasetCapture.RunBlocking(prepared, new CancelAfter(1));
            Assert.That(result.Succeeded, Is.False);
            Assert.That(result.Cancelled, Is.True, result.Message);
            Assert.That(Directory.Exists(prepared.DatasetFolder), Is.False);
            Assert.That(result.Message, Does.Contain("Partial files are in"));
        }

        [Test]
        public void ATargetWithoutRenderersIsRefusedBeforeAnythingIsWritten()
        {
            var empty = new GameObject("Nothing to see");
            var prepared = DatasetCapture.Prepare(Settings(), empty, _project);
            Assert.That(prepared.IsValid, Is.False);
            Assert.That(prepared.Problems.Select(p => p.Reason).Any(r => r.Contains("no enabled MeshRenderer")), Is.True);
            Assert.That(Directory.GetFileSystemEntries(_project), Is.Empty);
        }

        sealed class SilentProgress : ICaptureProgress
        {
            public void Report(ThroughputMeter meter) { }
            public bool CancelRequested => false;
            public void Close() { }
        }

        sealed class CancelAfter : ICaptureProgress
        {
            readonly int _views;
            int _done;
            public CancelAfter(int views) => _views = views;
            public void Report(ThroughputMeter meter) => _done = meter.Done;
            public bool CancelRequested => _done >= _views;
            public void Close() { }
        }
    }
}
