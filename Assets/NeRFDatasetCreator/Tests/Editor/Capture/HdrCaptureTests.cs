using System.Collections.Generic;
using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// The colour pass keeps light above 1, which the "hdr" output (Core's HdrColour) writes to r_&lt;i&gt;_hdr.exr. The
    /// capture camera renders into <see cref="CaptureEnvironment.ColorFormat"/> (R16G16B16A16_SFloat) with no
    /// post-processing: in URP the camera's intermediate target copies the target texture's descriptor for a Game camera
    /// whatever allowHDR says (URP 14.0.8 Runtime/UniversalRenderPipelineCore.cs:1363-1373; URP 17.0.3 :1541-1551) and
    /// post-processing is the camera data's renderPostProcessing, false by default (UniversalAdditionalCameraData.cs:322,
    /// UniversalRenderPipeline.cs:1258/1271 in 14.0.8, :1480/1492 in 17.0.3). In the Built-in pipeline no image effect is
    /// on the capture's own camera; whether its forward path with allowHDR = false clamps is native, which this test shows.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class HdrCaptureTests : GpuSceneFixture
    {
        const int Size = 16, K = 2, W = Size * K;

        [Test]
        public void AnUnlitColourAboveOneIsReadBackAboveOneAndTheHdrStageKeepsIt()
        {
            Assume.That(QualitySettings.activeColorSpace, Is.EqualTo(ColorSpace.Linear), "HDR colour needs a Linear colour-space project");
            var quad = GameObject.CreatePrimitive(PrimitiveType.Quad); // faces −Z: towards the camera
            var shader = Shader.Find("Unlit/Color");
            Assume.That(shader, Is.Not.Null, "Unity's built-in Unlit/Color shader");
            var material = Own(new Material(shader));
            material.SetColor("_Color", new Color(4f, 2f, 0.5f, 1f));
            quad.GetComponent<MeshRenderer>().sharedMaterial = material;
            quad.transform.localScale = new Vector3(4, 4, 1);

            var options = new CaptureOptions
            {
                Width = Size, Height = Size, Supersampling = K, VerticalFieldOfViewDegrees = 40, NearClip = 0.1, FarClip = 100,
                Passes = CapturePasses.Color | CapturePasses.Mask,
            };
            var consumer = new RecordingConsumer();
            CaptureRunner.RunBlocking(quad, new List<UnityPose> { LookAt.FromPositions(new Vector3d(0, 0, -3), Vector3d.Zero) }, options, consumer, new ScriptedProgress());
            var view = consumer.Views[0];
            Assert.That(view.OverBlackAt(W / 2, W / 2, 0), Is.GreaterThan(1.5f), "red above 1 survives the colour pass (not clamped, not tone-mapped)");

            var frame = new RawFrame(W, W, K) { ColorOverBlack = view.OverBlack, ColorOverWhite = view.OverWhite };
            var hdr = HdrColour.Resolve(frame);
            var centre = ((Size / 2) * Size + Size / 2) * 4;
            Assert.That(hdr[centre], Is.GreaterThan(1.5f), "the HDR image keeps it");
            Assert.That(hdr[centre + 3], Is.EqualTo(1f).Within(1e-3f), "opaque");
        }
    }
}
