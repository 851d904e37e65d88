using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// A lens capture renders Core's wide pinhole (<see cref="LensCapture.WideRender"/>): the capture options take its size
    /// and vertical field of view, the capture camera's projection is that pinhole (focal on both axes, centred), and a
    /// GPU capture through the lens writes distorted images that pass the self-check with the written lens.
    /// </summary>
    [TestFixture]
    public class LensWideRenderTests
    {
        Scene _scene;
        string _project;

        static DatasetSettings Settings()
        {
            var settings = new DatasetSettings { Name = "lens", Width = 64, Height = 48, Supersampling = 2, Distance = 2.2, PointCloudPoints = 2000 };
            settings.Camera.VerticalFovDegrees = 60;
            settings.Lens = new LensSettings { Model = "opencv", K1 = -0.2, K2 = 0.04, P1 = 0.002, P2 = -0.001 };
            settings.Train.Count = 8;
            settings.Val.Count = 2;
            settings.Test.Count = 4;
            foreach (var split in new[] { settings.Train, settings.Val, settings.Test })
            {
                split.Depth = ExtraOutput.Png;
                split.Normal = ExtraOutput.Png;
                split.Mask = true;
            }
            return settings;
        }

        [SetUp]
        public void SetUp()
        {
            _scene = TestScene.Open();
            _project = Path.Combine(Path.GetTempPath(), "nerf-lens-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_project);
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
            if (_project != null && Directory.Exists(_project)) Directory.Delete(_project, true);
        }

        [Test]
        public void TheOptionsAndTheCameraAreTheWidePinhole()
        {
            var settings = Settings();
            var wide = LensCapture.WideRender(settings.Lens.ToDistortion(), settings.Intrinsics());
            var options = new NerfDatasetCreator.Editor.CaptureOptions { Width = settings.Width, Height = settings.Height, Supersampling = 2, VerticalFieldOfViewDegrees = 60 };
            LensOptions.Apply(settings, options);
            Assert.That(options.Width, Is.EqualTo(wide.Width));
            Assert.That(options.Height, Is.EqualTo(wide.Height));
            Assert.That(options.Width, Is.GreaterThan(settings.Width), "a barrel lens sees more than its pinhole frame");
            Assert.That(options.WideVerticalFieldOfViewDegrees, Is.EqualTo(wide.VerticalFovDegrees));
            Assert.That(options.SupersampledWidth, Is.EqualTo(wide.Width * 2), "the render textures are the wide render × k");
            Assert.That(options.DataWidth, Is.EqualTo(wide.Width * 2), "data passes at the supersampled size under a lens");
            Assert.That(options.Validate(), Is.Empty);

        }

        /// <summary>
        /// One view of Unity's sphere (radius 0.5) from 2.2 units on the axis: the rendered textures are the wide render
        /// × k, and the sphere's silhouette in the mask has the radius the wide pinhole's focal gives,
        /// f·R/√(D² − R²) — with the output's field of view instead it would be ~25 % smaller.
        /// </summary>
        [Test]
        [Category("GPU")]
        public void TheWideRenderHasItsSizeAndFocal()
        {
            TestScene.RequireRendering();
            var sphere = TestScene.LitSphere("Lens focal sphere");
            var settings = Settings();
            var wide = LensCapture.WideRender(settings.Lens.ToDistortion(), settings.Intrinsics());
            var options = new NerfDatasetCreator.Editor.CaptureOptions
            {
                Width = settings.Width, Height = settings.Height, Supersampling = 2, VerticalFieldOfViewDegrees = 60,
                Passes = NerfDatasetCreator.Editor.CapturePasses.Color | NerfDatasetCreator.Editor.CapturePasses.Mask,
            };
            LensOptions.Apply(settings, options);
            const double distance = 2.2, radius = 0.5;
            var poses = new System.Collections.Generic.List<UnityPose> { LookAt.FromPositions(new Vector3d(0, 0, -distance), Vector3d.Zero) };
            var consumer = new RecordingConsumer();
            NerfDatasetCreator.Editor.CaptureRunner.RunBlocking(sphere, poses, options, consumer, new SilentProgress());
            var view = consumer.Views.Single();
            Assert.That(view.Width, Is.EqualTo(wide.Width * 2));
            Assert.That(view.Height, Is.EqualTo(wide.Height * 2));
            var covered = view.Mask.Sum(m => m / 255.0); // samples
            var measured = Math.Sqrt(covered / Math.PI) / 2; // wide-render pixels
            var expected = wide.Focal * radius / Math.Sqrt(distance * distance - radius * radius);
            // Unity's sphere is a 24-sided UV sphere: its silhouette's area is up to ~1.2 % below the true sphere's.
            Assert.That(measured, Is.EqualTo(expected).Within(0.02 * expected), "silhouette radius in wide pixels");
        }

        [Test]
        public void WithoutALensNothingChanges()
        {
            var settings = Settings();
            settings.Lens = new LensSettings();
            var options = new NerfDatasetCreator.Editor.CaptureOptions { Width = 64, Height = 48 };
            LensOptions.Apply(settings, options);
            Assert.That(options.Width, Is.EqualTo(64));
            Assert.That(options.WideVerticalFieldOfViewDegrees, Is.Null);
            Assert.That(options.DepthAndNormalAtOutputSize, Is.True);
        }

        [Test]
        [Category("GPU")]
        public void ADistortedCaptureWritesTheLensAndPassesTheSelfCheck()
        {
            TestScene.RequireRendering();
            var sphere = TestScene.LitSphere("Lens test sphere");
            var prepared = DatasetCapture.Prepare(Settings(), sphere, _project);
            Assert.That(prepared.Problems.Select(p => p.ToString()), Is.Empty);
            var result = DatasetCapture.RunBlocking(prepared, new SilentProgress());
            Assert.That(result.Succeeded, Is.True, result.Message);
            var json = JObject.Parse(File.ReadAllText(Path.Combine(result.DatasetFolder, "transforms_train.json")));
            Assert.That((string)json["camera_model"], Is.EqualTo("OPENCV"));
            Assert.That((double)json["k1"], Is.EqualTo(-0.2));
            var png = PngReader.Read(Path.Combine(result.DatasetFolder, "train", "r_0.png"));
            Assert.That(png.Width, Is.EqualTo(64), "the images are the output size, not the wide render's");
            Assert.That(png.Height, Is.EqualTo(48));
            Assert.That(result.Check, Is.Not.Null);
            Assert.That(result.CheckFailed, Is.False, result.Message);
        }

        sealed class SilentProgress : NerfDatasetCreator.Editor.ICaptureProgress
        {
            public void Report(ThroughputMeter meter) { }
            public bool CancelRequested => false;
            public void Close() { }
        }
    }
}
