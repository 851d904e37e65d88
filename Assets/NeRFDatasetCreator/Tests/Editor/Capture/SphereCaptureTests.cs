using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Renders Unity's primitive sphere (radius r = 0.5 at unit scale) from 8 cameras at distance d looking at its
    /// centre, 64×64 with 2× supersampling, and checks the pixels against the geometry: empty corners, covered
    /// centre, eye depth d − r, normal facing the camera, the sphere where the pose and intrinsics put it.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class SphereCaptureTests
    {
        const double Radius = 0.5;
        const double Distance = 3.0;
        const int Size = 64;
        const int Supersampling = 2;
        const double FovDegrees = 40.0;

        Scene _scene;
        GameObject _sphere;

        [SetUp]
        public void SetUp()
        {
            TestScene.RequireRendering();
            // A scene of our own, next to whatever the user has open, and closed again in TearDown.
            _scene = TestScene.Open();
            _sphere = TestScene.LitSphere("Test sphere");
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
        }

        static CaptureOptions Options() => new CaptureOptions
        {
            Width = Size,
            Height = Size,
            Supersampling = Supersampling,
            VerticalFieldOfViewDegrees = FovDegrees,
            NearClip = 0.1,
            FarClip = 100,
            ReadbacksInFlight = 3,
        };

        /// <summary>8 cameras at distance d around the origin: 4 on the equator, 2 above, 2 below.</summary>
        static List<UnityPose> Poses(Vector3d target)
        {
            var poses = new List<UnityPose>();
            double[] elevations = { 0, 0, 0, 0, 35, 35, -35, -35 };
            for (var i = 0; i < 8; i++)
            {
                var azimuth = i * Math.PI / 4 + 0.1;
                var elevation = elevations[i] * Math.PI / 180;
                var direction = new Vector3d(Math.Cos(elevation) * Math.Cos(azimuth), Math.Sin(elevation), Math.Cos(elevation) * Math.Sin(azimuth));
                poses.Add(LookAt.FromPositions(target + Distance * direction, target));
            }
            return poses;
        }

        RecordingConsumer Capture(CaptureOptions options, List<UnityPose> poses)
        {
            var consumer = new RecordingConsumer();
            CaptureRunner.RunBlocking(_sphere, poses, options, consumer, new ScriptedProgress());
            return consumer;
        }

        [Test]
        public void EveryViewIsDeliveredInOrderWithItsPoseAndSizes()
        {
            var poses = Poses(Vector3d.Zero);
            var consumer = Capture(Options(), poses);
            Assert.That(consumer.Finished, Is.True);
            Assert.That(consumer.Aborted, Is.False);
            Assert.That(consumer.Views, Has.Count.EqualTo(8));
            for (var i = 0; i < 8; i++)
            {
                var view = consumer.Views[i];
                Assert.That(view.ViewIndex, Is.EqualTo(i));
                Assert.That(view.Pose.Position, Is.EqualTo(poses[i].Position));
                Assert.That(view.Width, Is.EqualTo(Size * Supersampling));
                Assert.That(view.OverBlack, Has.Length.EqualTo(Size * Supersampling * Size * Supersampling * 4));
                Assert.That(view.OverWhite, Has.Length.EqualTo(Size * Supersampling * Size * Supersampling * 4));
                Assert.That(view.Mask, Has.Length.EqualTo(Size * Supersampling * Size * Supersampling));
                Assert.That(view.Depth, Has.Length.EqualTo(Size * Size));
                Assert.That(view.Normal, Has.Length.EqualTo(Size * Size * 4));
            }
        }

        [TestCase(false)]
        [TestCase(true)]
        public void CornersAreEmptyAndTheCentreIsCovered(bool synchronous)
        {
            var options = Options();
            options.ForceSynchronousReadback = synchronous;
            var consumer = Capture(options, Poses(Vector3d.Zero));
            var w = Size * Supersampling;
            foreach (var view in consumer.Views)
            {
                foreach (var (x, y) in new[] { (0, 0), (w - 1, 0), (0, w - 1), (w - 1, w - 1) })
                {
                    Assert.That(view.MaskAt(x, y), Is.EqualTo(0), $"view {view.ViewIndex} corner ({x},{y}) mask");
                    for (var c = 0; c < 3; c++)
                    {
                        Assert.That(view.OverBlackAt(x, y, c), Is.EqualTo(0f), $"view {view.ViewIndex} corner ({x},{y}) colour over black");
                        Assert.That(view.OverWhiteAt(x, y, c), Is.EqualTo(1f), $"view {view.ViewIndex} corner ({x},{y}) colour over white");
                    }
                    Assert.That(view.DepthAt(x * Size / w, y * Size / w), Is.EqualTo(0f), "no geometry → depth 0");
                }
                Assert.That(view.MaskAt(w / 2, w / 2), Is.EqualTo(255), $"view {view.ViewIndex} centre mask");
                Assert.That(view.AlphaAt(w / 2, w / 2), Is.EqualTo(1f).Within(1e-3), $"view {view.ViewIndex} centre alpha (opaque sphere)");
            }
        }

        [Test]
        public void CentreDepthIsDistanceMinusRadius()
        {
            var consumer = Capture(Options(), Poses(Vector3d.Zero));
            foreach (var view in consumer.Views)
            {
                // The pixel at (32, 32) is half a pixel off the optical axis: its ray meets the sphere within far
                // less than 1 % of d − r, as does the tessellated sphere's surface.
                var depth = view.DepthAt(Size / 2, Size / 2);
                Assert.That(depth, Is.EqualTo(Distance - Radius).Within(0.01 * (Distance - Radius)), $"view {view.ViewIndex}");
            }
        }

        [Test]
        public void CentreNormalPointsBackAtTheCamera()
        {
            var consumer = Capture(Options(), Poses(Vector3d.Zero));
            foreach (var view in consumer.Views)
            {
                var normal = view.NormalAt(Size / 2, Size / 2, out var coverage);
                Assert.That(coverage, Is.EqualTo(1f), "normal alpha = coverage");
                Assert.That(normal.Length, Is.EqualTo(1.0).Within(1e-3), "unit length");
                var towardsCamera = view.Pose.Position.Normalized(); // the sphere is at the origin
                Assert.That(Vector3d.Dot(normal, towardsCamera), Is.GreaterThan(0.99), $"view {view.ViewIndex}");
            }
        }

        /// <summary>
        /// The images agree with the plan's matrices: a small sphere away from the look-at point appears where the
        /// output camera-to-world matrix (BlenderConvention) and the intrinsics (CameraIntrinsics) project it, using
        /// NeRF's camera model (OpenGL axes, image rows downwards) — in the mask (drawn by the data-pass command
        /// buffer) and in the colour's alpha (drawn by the camera) alike, so a flip or shift of either shows.
        /// </summary>
        [Test]
        public void TheSphereAppearsWhereThePlansMatrixAndIntrinsicsProjectIt()
        {
            var centre = new Vector3d(0.4, 0.25, -0.3);
            _sphere.transform.position = centre.ToVector3();
            _sphere.transform.localScale = Vector3.one * 0.1f;
            var options = Options();
            var poses = Poses(Vector3d.Zero);
            var consumer = Capture(options, poses);
            var w = Size * Supersampling;
            var intrinsics = CameraIntrinsics.FromVerticalFov(FovDegrees, w, w);
            foreach (var view in consumer.Views)
            {
                var c2w = BlenderConvention.CameraToWorld(poses[view.ViewIndex]);
                var p = c2w.InverseRigid().MultiplyPoint(BlenderConvention.FromUnity(centre));
                var expectedX = intrinsics.Cx + intrinsics.FlX * p.X / -p.Z;
                var expectedRowFromTop = intrinsics.Cy - intrinsics.FlY * p.Y / -p.Z;

                double sumX = 0, sumY = 0, count = 0, alphaX = 0, alphaY = 0, alphaSum = 0;
                for (var y = 0; y < w; y++)
                for (var x = 0; x < w; x++)
                {
                    var alpha = Math.Max(0, Math.Min(1, view.AlphaAt(x, y)));
                    alphaX += alpha * (x + 0.5);
                    alphaY += alpha * (w - (y + 0.5)); // rows are bottom-up
                    alphaSum += alpha;
                    if (view.MaskAt(x, y) == 0) continue;
                    sumX += x + 0.5;
                    sumY += w - (y + 0.5);
                    count++;
                }
                Assert.That(count, Is.GreaterThan(10), $"view {view.ViewIndex} sees the sphere");
                Assert.That(sumX / count, Is.EqualTo(expectedX).Within(1.0), $"view {view.ViewIndex} mask column");
                Assert.That(sumY / count, Is.EqualTo(expectedRowFromTop).Within(1.0), $"view {view.ViewIndex} mask row");
                Assert.That(alphaSum, Is.GreaterThan(10), $"view {view.ViewIndex} colour sees the sphere");
                Assert.That(alphaX / alphaSum, Is.EqualTo(expectedX).Within(1.0), $"view {view.ViewIndex} colour column");
                Assert.That(alphaY / alphaSum, Is.EqualTo(expectedRowFromTop).Within(1.0), $"view {view.ViewIndex} colour row");
            }
        }

        /// <summary>
        /// A template camera lends its field of view and clip planes, not its projection mode or viewport: an
        /// orthographic split-screen template still gives the full-frame pinhole images of the built-in camera.
        /// </summary>
        [Test]
        public void AnOrthographicSplitScreenTemplateStillRendersTheFullPinholeView()
        {
            var template = new GameObject("Test template camera", typeof(Camera)).GetComponent<Camera>();
            template.enabled = false;
            template.fieldOfView = (float)FovDegrees;
            template.nearClipPlane = 0.1f;
            template.farClipPlane = 100f;
            template.orthographic = true;
            template.orthographicSize = 0.2f;
            template.rect = new Rect(0f, 0f, 0.5f, 0.5f);
            var options = Options();
            options.TemplateCamera = template;
            var withTemplate = Capture(options, Poses(Vector3d.Zero));
            var builtIn = Capture(Options(), Poses(Vector3d.Zero));
            for (var i = 0; i < builtIn.Views.Count; i++)
            {
                Assert.That(withTemplate.Views[i].Mask, Is.EqualTo(builtIn.Views[i].Mask), $"view {i} mask");
                Assert.That(withTemplate.Views[i].Depth, Is.EqualTo(builtIn.Views[i].Depth), $"view {i} depth");
            }
        }

        /// <summary>
        /// An unlit colour is stored as its sRGB bytes: in a Linear project the GPU encodes the linearised colour back
        /// to sRGB, in a Gamma project the value passes unchanged. Running this in either kind of project checks that
        /// both write the same bytes (within 1 LSB).
        /// </summary>
        [Test]
        public void UnlitColourIsWrittenAsItsSrgbBytesInThisColourSpace()
        {
            var shader = Shader.Find("Unlit/Color");
            Assume.That(shader, Is.Not.Null, "Unity's built-in Unlit/Color shader");
            var material = new Material(shader) { color = new Color32(200, 100, 50, 255) };
            try
            {
                _sphere.GetComponent<Renderer>().sharedMaterial = material;
                var consumer = Capture(Options(), Poses(Vector3d.Zero));
                var w = Size * Supersampling;
                foreach (var view in consumer.Views)
                {
                    Assert.That(view.ColorAt(w / 2, w / 2, 0), Is.EqualTo(200).Within(1), QualitySettings.activeColorSpace + " red");
                    Assert.That(view.ColorAt(w / 2, w / 2, 1), Is.EqualTo(100).Within(1), QualitySettings.activeColorSpace + " green");
                    Assert.That(view.ColorAt(w / 2, w / 2, 2), Is.EqualTo(50).Within(1), QualitySettings.activeColorSpace + " blue");
                }
            }
            finally
            {
                Object.DestroyImmediate(material);
            }
        }

        /// <summary>
        /// The threaded path end to end: every view's raw passes are encoded with ImageConversion on worker threads
        /// and written (PNG signature, EXR magic number): RawPassWriter's five files per view — the two colour
        /// renders, the mask, depth and normals.
        /// </summary>
        [Test]
        public void EveryViewsFilesAreWrittenByTheWorkerThreads()
        {
            var folder = Path.Combine(Path.GetTempPath(), "NerfCaptureTest_" + Guid.NewGuid().ToString("N"));
            try
            {
                using (var consumer = new ParallelViewConsumer(new RawPassWriter(folder), 2, 2))
                    CaptureRunner.RunBlocking(_sphere, Poses(Vector3d.Zero), Options(), consumer, new ScriptedProgress());
                for (var i = 0; i < 8; i++)
                {
                    var stem = Path.Combine(folder, "view_" + i.ToString("0000"));
                    var png = File.ReadAllBytes(stem + "_mask.png");
                    Assert.That(png.Take(8), Is.EqualTo(new byte[] { 137, 80, 78, 71, 13, 10, 26, 10 }), stem + "_mask.png");
                    foreach (var exr in new[] { stem + "_color_over_black.exr", stem + "_color_over_white.exr", stem + "_depth.exr", stem + "_normal.exr" })
                        Assert.That(File.ReadAllBytes(exr).Take(4), Is.EqualTo(new byte[] { 0x76, 0x2f, 0x31, 0x01 }), exr);
                }
                Assert.That(Directory.GetFiles(folder), Has.Length.EqualTo(8 * 5));
            }
            finally
            {
                if (Directory.Exists(folder)) Directory.Delete(folder, true);
            }
        }

        [Test]
        public void ACaptureLeavesTheScenesExactlyAsTheyWere()
        {
            var before = SceneSnapshot.Take();
            Capture(Options(), Poses(Vector3d.Zero));
            Assert.That(SceneSnapshot.Lines(SceneSnapshot.Take()), Is.EqualTo(SceneSnapshot.Lines(before)));
        }

        [Test]
        public void ACancelledCaptureStopsAbortsTheConsumerAndRestoresTheScenes()
        {
            var before = SceneSnapshot.Take();
            var consumer = new RecordingConsumer();
            var progress = new ScriptedProgress { CancelAfterViews = 1 };
            var options = Options();
            options.ReadbacksInFlight = 1;
            Assert.Throws<CaptureCancelledException>(() =>
                CaptureRunner.RunBlocking(_sphere, Poses(Vector3d.Zero), options, consumer, progress));
            Assert.That(consumer.Aborted, Is.True, "the consumer drops its pending work (no dataset is published)");
            Assert.That(consumer.Finished, Is.False);
            Assert.That(consumer.Views.Count, Is.LessThan(8));
            Assert.That(progress.Closed, Is.True);
            Assert.That(SceneSnapshot.Lines(SceneSnapshot.Take()), Is.EqualTo(SceneSnapshot.Lines(before)));
        }

        [Test]
        public void AWriterErrorStopsTheCaptureWithAClearMessage()
        {
            var before = SceneSnapshot.Take();
            using (var consumer = new ParallelViewConsumer(new FailingWriter(), 1, 1))
            {
                var e = Assert.Throws<CaptureException>(() =>
                    CaptureRunner.RunBlocking(_sphere, Poses(Vector3d.Zero), Options(), consumer, new ScriptedProgress()));
                Assert.That(e.Message, Does.Contain("No space left on device"));
                Assert.That(e.Message, Does.Contain("free space"));
            }
            Assert.That(SceneSnapshot.Lines(SceneSnapshot.Take()), Is.EqualTo(SceneSnapshot.Lines(before)));
        }

        [Test]
        public void DeletingTheTargetMidRunStopsTheCapture()
        {
            var progress = new ScriptedProgress();
            progress.OnReport = meter =>
            {
                if (meter.Done == 1 && _sphere != null) Object.DestroyImmediate(_sphere);
            };
            var consumer = new RecordingConsumer();
            var options = Options();
            options.ReadbacksInFlight = 1;
            var e = Assert.Throws<CaptureException>(() =>
                CaptureRunner.RunBlocking(_sphere, Poses(Vector3d.Zero), options, consumer, progress));
            Assert.That(e.Message, Does.Contain("was deleted during the capture"));
            Assert.That(consumer.Aborted, Is.True);
            Assert.That(consumer.Views.Count, Is.LessThan(8));
        }

        [Test]
        public void ATargetWithoutRenderersIsRefusedBeforeAnythingIsCreated()
        {
            var empty = new GameObject("Empty target");
            var before = SceneSnapshot.Take();
            var e = Assert.Throws<CaptureException>(() =>
                CaptureRunner.RunBlocking(empty, Poses(Vector3d.Zero), Options(), new RecordingConsumer(), new ScriptedProgress()));
            Assert.That(e.Message, Does.Contain("Empty target"));
            Assert.That(e.Message, Does.Contain("no enabled MeshRenderer"));
            Assert.That(SceneSnapshot.Lines(SceneSnapshot.Take()), Is.EqualTo(SceneSnapshot.Lines(before)));
        }

        sealed class FailingWriter : IViewWriter
        {
            public void Write(CapturedView view) => throw new IOException("No space left on device");
        }
    }
}
