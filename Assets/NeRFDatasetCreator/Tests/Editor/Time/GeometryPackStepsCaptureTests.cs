using System;
using System.Collections;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;
using UnityEngine.TestTools;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// <c>"geometryPack": "everyStep"</c> on a cube a legacy clip slides along Unity x (0 → 2 over 2 s): the per-step
    /// reader poses a copy by ContentClock at each step's time (the user's cube never moves), and a capture writes
    /// <c>geometry/target_mesh_t&lt;k&gt;.ply</c> with the cube where the clip puts it at step k, in the output frame, lined
    /// up with the depth maps of that step's train view — and not with another step's.
    /// </summary>
    [TestFixture]
    public class GeometryPackStepsCaptureTests
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
            _cube.name = "Stepping cube";
            var light = new GameObject("Stepping cube light", typeof(Light));
            light.GetComponent<Light>().type = LightType.Directional;
            _clip = new AnimationClip { name = "slide", legacy = true };
            _clip.SetCurve("", typeof(Transform), "localPosition.x", AnimationCurve.Linear(0, 0, 2, 2));
            var animation = _cube.AddComponent<Animation>();
            animation.AddClip(_clip, _clip.name);
            animation.clip = _clip;
            _project = Path.Combine(Path.GetTempPath(), "nerf-geometry-steps-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_project);
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
            if (_clip != null) UnityEngine.Object.DestroyImmediate(_clip);
            if (_project != null && Directory.Exists(_project)) Directory.Delete(_project, true);
        }

        static DatasetSettings Settings()
        {
            var s = new DatasetSettings { Name = "steps", Width = 64, Height = 64, Supersampling = 1, Distance = 8, Seed = 1, GeometryPackEveryStep = true };
            s.Train.Count = 3;
            s.Train.Depth = ExtraOutput.Png;
            s.Val.Count = 0;
            s.Test.Count = 1;
            s.Time.Mode = TimeMode.Monocular;
            s.Time.EndAtClipLength = true;
            return s;
        }

        [Test]
        public void EachStepReadsTheCubeWhereTheClipPutsIt()
        {
            var range = new TimeRange(TimeMode.Monocular, TimeSources.All, 0, 2, 3, 0);
            var warnings = new System.Collections.Generic.List<ValidationProblem>();
            using (var steps = new TargetSurfaceOverTime(_cube, range, 1, warnings))
            {
                // In any order: the clock evaluates each time from scratch.
                foreach (var k in new[] { 2, 0, 1 })
                {
                    var meshes = steps.At(k);
                    Assert.That(meshes.Count, Is.EqualTo(1));
                    Assert.That(meshes[0].Vertices.Average(v => v.X), Is.EqualTo(k).Within(1e-5), "step " + k + " is at " + range.SecondsOf(k) + " s, x = t");
                }
            }
            Assert.That(_cube.transform.position, Is.EqualTo(Vector3.zero), "the user's cube never moves");
            Assert.That(warnings, Is.Empty);
        }

        [Test]
        [Category("GPU")]
        public void ACaptureWritesEveryStepsMeshInLineWithThatStepsDepth()
        {
            TestScene.RequireRendering();
            var prepared = DatasetCapture.Prepare(Settings(), _cube, _project);
            var result = DatasetCapture.RunBlocking(prepared, new SilentProgress());
            Assert.That(result.Succeeded, Is.True, result.Message);
            Assert.That(DatasetValidator.Validate(result.DatasetFolder).Problems.Select(p => p.ToString()), Is.Empty);

            var config = JObject.Parse(File.ReadAllText(Path.Combine(result.DatasetFolder, DatasetLayout.ConfigFileName)));
            var entries = GeometryPackStepRecord.Entries(config);
            Assert.That(entries.Select(e => e.Step), Is.EqualTo(new int?[] { 0, 1, 2 }));
            Assert.That(entries.Select(e => e.File), Is.EqualTo(new[] { "geometry/target_mesh_t0000.ply", "geometry/target_mesh_t0001.ply", "geometry/target_mesh_t0002.ply" }));
            Assert.That(File.Exists(Path.Combine(result.DatasetFolder, TargetMeshPly.RelativePath)), Is.False, "every step replaces the start-only mesh");

            var scale = prepared.Plan.Normalisation.Scale;
            var start = GeometryFile.Read(Path.Combine(result.DatasetFolder, entries[0].File));
            var train = EvaluationDataset.Read(result.DatasetFolder, "train");
            for (var k = 0; k < 3; k++)
            {
                var mesh = GeometryFile.Read(Path.Combine(result.DatasetFolder, entries[k].File));
                Assert.That(mesh.TriangleCount, Is.EqualTo(12));
                // Unity x is output x: the cube moved k·1 Unity units (1 s per step) times the normalisation's scale.
                Assert.That(mesh.Vertices.Average(v => v.X) - start.Vertices.Average(v => v.X), Is.EqualTo(k * scale).Within(1e-5));
                // Step k's mesh lines up with the depth of the train view of step k (monocular: train view k), not with another step's.
                var points = GeometryEvaluation.ToFloats(SurfaceSampler.Sample(new[] { mesh }, 4000, 3));
                var seen = new int[3];
                for (var j = 0; j < 3; j++)
                {
                    // Monocular frames carry their time, not a time_step: train view j is step j, at the entry's time.
                    var frame = train.Frames.Single(f => Math.Abs(f.Time.Value - entries[j].Time.Value) < 1e-9);
                    var depth = EvaluationImages.DepthPng(PngReader.Read(frame.DepthPath), train.DepthScale, frame.DepthPath);
                    seen[j] = ObservedPoints.Mark(points, new bool[points.Length / 3], frame.CameraToWorld, depth, 64, 64, train.Focal(64), 32, 32, 0.01);
                }
                Assert.That(seen[k], Is.GreaterThan(points.Length / 3 / 5), "step " + k + " seen by its own train view");
                for (var j = 0; j < 3; j++)
                    if (j != k) Assert.That(seen[k], Is.GreaterThan(3 * seen[j]), "step " + k + " against step " + j + "'s depth");
            }
        }

        /// <summary>
        /// Review R4-6: the per-step geometry is the target as captured. A background capture is started, then the user's
        /// cube is scaled 3× (the clip animates only its x position); the pack, computed when the dataset is finished, still
        /// equals a foreground capture's of the unedited cube, vertex for vertex. Before, the copy was made from the live
        /// target at the end and every step's cube was three times too large.
        /// </summary>
        [UnityTest]
        [Category("GPU")]
        public IEnumerator AnEditDuringABackgroundCaptureDoesNotReachThePerStepGeometry()
        {
            TestScene.RequireRendering();
            var reference = DatasetCapture.RunBlocking(DatasetCapture.Prepare(Settings(), _cube, _project), new SilentProgress());
            Assert.That(reference.Succeeded, Is.True, reference.Message);
            var settings = Settings();
            settings.Name = "edited";
            var prepared = DatasetCapture.Prepare(settings, _cube, _project);
            DatasetCaptureResult result = null;
            Assert.That(DatasetCapture.StartInBackground(prepared, r => result = r), Is.Not.Null);
            _cube.transform.localScale = Vector3.one * 3; // the user edits the target while the capture runs
            for (var frames = 0; result == null && frames < 20000; frames++) yield return null;
            Assert.That(result, Is.Not.Null, "the background capture ended");
            Assert.That(result.Succeeded, Is.True, result.Message);
            for (var k = 0; k < 3; k++)
            {
                var file = GeometryPackSteps.RelativePath(k);
                var expected = GeometryFile.Read(Path.Combine(reference.DatasetFolder, file));
                var actual = GeometryFile.Read(Path.Combine(result.DatasetFolder, file));
                Assert.That(actual.Vertices.Count, Is.EqualTo(expected.Vertices.Count));
                for (var i = 0; i < expected.Vertices.Count; i++)
                    Assert.That((actual.Vertices[i] - expected.Vertices[i]).Length, Is.LessThan(1e-6), file + " vertex " + i);
            }
        }

        sealed class SilentProgress : ICaptureProgress
        {
            public void Report(ThroughputMeter meter) { }
            public bool CancelRequested => false;
            public void Close() { }
        }
    }
}
