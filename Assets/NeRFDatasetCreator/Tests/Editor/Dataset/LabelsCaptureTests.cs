using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// A dataset captured with labels through the window's path (<see cref="DatasetCapture"/>): a sphere "Left" and a cube
    /// "Right" under "Pair", one object per renderer, classes by name rules. labels.json gives them ids 1 and 2 (hierarchy
    /// order) and classes "ball" and "box" (rule order); every pixel of every instance map holds the id of the object its
    /// ray meets first (ray–sphere and ray–box in closed form from the view's pose), the semantic map its class; a
    /// second capture writes the same ids byte for byte; and in a dynamic capture the moving cube keeps its id at
    /// every time step.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class LabelsCaptureTests
    {
        const int Size = 40;
        static readonly Vector3 LeftCentre = new Vector3(-0.8f, 0, 0);
        static readonly Vector3 RightCentre = new Vector3(0.8f, 0, 0);
        const float SphereRadius = 0.5f, CubeHalf = 0.4f;

        Scene _scene;
        GameObject _pair;
        GameObject _right;
        AnimationClip _clip;
        string _project;

        [SetUp]
        public void SetUp()
        {
            TestScene.RequireRendering();
            _scene = TestScene.Open();
            _pair = new GameObject("Pair");
            var left = GameObject.CreatePrimitive(PrimitiveType.Sphere);
            left.name = "Left";
            left.transform.SetParent(_pair.transform, false);
            left.transform.localPosition = LeftCentre;
            _right = GameObject.CreatePrimitive(PrimitiveType.Cube);
            _right.name = "Right";
            _right.transform.SetParent(_pair.transform, false);
            _right.transform.localPosition = RightCentre;
            _right.transform.localScale = Vector3.one * (2 * CubeHalf);
            var light = new GameObject("Pair light", typeof(Light));
            light.GetComponent<Light>().type = LightType.Directional;
            _project = Path.Combine(Path.GetTempPath(), "nerf-labels-capture-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_project);
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
            if (_clip != null) UnityEngine.Object.DestroyImmediate(_clip);
            if (_project != null && Directory.Exists(_project)) Directory.Delete(_project, true);
        }

        static DatasetSettings Settings(string name)
        {
            var settings = new DatasetSettings { Name = name, Width = Size, Height = Size, Supersampling = 2, Distance = 4, Seed = 3 };
            settings.Train.Count = 4;
            settings.Val.Count = 1;
            settings.Test.Count = 1;
            settings.Labels = new LabelSettings
            {
                Enabled = true,
                Instances = InstanceRule.Renderer,
                ClassFrom = ClassSource.Name,
                Classes = new List<ClassRule> { new ClassRule("Left", "ball"), new ClassRule("Right", "box") },
            };
            return settings;
        }

        DatasetCaptureResult Capture(DatasetSettings settings, out PreparedCapture prepared)
        {
            prepared = DatasetCapture.Prepare(settings, _pair, _project);
            Assert.That(prepared.Problems.Select(p => p.ToString()), Is.Empty);
            var result = DatasetCapture.RunBlocking(prepared, new SilentProgress());
            Assert.That(result.Succeeded, Is.True, result.Message);
            return result;
        }

        /// <summary>The ray parameter of the first hit with the sphere / the box, or +∞.</summary>
        static float HitSphere(Ray ray, Vector3 centre)
        {
            var oc = ray.origin - centre;
            float b = Vector3.Dot(oc, ray.direction), c = oc.sqrMagnitude - SphereRadius * SphereRadius, d = b * b - c;
            if (d < 0) return float.PositiveInfinity;
            var t = -b - Mathf.Sqrt(d);
            return t > 0 ? t : float.PositiveInfinity;
        }

        static float HitBox(Ray ray, Vector3 centre)
        {
            var bounds = new Bounds(centre, Vector3.one * (2 * CubeHalf));
            return bounds.IntersectRay(ray, out var t) && t > 0 ? t : float.PositiveInfinity;
        }

        /// <summary>The id the scene puts on the ray: 1 (sphere), 2 (cube) or 0.</summary>
        static int IdOnRay(Ray ray, Vector3 rightCentre)
        {
            float s = HitSphere(ray, LeftCentre), c = HitBox(ray, rightCentre);
            if (float.IsInfinity(s) && float.IsInfinity(c)) return 0;
            return s < c ? 1 : 2;
        }

        /// <summary>
        /// The id of output pixel (x, row from the top) where the pixel's centre and the four points half a pixel from it
        /// agree (elsewhere the majority of the k × k samples decides, which is Core's rule, tested there); null otherwise.
        /// </summary>
        static int? Expected(Camera camera, int x, int row, Vector3 rightCentre)
        {
            int? id = null;
            foreach (var (dx, dy) in new[] { (0.5f, 0.5f), (0.02f, 0.5f), (0.98f, 0.5f), (0.5f, 0.02f), (0.5f, 0.98f) })
            {
                var ray = camera.ViewportPointToRay(new Vector3((x + dx) / Size, 1 - (row + dy) / Size, 0));
                var here = IdOnRay(ray, rightCentre);
                if (id == null) id = here;
                else if (id != here) return null;
            }
            return id;
        }

        static void AssertMapsMatchTheScene(string folder, PreparedCapture prepared, Func<PlannedView, Vector3> rightCentreAt)
        {
            var camera = new GameObject("Expected rays", typeof(Camera)).GetComponent<Camera>();
            try
            {
                camera.fieldOfView = (float)prepared.Plan.Settings.Camera.VerticalFovDegrees;
                camera.aspect = 1;
                var seen = new Dictionary<int, int>();
                foreach (var view in prepared.Plan.Views)
                {
                    view.Pose.ApplyTo(camera.transform);
                    var instance = PngGray16Reader.Read(Path.Combine(folder, DatasetLayout.RelativePath(view.Split, view.Index, DatasetFileKind.InstancePng)), out var w, out var h);
                    var semantic = PngGray16Reader.Read(Path.Combine(folder, DatasetLayout.RelativePath(view.Split, view.Index, DatasetFileKind.SemanticPng)), out _, out _);
                    Assert.That(w, Is.EqualTo(Size));
                    Assert.That(h, Is.EqualTo(Size));
                    for (var row = 0; row < Size; row++)
                        for (var x = 0; x < Size; x++)
                        {
                            var expected = Expected(camera, x, row, rightCentreAt(view));
                            if (expected == null) continue;
                            var at = row * Size + x;
                            Assert.That(instance[at], Is.EqualTo(expected.Value), view.FramePath + " pixel (" + x + ", " + row + ")");
                            Assert.That(semantic[at], Is.EqualTo(expected.Value), view.FramePath + " class at (" + x + ", " + row + "): ball = 1, box = 2");
                            seen[expected.Value] = seen.TryGetValue(expected.Value, out var n) ? n + 1 : 1;
                        }
                }
                foreach (var id in new[] { 0, 1, 2 })
                    Assert.That(seen.TryGetValue(id, out var count) ? count : 0, Is.GreaterThan(100), "pixels of id " + id + " checked");
            }
            finally
            {
                UnityEngine.Object.DestroyImmediate(camera.gameObject);
            }
        }

        [Test]
        public void TwoObjectsGetTheirIdsAndEveryPixelHoldsTheObjectProjectedThere()
        {
            var result = Capture(Settings("labels"), out var prepared);
            var table = LabelsJson.ReadFile(Path.Combine(result.DatasetFolder, DatasetLayout.LabelsFileName));
            Assert.That(table.Instances.Select(i => i.Path), Is.EqualTo(new[] { "Pair/Left", "Pair/Right" }), "ids 1, 2 in hierarchy order");
            Assert.That(table.Instances.Select(i => i.ClassName), Is.EqualTo(new[] { "ball", "box" }));
            Assert.That(table.Classes.Select(c => c.Name), Is.EqualTo(new[] { "ball", "box" }), "class ids 1, 2 in rule order");
            AssertMapsMatchTheScene(result.DatasetFolder, prepared, _ => RightCentre);
        }

        [Test]
        public void ASecondCaptureWritesTheSameIds()
        {
            var a = Capture(Settings("first"), out var prepared);
            var b = Capture(Settings("second"), out _);
            Assert.That(File.ReadAllText(Path.Combine(b.DatasetFolder, DatasetLayout.LabelsFileName)),
                Is.EqualTo(File.ReadAllText(Path.Combine(a.DatasetFolder, DatasetLayout.LabelsFileName))));
            foreach (var view in prepared.Plan.Views)
            {
                var file = DatasetLayout.RelativePath(view.Split, view.Index, DatasetFileKind.InstancePng);
                Assert.That(File.ReadAllBytes(Path.Combine(b.DatasetFolder, file)), Is.EqualTo(File.ReadAllBytes(Path.Combine(a.DatasetFolder, file))), file);
            }
        }

        [Test]
        public void TheMovingCubeKeepsItsIdAtEveryTimeStep()
        {
            // The cube slides from x = 0.8 to 1.6 over 2 s (a legacy clip, as DynamicCaptureTests).
            _clip = new AnimationClip { name = "slide", legacy = true };
            _clip.SetCurve("", typeof(Transform), "localPosition.x", AnimationCurve.Linear(0, RightCentre.x, 2, RightCentre.x + 0.8f));
            _clip.SetCurve("", typeof(Transform), "localPosition.y", AnimationCurve.Constant(0, 2, 0));
            _clip.SetCurve("", typeof(Transform), "localPosition.z", AnimationCurve.Constant(0, 2, 0));
            var animation = _right.AddComponent<Animation>();
            animation.AddClip(_clip, _clip.name);
            animation.clip = _clip;
            var settings = Settings("moving");
            settings.Time.Mode = TimeMode.MultiView;
            settings.Time.Steps = 3;
            settings.Time.EndAtClipLength = true;
            var result = Capture(settings, out var prepared);
            var table = LabelsJson.ReadFile(Path.Combine(result.DatasetFolder, DatasetLayout.LabelsFileName));
            Assert.That(table.Instances.Select(i => i.Path), Is.EqualTo(new[] { "Pair/Left", "Pair/Right" }));
            Assert.That(prepared.Plan.Views.Select(v => v.Time.Value.Seconds).Distinct().Count(), Is.EqualTo(3), "three time steps");
            AssertMapsMatchTheScene(result.DatasetFolder, prepared, view => RightCentre + new Vector3((float)(0.4 * view.Time.Value.Seconds), 0, 0));
        }

        sealed class SilentProgress : ICaptureProgress
        {
            public void Report(ThroughputMeter meter) { }
            public bool CancelRequested => false;
            public void Close() { }
        }
    }
}
