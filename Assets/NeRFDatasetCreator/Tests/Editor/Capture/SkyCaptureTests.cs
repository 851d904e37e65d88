using System.Collections.Generic;
using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// The opaque sky of an environment capture (<see cref="CaptureOptions.Skybox"/>): the colour pass renders once with
    /// the skybox and that image is both halves of the matting pair, so every sample is opaque and shows the sky. One
    /// camera 3 units in front of a small cube, looking level along +Z, 32×32 at k = 2; Unity's built-in
    /// Skybox/Procedural shader (drawn by the Built-in pipeline and URP).
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class SkyCaptureTests : GpuSceneFixture
    {
        const int Size = 32, K = 2, W = Size * K;

        Material Sky()
        {
            var shader = Shader.Find("Skybox/Procedural");
            Assume.That(shader, Is.Not.Null, "Unity's built-in Skybox/Procedural shader");
            return Own(new Material(shader));
        }

        RecordedView Capture(Material sky)
        {
            var cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
            cube.transform.localScale = Vector3.one * 0.2f;
            var options = new CaptureOptions
            {
                Width = Size, Height = Size, Supersampling = K, VerticalFieldOfViewDegrees = 40, NearClip = 0.1, FarClip = 100,
                Passes = CapturePasses.Color, Skybox = sky,
            };
            var consumer = new RecordingConsumer();
            var poses = new List<UnityPose> { LookAt.FromPositions(new Vector3d(0, 0, -3), Vector3d.Zero) };
            CaptureRunner.RunBlocking(cube, poses, options, consumer, new ScriptedProgress());
            Assert.That(consumer.Views, Has.Count.EqualTo(1));
            return consumer.Views[0];
        }

        [Test]
        public void WithASkyEverySampleIsOpaqueAndTheSkyIsInTheColour()
        {
            var view = Capture(Sky());
            for (var y = 0; y < W; y++)
            for (var x = 0; x < W; x++)
                Assert.That(view.AlphaAt(x, y), Is.EqualTo(1f), "sample " + x + ", " + y + ": the two halves are one render");
            // Level camera, 40° field of view: the top row looks 20° above the horizon, the bottom row 20° below it;
            // the procedural sky is lit above and its ground colour below, so they differ and the corner is not black.
            float Brightness(int x, int y) => view.OverBlackAt(x, y, 0) + view.OverBlackAt(x, y, 1) + view.OverBlackAt(x, y, 2);
            Assert.That(Brightness(0, 0), Is.GreaterThan(0.01f), "the sky shows where there is no content");
            Assert.That(Brightness(0, 0), Is.Not.EqualTo(Brightness(0, W - 1)).Within(1e-3f), "sky above, ground colour below");
        }

        [Test]
        public void WithoutASkyTheCornerIsStillTransparent()
        {
            var view = Capture(null);
            Assert.That(view.AlphaAt(0, 0), Is.EqualTo(0f).Within(1e-3f));
            Assert.That(view.AlphaAt(W / 2, W / 2), Is.EqualTo(1f).Within(1e-3f), "the cube");
        }
    }
}
