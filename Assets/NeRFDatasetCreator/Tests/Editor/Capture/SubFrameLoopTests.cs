using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Motion blur's sub-frame loop in a real Editor (<see cref="SubFrameRenderer"/>): N renders at the scheduled poses,
    /// averaged before the view's mid-pose render. A sphere of diameter 1 at the origin, one camera 3 units in front of
    /// it sliding 0.6 units sideways over the shutter, 32×32, k = 1.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class SubFrameLoopTests : GpuSceneFixture
    {
        const int Size = 32;
        const int SubFrames = 8;

        [Test]
        public void EachSubFrameIsRenderedAtItsScheduledPoseAndTheAverageIsBlurredAroundTheSharpMidPose()
        {
            var target = GameObject.CreatePrimitive(PrimitiveType.Sphere);
            target.name = "Blur target";
            var pose = LookAt.FromPositions(new Vector3d(0, 0, -3), Vector3d.Zero);
            var motion = ShutterMotion.Centred(pose, new Vector3d(0.6, 0, 0), Vector3d.Zero, SceneNormalisation.Identity, null, null);
            var schedule = SubFrameSchedule.For(motion, SubFrames);
            var seen = new List<(SubFrame Sub, Vector3 Position, Quaternion Rotation)>();
            var options = new CaptureOptions
            {
                Width = Size, Height = Size, Supersampling = 1, VerticalFieldOfViewDegrees = 40, NearClip = 0.1, FarClip = 100,
                SubFramesOf = index => schedule,
                BeforeSubFrame = (root, sub, camera) => seen.Add((sub, camera.position, camera.rotation)),
            };
            var consumer = new RecordingConsumer();
            CaptureRunner.RunBlocking(target, new[] { pose }, options, consumer, new ScriptedProgress());

            Assert.That(seen.Select(s => s.Sub.Index), Is.EqualTo(Enumerable.Range(0, SubFrames)), "N sub-frames, in order");
            foreach (var (sub, position, rotation) in seen)
            {
                Assert.That(sub.Fraction, Is.EqualTo((sub.Index + 0.5) / SubFrames));
                Assert.That(Vector3d.Distance(new Vector3d(position.x, position.y, position.z), sub.Pose.Position), Is.LessThan(1e-5), "camera at the scheduled position");
                var expected = sub.Pose.Rotation;
                Assert.That(Math.Abs(rotation.x * expected.X + rotation.y * expected.Y + rotation.z * expected.Z + rotation.w * expected.W), Is.GreaterThan(1 - 1e-6), "and rotation");
            }
            Assert.That(seen.First().Position.x, Is.EqualTo(-0.3 + 0.6 / 16).Within(1e-5), "the first sub-frame is a sixteenth of the way from the start");

            var view = consumer.Views.Single();
            Assert.That(view.BlurredOverBlack, Is.Not.Null);
            // The sharp render is at the mid pose: the sphere is centred. The blurred one has partial coverage where the
            // sharp silhouette's edge was, and its coverage summed over the image is the sharp one's (the sphere only slides).
            double sharpSum = 0, blurredSum = 0;
            var partial = 0;
            for (var y = 0; y < Size; y++)
                for (var x = 0; x < Size; x++)
                {
                    var sharp = view.AlphaAt(x, y);
                    var blurred = BlurredAlpha(view, x, y);
                    sharpSum += sharp;
                    blurredSum += blurred;
                    if (blurred > 0.1f && blurred < 0.9f && (sharp < 0.05f || sharp > 0.95f)) partial++;
                }
            Assert.That(partial, Is.GreaterThan(8), "blur along the sphere's left and right edges");
            Assert.That(blurredSum, Is.EqualTo(sharpSum).Within(0.05 * sharpSum));
        }

        /// <summary>
        /// Issue 32, R4-2: the sub-frames are summed on Core's worker thread into pooled arrays while the next render runs,
        /// with several views' readbacks in flight. Views alternate between a sliding camera and a still one (zero
        /// motion: its N sub-frames are the same render, so its average is the sharp render, to half-float rounding): each
        /// view must get the average of its own sub-frames, in order, with no array shared between views.
        /// </summary>
        [Test]
        public void EveryViewGetsTheAverageOfItsOwnSubFramesWithSeveralViewsInFlight()
        {
            var target = GameObject.CreatePrimitive(PrimitiveType.Sphere);
            target.name = "Blur target";
            var pose = LookAt.FromPositions(new Vector3d(0, 0, -3), Vector3d.Zero);
            var sliding = SubFrameSchedule.For(ShutterMotion.Centred(pose, new Vector3d(0.6, 0, 0), Vector3d.Zero, SceneNormalisation.Identity, null, null), SubFrames);
            var still = SubFrameSchedule.For(ShutterMotion.Centred(pose, Vector3d.Zero, Vector3d.Zero, SceneNormalisation.Identity, null, null), SubFrames);
            const int views = 7;
            var options = new CaptureOptions
            {
                Width = Size, Height = Size, Supersampling = 1, VerticalFieldOfViewDegrees = 40, NearClip = 0.1, FarClip = 100,
                ReadbacksInFlight = 3,
                SubFramesOf = index => index % 2 == 0 ? sliding : still,
            };
            var consumer = new RecordingConsumer();
            CaptureRunner.RunBlocking(target, Enumerable.Repeat(pose, views).ToArray(), options, consumer, new ScriptedProgress());

            Assert.That(consumer.Views.Select(v => v.ViewIndex), Is.EqualTo(Enumerable.Range(0, views)));
            foreach (var view in consumer.Views)
            {
                int partial = 0;
                var worst = 0f;
                for (var y = 0; y < Size; y++)
                    for (var x = 0; x < Size; x++)
                    {
                        float sharp = view.AlphaAt(x, y), blurred = BlurredAlpha(view, x, y);
                        worst = Math.Max(worst, Math.Abs(sharp - blurred));
                        if (blurred > 0.1f && blurred < 0.9f && (sharp < 0.05f || sharp > 0.95f)) partial++;
                    }
                if (view.ViewIndex % 2 == 0) Assert.That(partial, Is.GreaterThan(8), "view " + view.ViewIndex + " slides: blurred edges");
                else Assert.That(worst, Is.LessThan(2e-3f), "view " + view.ViewIndex + " is still: its average is its sharp render");
            }
        }

        static float BlurredAlpha(RecordedView view, int x, int y)
        {
            float t = 0;
            for (var c = 0; c < 3; c++)
            {
                var i = (y * view.Width + x) * 4 + c;
                t += HalfFloat.ToFloat(view.BlurredOverWhite[i]) - HalfFloat.ToFloat(view.BlurredOverBlack[i]);
            }
            return 1f - t / 3f;
        }
    }
}
