using System.Collections.Generic;
using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// A capture with relighting (issue 38) delivers one more colour pair per lighting render, keyed as the files are
    /// named, with the same coverage as the plain pair; the capture's own lighting is back for the plain image of the
    /// next view (its two views' plain renders are equal).
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class RelitCaptureTests : GpuSceneFixture
    {
        const int Size = 32;

        [Test]
        public void EachViewGetsAPairPerRenderAndThePlainImagesKeepTheScenesLighting()
        {
            var quad = GameObject.CreatePrimitive(PrimitiveType.Quad);
            var light = new GameObject("Scene light", typeof(Light)).GetComponent<Light>();
            light.type = LightType.Directional;
            var relighting = new RelightingSettings
            {
                On = true,
                Conditions = new List<LightingCondition>
                {
                    new LightingCondition { Name = "olat-00", Kind = LightingKind.Point, Position = new double[] { 0, -2, 0 }, Intensity = 5 },
                    new LightingCondition { Name = "key", Kind = LightingKind.Spot, Position = new double[] { 0, -2, 0.5 }, Intensity = 5, SpotAngle = 40 },
                },
            };
            var options = new CaptureOptions
            {
                Width = Size, Height = Size, Supersampling = 1, Passes = CapturePasses.Color | CapturePasses.Mask,
                VerticalFieldOfViewDegrees = 60, NearClip = 0.1, FarClip = 100, ReadbacksInFlight = 1,
                Relighting = RelightingInUnity.Resolve(relighting, SceneNormalisation.Identity),
            };
            var pose = LookAt.FromPositions(new Vector3d(0, 0, -2), Vector3d.Zero);
            var consumer = new RecordingConsumer();
            CaptureRunner.RunBlocking(quad, new List<UnityPose> { pose, pose }, options, consumer, new ScriptedProgress());
            Assert.That(consumer.Views, Has.Count.EqualTo(2));
            foreach (var view in consumer.Views)
            {
                Assert.That(view.Relit.Keys, Is.EquivalentTo(new[] { "olat-00", "key" }));
                foreach (var pair in view.Relit.Values)
                {
                    Assert.That(pair[0], Has.Length.EqualTo(view.OverBlack.Length));
                    // Difference matting of the relit pair: opaque on the quad, transparent in a corner, like the plain pair.
                    var centre = (Size / 2 * Size + Size / 2) * 4;
                    Assert.That(HalfFloat.ToFloat(pair[1][centre]) - HalfFloat.ToFloat(pair[0][centre]), Is.EqualTo(0).Within(1e-3));
                    Assert.That(HalfFloat.ToFloat(pair[1][0]) - HalfFloat.ToFloat(pair[0][0]), Is.EqualTo(1).Within(1e-3));
                }
            }
            Assert.That(consumer.Views[1].OverBlack, Is.EqualTo(consumer.Views[0].OverBlack),
                "the second view's plain image is lit as the first's: the conditions switched back");
            Assert.That(light.enabled, Is.True, "the user's light was never touched");
        }
    }
}
