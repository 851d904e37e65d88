using System.Collections.Generic;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Alpha by difference matting for content the old mask-as-alpha got wrong: glass, particles, cutout holes. One
    /// camera 3 units in front of the origin, looking at it (+Z), 32×32 at k = 2. The materials use Unity's built-in
    /// untagged shaders (Unlit/Transparent, Unlit/Transparent Cutout, Unlit/Color), which the Built-in pipeline and URP
    /// (as SRPDefaultUnlit) both draw, so these tests need no particular pipeline.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class AlphaCaptureTests : GpuSceneFixture
    {
        const int Size = 32, K = 2, W = Size * K;

        RecordedView CaptureFront(GameObject target)
        {
            var options = new CaptureOptions
            {
                Width = Size, Height = Size, Supersampling = K, VerticalFieldOfViewDegrees = 40, NearClip = 0.1, FarClip = 100,
                Passes = CapturePasses.Color | CapturePasses.Mask,
            };
            var consumer = new RecordingConsumer();
            var poses = new List<UnityPose> { LookAt.FromPositions(new Vector3d(0, 0, -3), Vector3d.Zero) };
            CaptureRunner.RunBlocking(target, poses, options, consumer, new ScriptedProgress());
            Assert.That(consumer.Views, Has.Count.EqualTo(1));
            return consumer.Views[0];
        }

        Material Material(string shaderName)
        {
            var shader = Shader.Find(shaderName);
            Assume.That(shader, Is.Not.Null, "Unity's built-in " + shaderName + " shader");
            var material = new Material(shader);
            Own(material);
            return material;
        }

        Texture2D Texture(int width, Color32[] pixels)
        {
            var texture = new Texture2D(width, pixels.Length / width, TextureFormat.RGBA32, false) { filterMode = FilterMode.Point, wrapMode = TextureWrapMode.Clamp };
            texture.SetPixels32(pixels);
            texture.Apply();
            Own(texture);
            return texture;
        }

        [Test]
        public void ATransparentSphereIsPartlyTransparentInsideAndWholeInTheMask()
        {
            // Unlit/Transparent: Blend SrcAlpha OneMinusSrcAlpha, texture alpha 128/255 ≈ 0.502 (alpha is never sRGB-decoded).
            var sphere = GameObject.CreatePrimitive(PrimitiveType.Sphere);
            var glass = Material("Unlit/Transparent");
            glass.mainTexture = Texture(1, new[] { new Color32(255, 255, 255, 128) });
            sphere.GetComponent<MeshRenderer>().sharedMaterial = glass;

            var view = CaptureFront(sphere);
            var alpha = view.AlphaAt(W / 2, W / 2);
            Assert.That(alpha, Is.GreaterThan(0f).And.LessThan(1f), "glass: 0 < alpha < 1");
            Assert.That(alpha, Is.EqualTo(128f / 255f).Within(0.01f), "the material's own opacity");
            Assert.That(view.AlphaAt(0, 0), Is.EqualTo(0f).Within(1e-3f), "corner: nothing");
            Assert.That(view.MaskAt(W / 2, W / 2), Is.EqualTo(255), "the mask is the geometry, whatever its opacity");
        }

        [Test]
        public void ACutoutQuadsHolesAreTransparentAndItsSolidPartOpaque()
        {
            // A 2×1 point-sampled texture: left half alpha 0 (clipped at _Cutoff 0.5), right half alpha 255.
            var quad = GameObject.CreatePrimitive(PrimitiveType.Quad); // faces −Z: towards the camera
            var cutout = Material("Unlit/Transparent Cutout");
            cutout.mainTexture = Texture(2, new[] { new Color32(255, 255, 255, 0), new Color32(255, 255, 255, 255) });
            cutout.SetFloat("_Cutoff", 0.5f);
            quad.GetComponent<MeshRenderer>().sharedMaterial = cutout;

            var view = CaptureFront(quad);
            // The unit quad spans ±0.5 at distance 3 with a 40° vertical FOV: ±0.5/(3·tan 20°) = ±0.458 of the half-width.
            // The camera looks along +Z, so world +X is image right; texture u runs along the quad's +X.
            int left = W / 2 - W / 8, right = W / 2 + W / 8, row = W / 2;
            Assert.That(view.AlphaAt(left, row), Is.EqualTo(0f).Within(1e-3f), "the hole shows nothing");
            Assert.That(view.AlphaAt(right, row), Is.EqualTo(1f).Within(1e-3f), "the solid half is opaque");
        }

        [Test]
        public void AParticleSystemShowsInColourAndAlphaButNotInTheMask()
        {
            // The capture needs a mesh on the target: a small cube off to the side; the particle sits at the centre.
            var target = new GameObject("Particles target");
            var anchor = GameObject.CreatePrimitive(PrimitiveType.Cube);
            anchor.transform.SetParent(target.transform, false);
            anchor.transform.localPosition = new Vector3(0, -0.8f, 0);
            anchor.transform.localScale = Vector3.one * 0.1f;

            var particles = new GameObject("Particles", typeof(ParticleSystem)).GetComponent<ParticleSystem>();
            particles.transform.SetParent(target.transform, false);
            var main = particles.main;
            main.playOnAwake = false;
            main.simulationSpace = ParticleSystemSimulationSpace.Local;
            var emission = particles.emission;
            emission.enabled = false;
            var red = Material("Unlit/Color");
            red.color = Color.red;
            particles.GetComponent<ParticleSystemRenderer>().sharedMaterial = red;
            particles.Emit(new ParticleSystem.EmitParams
            {
                position = Vector3.zero, velocity = Vector3.zero, startSize = 0.6f, startLifetime = 1000f, applyShapeToPosition = false,
            }, 1);
            Assume.That(particles.particleCount, Is.EqualTo(1), "the source system holds the emitted particle");

            var view = CaptureFront(target);
            Assert.That(view.AlphaAt(W / 2, W / 2), Is.EqualTo(1f).Within(1e-3f), "an opaque particle is opaque in alpha");
            Assert.That(view.ColorAt(W / 2, W / 2, 0), Is.EqualTo(255).Within(1), "red");
            Assert.That(view.ColorAt(W / 2, W / 2, 1), Is.EqualTo(0).Within(1), "red");
            Assert.That(view.MaskAt(W / 2, W / 2), Is.EqualTo(0), "particles are not drawn by the data passes");
        }
    }
}
