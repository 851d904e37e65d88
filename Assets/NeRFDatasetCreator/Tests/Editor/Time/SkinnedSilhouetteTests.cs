using System;
using System.IO;
using System.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// A skinned mesh follows time: a cube skinned to one bone that a legacy clip scales from 1 to 2 over 2 s. In a
    /// multi-view capture every camera sees the silhouette grow (area ×4 at the end under a near-orthographic view,
    /// more than ×3 allowing for perspective), while the user's bone stays at scale 1.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class SkinnedSilhouetteTests
    {
        Scene _scene;
        GameObject _character;
        Transform _bone;
        Mesh _mesh;
        AnimationClip _clip;
        string _project;

        [SetUp]
        public void SetUp()
        {
            _scene = TestScene.Open();
            new GameObject("Skinned light", typeof(Light)).GetComponent<Light>().type = LightType.Directional;
            _character = new GameObject("Character");
            var body = new GameObject("Body", typeof(SkinnedMeshRenderer));
            body.transform.SetParent(_character.transform, false);
            _bone = new GameObject("Root bone").transform;
            _bone.SetParent(_character.transform, false);

            var cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
            _mesh = UnityEngine.Object.Instantiate(cube.GetComponent<MeshFilter>().sharedMesh);
            var material = cube.GetComponent<MeshRenderer>().sharedMaterial;
            UnityEngine.Object.DestroyImmediate(cube);
            _mesh.boneWeights = Enumerable.Repeat(new BoneWeight { boneIndex0 = 0, weight0 = 1 }, _mesh.vertexCount).ToArray();
            _mesh.bindposes = new[] { _bone.worldToLocalMatrix * body.transform.localToWorldMatrix };
            var renderer = body.GetComponent<SkinnedMeshRenderer>();
            renderer.bones = new[] { _bone };
            renderer.rootBone = _bone;
            renderer.sharedMesh = _mesh;
            renderer.sharedMaterial = material;
            // The bounds must hold the largest pose, or the renderer could be culled (SkinnedMeshRenderer.localBounds).
            renderer.localBounds = new Bounds(Vector3.zero, Vector3.one * 4);

            _clip = new AnimationClip { name = "grow", legacy = true };
            foreach (var axis in new[] { "x", "y", "z" })
                _clip.SetCurve("Root bone", typeof(Transform), "localScale." + axis, AnimationCurve.Linear(0, 1, 2, 2));
            var animation = _character.AddComponent<Animation>();
            animation.AddClip(_clip, _clip.name);
            animation.clip = _clip;
            _project = Path.Combine(Path.GetTempPath(), "nerf-skinned-silhouette-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_project);
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
            if (_clip != null) UnityEngine.Object.DestroyImmediate(_clip);
            if (_mesh != null) UnityEngine.Object.DestroyImmediate(_mesh);
            if (_project != null && Directory.Exists(_project)) Directory.Delete(_project, true);
        }

        [Test]
        public void EveryCameraSeesTheSilhouetteGrowWithTheBone()
        {
            TestScene.RequireRendering();
            var settings = new DatasetSettings { Name = "skinned", Width = 64, Height = 64, Supersampling = 1, Distance = 12, Seed = 1 };
            settings.Loaders = TargetLoaders.GaussianSplatting;
            settings.Train.Count = 3;
            settings.Val.Count = 0;
            settings.Test.Count = 1;
            settings.Time.Mode = TimeMode.MultiView;
            settings.Time.EndAtClipLength = true;
            settings.Time.Steps = 3;
            var result = DatasetCapture.RunBlocking(DatasetCapture.Prepare(settings, _character, _project), new SilentProgress());
            Assert.That(result.Succeeded, Is.True, result.Message);

            var texture = new Texture2D(2, 2);
            try
            {
                for (var camera = 0; camera < 3; camera++)
                {
                    // Frame r_(k·C + c) is camera c at step k (C = 3 train cameras).
                    var areas = Enumerable.Range(0, 3).Select(step =>
                    {
                        var path = Path.Combine(result.DatasetFolder, "train", "r_" + (step * 3 + camera) + ".png");
                        Assert.That(texture.LoadImage(File.ReadAllBytes(path)), Is.True);
                        return texture.GetPixels().Sum(p => p.a);
                    }).ToList();
                    Assert.That(areas[0], Is.GreaterThan(0), "camera " + camera + " sees the mesh at 0 s");
                    Assert.That(areas[1], Is.GreaterThan(areas[0] * 1.5), "camera " + camera + " at 1 s (scale 1.5)");
                    Assert.That(areas[2], Is.GreaterThan(areas[0] * 3), "camera " + camera + " at 2 s (scale 2)");
                }
            }
            finally
            {
                UnityEngine.Object.DestroyImmediate(texture);
            }
            Assert.That(_bone.localScale, Is.EqualTo(Vector3.one), "the user's bone is never posed");
        }

        sealed class SilentProgress : ICaptureProgress
        {
            public void Report(ThroughputMeter meter) { }
            public bool CancelRequested => false;
            public void Close() { }
        }
    }
}
