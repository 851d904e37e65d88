using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// LOD groups (LOD 0 only, in the bounds, the point cloud and the images) and template cameras (culling mask
    /// checked against the target's layers; a physical camera's gate fit reproduced or refused).
    /// </summary>
    [TestFixture]
    public class LodAndTemplateCameraTests
    {
        Scene _scene;
        string _project;

        [SetUp]
        public void SetUp()
        {
            _scene = TestScene.Open();
            _project = Path.Combine(Path.GetTempPath(), "nerf-lod-template-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_project);
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
            if (Directory.Exists(_project)) Directory.Delete(_project, true);
        }

        /// <summary>
        /// A LODGroup whose LOD 0 is a unit sphere at the origin and whose LOD 1 is a 1.2 cube — at (offset, 0, 0).
        /// LOD 0 is drawn only above 99 % of the screen height, so at a normal distance Unity would pick LOD 1.
        /// </summary>
        static GameObject LodTarget(float lod1Offset)
        {
            var root = new GameObject("LOD target");
            var sphere = GameObject.CreatePrimitive(PrimitiveType.Sphere);
            sphere.transform.SetParent(root.transform, false);
            var cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
            cube.transform.SetParent(root.transform, false);
            cube.transform.localPosition = new Vector3(lod1Offset, 0, 0);
            cube.transform.localScale = Vector3.one * 1.2f;
            var group = root.AddComponent<LODGroup>();
            group.SetLODs(new[]
            {
                new LOD(0.99f, new Renderer[] { sphere.GetComponent<Renderer>() }),
                new LOD(0.01f, new Renderer[] { cube.GetComponent<Renderer>() }),
            });
            return root;
        }

        [Test]
        public void TheMeasurementAndThePointCloudUseLod0Only()
        {
            var target = LodTarget(5);
            var measured = DatasetCapture.MeasureTarget(target);
            Assert.That(measured.Centre.Length, Is.LessThan(1e-5), "the far LOD 1 cube would move the centre to x ≈ 2.7");
            Assert.That(measured.BoundingRadius, Is.EqualTo(0.5 * Math.Sqrt(3)).Within(1e-5));
            var meshes = TargetSurface.Collect(target, new List<ValidationProblem>());
            Assert.That(meshes, Has.Count.EqualTo(1), "only the LOD 0 sphere is sampled");
        }

        [Test]
        [Category("GPU")]
        public void TheImagesShowLod0WhateverTheDistance()
        {
            TestScene.RequireRendering();
            var target = LodTarget(0);
            new GameObject("LOD light", typeof(Light)).GetComponent<Light>().type = LightType.Directional;
            var options = new CaptureOptions { Width = 64, Height = 64, Supersampling = 1, VerticalFieldOfViewDegrees = 40, NearClip = 0.1, FarClip = 100 };
            var consumer = new RecordingConsumer();
            var pose = LookAt.FromPositions(new Vector3d(0, 0, -3), Vector3d.Zero);
            CaptureRunner.RunBlocking(target, new List<UnityPose> { pose }, options, consumer, new ScriptedProgress());
            var view = consumer.Views.Single();
            // In the image plane (tan of the angle, half-width tan 20° = 0.364): the sphere's silhouette reaches
            // tan(asin(0.5/3)) = 0.169, 46 % of the half-width; the cube's near face (half-side 0.6 at distance 2.4)
            // would reach 0.25, 69 %. Pixel 51 is 61 % out.
            Assert.That(view.MaskAt(32, 32), Is.EqualTo(255), "the LOD 0 sphere is drawn");
            Assert.That(view.MaskAt(32 + 19, 32), Is.EqualTo(0), "at 60 % of the half-width only the LOD 1 cube would cover the pixel");
            // The colour pass too: the camera, not the data-pass command buffer, decides what it draws.
            Assert.That(view.AlphaAt(32, 32), Is.EqualTo(1f).Within(1e-3f), "the LOD 0 sphere is in the colour pass");
            Assert.That(view.AlphaAt(32 + 19, 32), Is.EqualTo(0f).Within(1e-3f), "and the LOD 1 cube is not");
            Assert.That(target.GetComponentsInChildren<Renderer>().All(r => r.enabled), Is.True, "the user's renderers are untouched");
        }

        static Camera Template(string name)
        {
            var camera = new GameObject(name, typeof(Camera)).GetComponent<Camera>();
            camera.enabled = false;
            return camera;
        }

        static DatasetSettings Settings(string camera)
        {
            var settings = new DatasetSettings { Name = "template", Width = 16, Height = 16, Distance = 3 };
            settings.Camera.CopyFromCamera = camera;
            return settings;
        }

        [Test]
        public void ATemplateThatCullsEveryTargetLayerIsRefusedAndOneThatCullsSomeIsAWarning()
        {
            var target = GameObject.CreatePrimitive(PrimitiveType.Sphere);
            var child = GameObject.CreatePrimitive(PrimitiveType.Cube);
            child.transform.SetParent(target.transform, false);
            child.layer = 8;
            var camera = Template("Culling template");

            camera.cullingMask = ~(1 << 8); // the child's layer only
            var some = DatasetCapture.Prepare(Settings(camera.name), target, _project);
            Assert.That(some.Problems.Where(p => p.Field == "camera.copyFromCamera"), Is.Empty);
            Assert.That(some.Warnings.Single(p => p.Field == "camera.copyFromCamera").Reason, Does.Contain("(8)").And.Contain("1 of the target's 2 renderers"));

            camera.cullingMask = 1 << 5; // neither layer 0 nor 8
            var none = DatasetCapture.Prepare(Settings(camera.name), target, _project);
            Assert.That(none.IsValid, Is.False);
            Assert.That(none.Problems.Single(p => p.Field == "camera.copyFromCamera").Reason, Does.Contain("every image would be empty"));
        }

        [Test]
        public void APhysicalTemplatesGateFitIsReproducedInTheWrittenFieldOfView()
        {
            var target = GameObject.CreatePrimitive(PrimitiveType.Sphere);
            var camera = Template("Physical template");
            camera.usePhysicalProperties = true;
            camera.focalLength = 50;
            camera.sensorSize = new Vector2(36, 24);
            camera.lensShift = Vector2.zero;

            // A square image with Horizontal fit: the sensor's 36 mm span the width, 2·atan(18/50) = 39.5978° (Core's hand-derived value).
            camera.gateFit = Camera.GateFitMode.Horizontal;
            var horizontal = DatasetCapture.Prepare(Settings(camera.name), target, _project);
            Assert.That(horizontal.Problems.Select(p => p.ToString()), Is.Empty);
            Assert.That(horizontal.Plan.Settings.Camera.VerticalFovDegrees, Is.EqualTo(39.597752709049864).Within(1e-4));
            Assert.That(camera.fieldOfView, Is.EqualTo(26.9915f).Within(1e-3f), "Unity's own fieldOfView is the Vertical fit's, which would have been wrong");

            camera.gateFit = Camera.GateFitMode.None; // stretches a 3:2 sensor onto a square image
            Assert.That(DatasetCapture.Prepare(Settings(camera.name), target, _project).Problems.Single(p => p.Field == "camera.copyFromCamera").Reason,
                Does.Contain("not square"));

            camera.gateFit = Camera.GateFitMode.Vertical;
            camera.lensShift = new Vector2(0.1f, 0);
            Assert.That(DatasetCapture.Prepare(Settings(camera.name), target, _project).Problems.Single(p => p.Field == "camera.copyFromCamera").Reason,
                Does.Contain("shifts the lens"));
            Object.DestroyImmediate(camera.gameObject);
        }
    }
}
