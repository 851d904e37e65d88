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
    /// A capture writes <c>geometry/target_mesh.ply</c>: the target's cube in the output frame and units, lined up with
    /// the capture's own depth maps (Core's ObservedPoints marks its visible corners' faces as seen); with
    /// <c>"geometryPack": false</c> it writes neither the file nor its record.
    /// </summary>
    [TestFixture]
    public class GeometryPackCaptureTests
    {
        Scene _scene;
        GameObject _cube;
        string _project;

        [SetUp]
        public void SetUp()
        {
            _scene = TestScene.Open();
            _cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
            _cube.name = "Pack cube";
            _cube.transform.position = new Vector3(1, 2, 3);
            var light = new GameObject("Pack light", typeof(Light));
            light.GetComponent<Light>().type = LightType.Directional;
            _project = Path.Combine(Path.GetTempPath(), "nerf-geometry-pack-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_project);
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
            if (_project != null && Directory.Exists(_project)) Directory.Delete(_project, true);
        }

        [Test]
        [Category("GPU")]
        public void TheCubeIsWrittenInTheOutputFrameAndMatchesTheDepthMaps()
        {
            TestScene.RequireRendering();
            var settings = new DatasetSettings { Name = "pack", Width = 64, Height = 64, Supersampling = 1, Distance = 4, Seed = 1 };
            settings.Train.Count = 4;
            settings.Train.Depth = ExtraOutput.Png;
            settings.Val.Count = 0;
            settings.Test.Count = 1;
            var result = DatasetCapture.RunBlocking(DatasetCapture.Prepare(settings, _cube, _project), new SilentProgress());
            Assert.That(result.Succeeded, Is.True, result.Message);

            var mesh = GeometryFile.Read(Path.Combine(result.DatasetFolder, TargetMeshPly.RelativePath));
            Assert.That(mesh.TriangleCount, Is.EqualTo(12), "Unity's cube");
            // Recentred on the cube, scale 1: the corners are at ±0.5 on every output axis.
            Assert.That(mesh.Vertices.Select(v => Math.Max(Math.Abs(v.X), Math.Max(Math.Abs(v.Y), Math.Abs(v.Z)))), Is.All.EqualTo(0.5).Within(1e-5));
            var config = JObject.Parse(File.ReadAllText(Path.Combine(result.DatasetFolder, DatasetLayout.ConfigFileName)));
            Assert.That((int)config["geometry"]["triangles"], Is.EqualTo(12));

            // Faces the cameras see agree with their depth maps.
            var points = GeometryEvaluation.ToFloats(SurfaceSampler.Sample(new[] { mesh }, 5000, 3));
            var observed = new bool[points.Length / 3];
            var train = EvaluationDataset.Read(result.DatasetFolder, "train");
            foreach (var frame in train.Frames)
            {
                var depth = EvaluationImages.DepthPng(PngReader.Read(frame.DepthPath), train.DepthScale, frame.DepthPath);
                ObservedPoints.Mark(points, observed, frame.CameraToWorld, depth, 64, 64, train.Focal(64), 32, 32, 0.01);
            }
            Assert.That(observed.Count(o => o), Is.GreaterThan(observed.Length / 3), "at least the faces towards the cameras");
        }

        [Test]
        [Category("GPU")]
        public void TurnedOffTheCaptureWritesNoPackAndNoRecord()
        {
            TestScene.RequireRendering();
            var settings = new DatasetSettings { Name = "nopack", Width = 32, Height = 32, Supersampling = 1, Distance = 4, Seed = 1, GeometryPack = false };
            settings.Train.Count = 1;
            settings.Val.Count = 0;
            settings.Test.Count = 1;
            var result = DatasetCapture.RunBlocking(DatasetCapture.Prepare(settings, _cube, _project), new SilentProgress());
            Assert.That(result.Succeeded, Is.True, result.Message);
            Assert.That(Directory.Exists(Path.Combine(result.DatasetFolder, TargetMeshPly.Folder)), Is.False);
            var config = JObject.Parse(File.ReadAllText(Path.Combine(result.DatasetFolder, DatasetLayout.ConfigFileName)));
            Assert.That(config[GeometryPackRecord.Key], Is.Null);
        }

        sealed class SilentProgress : ICaptureProgress
        {
            public void Report(ThroughputMeter meter) { }
            public bool CancelRequested => false;
            public void Close() { }
        }
    }
}
