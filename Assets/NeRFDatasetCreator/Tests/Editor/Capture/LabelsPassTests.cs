using System;
using System.Collections.Generic;
using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// The labels pass draws each renderer's ids exactly: two quads side by side in front of a larger one, with ids that
    /// need both bytes (7, 300, 513). Every sample's expected id comes from the pinhole model alone (the nearest quad the
    /// sample's ray meets), the ids cover exactly the mask's samples, and they are the same in two captures and wherever
    /// a dynamic capture moves an object between views.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class LabelsPassTests : GpuSceneFixture
    {
        const int Size = 48;
        const int K = 2;
        const double FovDegrees = 60.0;
        const double Distance = 2.0;

        static readonly RendererLabelIds LeftIds = new RendererLabelIds(7, 1);
        static readonly RendererLabelIds RightIds = new RendererLabelIds(300, 2);
        static readonly RendererLabelIds BackIds = new RendererLabelIds(513, 3);

        GameObject _pair;
        Dictionary<Renderer, RendererLabelIds> _labels;

        /// <summary>Quads (Unity's primitive: 1 × 1 in its x-y plane, front towards −Z) at x = ∓0.6, z = 0 and a 4 × 4 one at z = 1.</summary>
        [SetUp]
        public void MakePair()
        {
            _pair = new GameObject("Pair");
            var left = Quad("Left", new Vector3(-0.6f, 0, 0), 1);
            var right = Quad("Right", new Vector3(0.6f, 0, 0), 1);
            var back = Quad("Back", new Vector3(0, 0, 1), 4);
            var light = new GameObject("Pair light", typeof(Light));
            light.GetComponent<Light>().type = LightType.Directional;
            _labels = new Dictionary<Renderer, RendererLabelIds>
            {
                [left.GetComponent<Renderer>()] = LeftIds,
                [right.GetComponent<Renderer>()] = RightIds,
                [back.GetComponent<Renderer>()] = BackIds,
            };
        }

        GameObject Quad(string name, Vector3 position, float scale)
        {
            var quad = GameObject.CreatePrimitive(PrimitiveType.Quad);
            quad.name = name;
            quad.transform.SetParent(_pair.transform, false);
            quad.transform.localPosition = position;
            quad.transform.localScale = new Vector3(scale, scale, 1);
            return quad;
        }

        CaptureOptions Options(Action<GameObject, int> beforeView = null) => new CaptureOptions
        {
            Width = Size,
            Height = Size,
            Supersampling = K,
            Passes = CapturePasses.Color | CapturePasses.Mask,
            VerticalFieldOfViewDegrees = FovDegrees,
            NearClip = 0.1,
            FarClip = 100,
            ReadbacksInFlight = 1,
            Labels = _labels,
            BeforeView = beforeView,
        };

        List<RecordedView> Capture(int views, Action<GameObject, int> beforeView = null)
        {
            var consumer = new RecordingConsumer();
            var poses = new List<UnityPose>();
            for (var i = 0; i < views; i++) poses.Add(LookAt.FromPositions(new Vector3d(0, 0, -Distance), Vector3d.Zero));
            CaptureRunner.RunBlocking(_pair, poses, Options(beforeView), consumer, new ScriptedProgress());
            Assert.That(consumer.Views, Has.Count.EqualTo(views));
            foreach (var view in consumer.Views) Assert.That(view.Labels, Is.Not.Null, "the labels pass ran");
            return consumer.Views;
        }

        /// <summary>
        /// The id the pinhole model puts at sample (sx, sy) (row from the bottom) with the right quad at x = rightX, or
        /// null within a sample's width of an edge, where rasterisation rules decide. The camera is at (0, 0, −d) looking
        /// +Z with +Y up, so the world ray of a sample is ((sx + ½ − W/2)/f, (sy + ½ − H/2)/f, 1).
        /// </summary>
        static int? Expected(int sx, int sy, double rightX)
        {
            double w = Size * K, f = w / 2 / Math.Tan(FovDegrees * Math.PI / 360);
            double dx = (sx + 0.5 - w / 2) / f, dy = (sy + 0.5 - w / 2) / f;
            var margin = 1.5 / f * 3; // 1.5 samples at the farthest quad (distance 3)
            int? Hit(double z, double cx, double half, int id)
            {
                double x = dx * (z + Distance), y = dy * (z + Distance);
                var inside = Math.Max(Math.Abs(x - cx), Math.Abs(y)) - half;
                if (Math.Abs(inside) < margin) return null;
                return inside < 0 ? id : 0;
            }
            foreach (var (z, cx, half, id) in new[] { (0.0, -0.6, 0.5, 7), (0.0, rightX, 0.5, 300), (1.0, 0.0, 2.0, 513) })
            {
                var hit = Hit(z, cx, half, id);
                if (hit == null) return null;
                if (hit.Value != 0) return hit;
            }
            return 0;
        }

        static void AssertIdsMatchTheProjection(RecordedView view, double rightX, string what)
        {
            var checkedSamples = new Dictionary<int, int>();
            for (var y = 0; y < view.Height; y++)
            for (var x = 0; x < view.Width; x++)
            {
                var expected = Expected(x, y, rightX);
                if (expected == null) continue;
                var actual = view.InstanceAt(x, y);
                if (actual != expected.Value)
                    Assert.Fail(what + ": sample (" + x + ", " + y + ") holds id " + actual + " where the object projected there has id " + expected.Value);
                checkedSamples[actual] = checkedSamples.TryGetValue(actual, out var n) ? n + 1 : 1;
            }
            // Every object (and the background) was seen by many samples, so the test cannot pass on an empty image.
            foreach (var id in new[] { 0, 7, 300, 513 })
                Assert.That(checkedSamples.TryGetValue(id, out var count) ? count : 0, Is.GreaterThan(50), what + ": samples of id " + id);
        }

        [Test]
        public void EachSampleHoldsTheIdsOfTheObjectProjectedThere()
        {
            var view = Capture(1)[0];
            Assert.That(view.Width, Is.EqualTo(Size * K), "the labels pass is read back at the supersampled size");
            AssertIdsMatchTheProjection(view, 0.6, "view 0");
            // The class ids travel with the instance ids, byte for byte.
            for (var i = 0; i < view.Width * view.Height; i++)
            {
                var instance = RendererLabelIds.InstanceAt(view.Labels, i);
                var classId = RendererLabelIds.ClassAt(view.Labels, i);
                var expectedClass = instance == 7 ? 1 : instance == 300 ? 2 : instance == 513 ? 3 : 0;
                Assert.That(classId, Is.EqualTo(expectedClass), "class of sample " + i + " (instance " + instance + ")");
            }
        }

        [Test]
        public void TheIdsCoverExactlyTheMasksSamples()
        {
            var view = Capture(1)[0];
            for (var i = 0; i < view.Width * view.Height; i++)
                Assert.That(RendererLabelIds.InstanceAt(view.Labels, i) != 0, Is.EqualTo(view.Mask[i] == 255),
                    "sample " + i + ": mask " + view.Mask[i] + ", instance " + RendererLabelIds.InstanceAt(view.Labels, i));
        }

        [Test]
        public void TwoCapturesOfTheSameSceneGiveTheSameIds()
        {
            var first = Capture(1)[0];
            var second = Capture(1)[0];
            Assert.That(second.Labels, Is.EqualTo(first.Labels));
        }

        [Test]
        public void AnObjectMovedBetweenViewsKeepsItsIds()
        {
            // A dynamic capture poses the copies before each view (CaptureOptions.BeforeView, as ContentClock does).
            var views = Capture(2, (root, index) => root.transform.Find("Pair/Right").localPosition = new Vector3(index == 0 ? 0.6f : 0.9f, 0, 0));
            AssertIdsMatchTheProjection(views[0], 0.6, "time step 0");
            AssertIdsMatchTheProjection(views[1], 0.9, "time step 1");
            Assert.That(views[1].Labels, Is.Not.EqualTo(views[0].Labels), "the object did move");
        }

        [Test]
        public void WithoutLabelsThereIsNoLabelsPass()
        {
            var consumer = new RecordingConsumer();
            var options = Options();
            options.Labels = null;
            CaptureRunner.RunBlocking(_pair, new List<UnityPose> { LookAt.FromPositions(new Vector3d(0, 0, -Distance), Vector3d.Zero) }, options, consumer, new ScriptedProgress());
            Assert.That(consumer.Views[0].Labels, Is.Null);
            Assert.That(options.EffectivePasses & CapturePasses.Labels, Is.EqualTo(CapturePasses.None));
        }
    }
}
