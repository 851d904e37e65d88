using System;
using System.Collections.Generic;
using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// The material passes (issue 38) render a material's known base colour, metallic and roughness within one 8-bit code,
    /// in the pipeline the project runs: a Built-in Standard / Standard (Specular setup) material through
    /// NerfMaterial.shader's replacement pass, a URP Lit material through the Rendering Debugger's material modes; any
    /// other shader is listed unsupported and its samples are 0. A 1 × 1 quad fills the centre of a 60° view from 2 units,
    /// so the centre sample is the material's own value (no texture: the shaders' default white).
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class MaterialPassCaptureTests : GpuSceneFixture
    {
        const int Size = 32;
        static readonly Color SrgbColour = new Color(0.8f, 0.4f, 0.2f, 1f);

        static bool Urp => MaterialPassCapture.CurrentPipeline() == MaterialPipeline.Urp;

        static bool Linear => QualitySettings.activeColorSpace == ColorSpace.Linear;

        GameObject Quad(Material material)
        {
            var quad = GameObject.CreatePrimitive(PrimitiveType.Quad);
            quad.GetComponent<Renderer>().sharedMaterial = material;
            var light = new GameObject("Quad light", typeof(Light));
            light.GetComponent<Light>().type = LightType.Directional;
            return quad;
        }

        static (RecordedView View, CaptureSummary Summary) Capture(GameObject target, params MaterialPassKind[] passes)
        {
            var consumer = new RecordingConsumer();
            var options = new CaptureOptions
            {
                Width = Size, Height = Size, Supersampling = 1, Passes = CapturePasses.Color | CapturePasses.Mask,
                VerticalFieldOfViewDegrees = 60, NearClip = 0.1, FarClip = 100, ReadbacksInFlight = 1,
                MaterialPasses = passes,
            };
            var poses = new List<UnityPose> { LookAt.FromPositions(new Vector3d(0, 0, -2), Vector3d.Zero) };
            var summary = CaptureRunner.RunBlocking(target, poses, options, consumer, new ScriptedProgress());
            Assert.That(consumer.Views, Has.Count.EqualTo(1));
            Assert.That(consumer.Views[0].Materials, Is.Not.Null, "the material passes ran");
            return (consumer.Views[0], summary);
        }

        static int Centre => Size / 2 * Size + Size / 2;

        /// <summary>Within one 8-bit code of the sRGB encoding (colours) …</summary>
        static void AssertColour(float[] rgba, int sample, Color expectedLinear, string what)
        {
            for (var c = 0; c < 3; c++)
            {
                var got = Srgb.EncodeByteExact(rgba[4 * sample + c]);
                var expected = Srgb.EncodeByteExact(expectedLinear[c]);
                Assert.That(Math.Abs(got - expected), Is.LessThanOrEqualTo(1), what + " channel " + c + ": " + rgba[4 * sample + c] + " vs " + expectedLinear[c]);
            }
        }

        /// <summary>… and of the linear 8-bit code (scalars, as the PNGs store them).</summary>
        static void AssertScalar(float got, float expected, string what) =>
            Assert.That(Math.Abs(Math.Round(got * 255) - Math.Round(expected * 255)), Is.LessThanOrEqualTo(1), what + ": " + got + " vs " + expected);

        [Test]
        public void BuiltInStandardRendersItsKnownAlbedoMetallicAndRoughness()
        {
            if (Urp) Assert.Ignore("a Built-in pipeline test; this project runs URP");
            var material = Own(new Material(Shader.Find("Standard")));
            material.SetColor("_Color", SrgbColour);
            material.SetFloat("_Metallic", 0.5f);
            material.SetFloat("_Glossiness", 0.3f);
            var (view, summary) = Capture(Quad(material), MaterialPassKind.Albedo, MaterialPassKind.Metallic, MaterialPassKind.Smoothness);
            var m = view.Materials;
            Assert.That(m.Supported[Centre], Is.EqualTo(255));
            AssertColour(m.Albedo, Centre, SrgbColour.linear, "albedo");
            // Standard.shader:16 declares [Gamma] _Metallic: in a Linear project the shader (and its BRDF) sees the
            // slider's value linearised; that is the metallic the passes record.
            AssertScalar(m.Metallic[Centre], Linear ? Mathf.GammaToLinearSpace(0.5f) : 0.5f, "metallic");
            AssertScalar(m.Roughness[Centre], 0.7f, "roughness = 1 − smoothness");
            Assert.That(m.Supported[0], Is.EqualTo(0), "a corner sample misses the quad");
            Assert.That(m.Albedo[0] + m.Albedo[1] + m.Albedo[2] + m.Roughness[0], Is.EqualTo(0), "nothing where nothing is drawn");
            Assert.That(summary.Materials.Supported, Is.EqualTo(new[] { "Standard" }));
            Assert.That(summary.Materials.Unsupported, Is.Empty);
        }

        [Test]
        public void BuiltInStandardSpecularSetupRendersItsSpecularColourAndNoMetallic()
        {
            if (Urp) Assert.Ignore("a Built-in pipeline test; this project runs URP");
            var material = Own(new Material(Shader.Find("Standard (Specular setup)")));
            var specular = new Color(0.2f, 0.4f, 0.6f, 1f);
            material.SetColor("_Color", SrgbColour);
            material.SetColor("_SpecColor", specular);
            material.SetFloat("_Glossiness", 0.9f);
            var (view, _) = Capture(Quad(material), MaterialPassKind.Albedo, MaterialPassKind.Metallic, MaterialPassKind.Smoothness, MaterialPassKind.Specular);
            var m = view.Materials;
            AssertColour(m.Albedo, Centre, SrgbColour.linear, "albedo");
            AssertColour(m.Specular, Centre, specular.linear, "specular");
            Assert.That(m.Metallic[Centre], Is.EqualTo(0), "a specular setup has no metallic value");
            AssertScalar(m.Roughness[Centre], 0.1f, "roughness");
        }

        [Test]
        public void UrpLitRendersItsKnownAlbedoMetallicAndRoughness()
        {
            if (!Urp) Assert.Ignore("a URP test; this project runs the " + CaptureEnvironment.RenderPipelineName + " pipeline");
            var shader = Shader.Find("Universal Render Pipeline/Lit");
            if (shader == null) Assert.Ignore("URP's Lit shader is not in this project");
            var material = Own(new Material(shader));
            material.SetColor("_BaseColor", SrgbColour);
            material.SetFloat("_Metallic", 0.5f); // URP 14 Lit.shader:16: no [Gamma], the shader sees 0.5
            material.SetFloat("_Smoothness", 0.3f);
            var (view, summary) = Capture(Quad(material), MaterialPassKind.Albedo, MaterialPassKind.Metallic, MaterialPassKind.Smoothness);
            var m = view.Materials;
            Assert.That(m.Supported[Centre], Is.EqualTo(255));
            AssertColour(m.Albedo, Centre, SrgbColour.linear, "albedo");
            AssertScalar(m.Metallic[Centre], 0.5f, "metallic");
            AssertScalar(m.Roughness[Centre], 0.7f, "roughness = 1 − smoothness");
            Assert.That(summary.Materials.Supported, Is.EqualTo(new[] { "Universal Render Pipeline/Lit" }));
        }

        [Test]
        public void ACustomShaderIsReportedUnsupportedAndItsSamplesAreZero()
        {
            var shader = Shader.Find("Unlit/Color");
            if (shader == null) Assert.Ignore("Unity's built-in Unlit/Color shader was not found");
            var material = Own(new Material(shader));
            material.SetColor("_Color", Color.white);
            var (view, summary) = Capture(Quad(material), MaterialPassKind.Albedo, MaterialPassKind.Smoothness);
            var m = view.Materials;
            Assert.That(view.MaskAt(Size / 2, Size / 2), Is.EqualTo(255), "the quad is there");
            Assert.That(m.Supported[Centre], Is.EqualTo(0), "but its shader is not read");
            Assert.That(m.Albedo[4 * Centre] + m.Albedo[4 * Centre + 1] + m.Albedo[4 * Centre + 2], Is.EqualTo(0), "never guessed");
            Assert.That(m.Roughness[Centre], Is.EqualTo(0));
            Assert.That(summary.Materials.Unsupported, Has.Count.EqualTo(1));
            Assert.That(summary.Materials.Unsupported[0].Key, Is.EqualTo("Unlit/Color"));
            Assert.That(summary.Materials.Warning(), Does.Contain("Unlit/Color"));
        }
    }
}
