using System.Linq;
using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>An animated camera sampled on a copy: the clip's poses at the sample times, the user's scene untouched.</summary>
    public class AnimatedCameraTests
    {
        // The child "Cam" slides along its parent's x from 0 to 10 over 2 s; its field of view goes 30° → 30°.
        static readonly AnimationCurve Slide = AnimationCurve.Linear(0, 0, 2, 10);

        static Camera AnimatedRig(float frameRate)
        {
            var root = new GameObject("Flythrough");
            root.transform.position = new Vector3(5, 1, 0);
            root.transform.rotation = Quaternion.Euler(0, 90, 0);
            var cam = new GameObject("Cam", typeof(Camera));
            cam.transform.SetParent(root.transform, false);
            cam.transform.localPosition = new Vector3(-3, 0, 0); // not the clip's start: the sampler must not move it
            cam.GetComponent<Camera>().fieldOfView = 30;
            var clip = new AnimationClip { legacy = true, name = "Slide", frameRate = frameRate };
            clip.SetCurve("Cam", typeof(Transform), "localPosition.x", Slide);
            clip.SetCurve("Cam", typeof(Transform), "localPosition.y", AnimationCurve.Constant(0, 2, 0));
            clip.SetCurve("Cam", typeof(Transform), "localPosition.z", AnimationCurve.Constant(0, 2, 0));
            var animation = root.AddComponent<Animation>();
            animation.AddClip(clip, clip.name);
            animation.clip = clip;
            return cam.GetComponent<Camera>();
        }

        static void AssertClipPoses(System.Collections.Generic.IReadOnlyList<SceneCamera> sampled, double[] times, Camera user)
        {
            Assert.That(sampled, Has.Count.EqualTo(times.Length));
            var root = user.transform.parent;
            for (var i = 0; i < times.Length; i++)
            {
                var expected = root.TransformPoint(new Vector3(Slide.Evaluate((float)times[i]), 0, 0));
                var p = sampled[i].Pose.Position;
                Assert.That(Vector3.Distance(new Vector3((float)p.X, (float)p.Y, (float)p.Z), expected), Is.LessThan(1e-4f), "t = " + times[i]);
                var q = sampled[i].Pose.Rotation;
                Assert.That(Quaternion.Angle(new Quaternion((float)q.X, (float)q.Y, (float)q.Z, (float)q.W), root.rotation), Is.LessThan(1e-3f));
                Assert.That(sampled[i].VerticalFovDegrees, Is.EqualTo(30).Within(1e-4));
            }
            Assert.That(user.transform.localPosition, Is.EqualTo(new Vector3(-3, 0, 0)), "the user's camera never moves");
        }

        [Test]
        public void EvenSamplesGiveTheClipsPosesAtTheirTimes()
        {
            var scene = TestScene.Open();
            try
            {
                var camera = AnimatedRig(30);
                AnimatedCameraSampler.ClearCache();
                var source = new CameraSourceSettings { Kind = CameraSourceKind.AnimatedCamera, ObjectPath = "Flythrough/Cam", Samples = 5 };
                var sampled = AnimatedCameraSampler.Sample(source, 64, 64, "splits.test.source", out var problem);
                Assert.That(problem, Is.Null);
                AssertClipPoses(sampled, new[] { 0, 0.5, 1, 1.5, 2 }, camera);
                Assert.That(sampled[2].Name, Is.EqualTo("Flythrough/Cam @ 1 s"));
            }
            finally
            {
                TestScene.Close(scene);
            }
        }

        [Test]
        public void AFrameStepUsesTheClipsFrameRate()
        {
            var scene = TestScene.Open();
            try
            {
                var camera = AnimatedRig(4);
                AnimatedCameraSampler.ClearCache();
                // 4 frames per second, every 3rd frame over 2 s: frames 0, 3, 6 → 0, 0.75, 1.5 s.
                var source = new CameraSourceSettings { Kind = CameraSourceKind.AnimatedCamera, ObjectPath = "Flythrough/Cam", FrameStep = 3 };
                var sampled = AnimatedCameraSampler.Sample(source, 64, 64, "splits.test.source", out var problem);
                Assert.That(problem, Is.Null);
                AssertClipPoses(sampled, new[] { 0, 0.75, 1.5 }, camera);

                var settings = new DatasetSettings { Width = 64, Height = 64 };
                settings.Test.Source = source;
                SceneCameraSources.Resolve(settings);
                var plan = CapturePlan.Build(settings, PlanTarget.AtOrigin);
                Assert.That(plan.ViewsOf(DatasetSplit.Test).Select(v => v.Pose.Position.X), Is.EqualTo(sampled.Select(s => s.Pose.Position.X)));
            }
            finally
            {
                TestScene.Close(scene);
            }
        }

        [Test]
        public void ACameraWithoutAnimationIsRefused()
        {
            var scene = TestScene.Open();
            try
            {
                new GameObject("Still", typeof(Camera));
                var source = new CameraSourceSettings { Kind = CameraSourceKind.AnimatedCamera, ObjectPath = "Still" };
                Assert.That(AnimatedCameraSampler.Sample(source, 64, 64, "splits.test.source", out var problem), Is.Null);
                Assert.That(problem.Field, Is.EqualTo("splits.test.source.camera"));
                Assert.That(problem.Reason, Does.Contain("is not animated"));
            }
            finally
            {
                TestScene.Close(scene);
            }
        }
    }
}
