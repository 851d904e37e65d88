using NUnit.Framework;
using UnityEditor.Animations;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Issue 32, R4-1: an Animator with Apply Root Motion posed by <see cref="ContentClock"/> is where time t puts it,
    /// whatever was shown before. The clip walks the root 2 units along z in 1 s (a generic clip on the Animator's own
    /// transform, which root motion turns into deltas); the controller is built in memory (UnityCsReference 2022.3.76f1
    /// Editor/Mono/Animation/AnimatorController.cs:52-66 <c>AddLayer</c> adds its state machine to an asset only when the
    /// controller is one, :184-193 <c>AddMotion</c>). Without the fix every <c>Show</c> adds the displacement from 0 to t
    /// to wherever the previous call left the object.
    /// </summary>
    [TestFixture]
    public class RootMotionPoseTests
    {
        Scene _scene;
        GameObject _walker;
        AnimationClip _clip;
        AnimatorController _controller;

        [SetUp]
        public void SetUp()
        {
            _scene = TestScene.Open();
            _clip = new AnimationClip { name = "walk" };
            _clip.SetCurve("", typeof(Transform), "localPosition.z", AnimationCurve.Linear(0, 0, 1, 2));
            _controller = new AnimatorController { name = "walker" };
            _controller.AddLayer("Base Layer");
            _controller.AddMotion(_clip);
            _walker = Walker();
        }

        GameObject Walker()
        {
            var walker = GameObject.CreatePrimitive(PrimitiveType.Cube);
            walker.name = "Walker";
            walker.transform.localPosition = new Vector3(1, 0, 3);
            walker.transform.localRotation = Quaternion.Euler(0, 30, 0);
            var animator = walker.AddComponent<Animator>();
            animator.applyRootMotion = true;
            animator.runtimeAnimatorController = _controller;
            return walker;
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
            if (_controller != null) Object.DestroyImmediate(_controller);
            if (_clip != null) Object.DestroyImmediate(_clip);
        }

        static (Vector3 Position, Quaternion Rotation) Pose(GameObject o) => (o.transform.localPosition, o.transform.localRotation);

        static void AssertSame((Vector3 Position, Quaternion Rotation) actual, (Vector3 Position, Quaternion Rotation) expected, string what)
        {
            Assert.That(Vector3.Distance(actual.Position, expected.Position), Is.LessThan(1e-4f), what + ": position " + actual.Position + " vs " + expected.Position);
            Assert.That(Quaternion.Angle(actual.Rotation, expected.Rotation), Is.LessThan(1e-2f), what + ": rotation");
        }

        [Test]
        public void ThePoseAtATimeDoesNotDependOnTheCallsBefore()
        {
            var clock = new ContentClock(TimeSources.Animator, 1);
            clock.Show(_walker, 1);
            var first = Pose(_walker);
            clock.Show(_walker, 0.5);
            var half = Pose(_walker);
            clock.Show(_walker, 1);
            AssertSame(Pose(_walker), first, "t = 1 after t = 1, 0.5");
            clock.Show(_walker, 0.25);
            clock.Show(_walker, 0.75);
            clock.Show(_walker, 0.5);
            AssertSame(Pose(_walker), half, "t = 0.5 after t = 1, 0.5, 1, 0.25, 0.75");
            for (var i = 0; i < 5; i++)
            {
                clock.Show(_walker, 0.9);
                clock.Show(_walker, 1);
            }
            AssertSame(Pose(_walker), first, "t = 1 after ten more calls");

            // A fresh object with a fresh clock, posed at t once, is where the first one is.
            var fresh = Walker();
            new ContentClock(TimeSources.Animator, 1).Show(fresh, 1);
            AssertSame(Pose(fresh), first, "a fresh copy posed at t = 1 once");
            Assert.That(Vector3.Distance(first.Position, half.Position), Is.GreaterThan(0.5f), "the clip moves the walker (2 units per second)");
        }

        [Test]
        public void MovingToAnotherRootPutsTheLastOneBackWhereItStarted()
        {
            var start = Pose(_walker);
            var clock = new ContentClock(TimeSources.Animator, 1);
            clock.Show(_walker, 1);
            var other = Walker();
            clock.Show(other, 0.5);
            AssertSame(Pose(_walker), start, "the first root after the clock moved on");
        }
    }
}
