using System.Collections.Generic;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The transforms of the Animators that apply root motion, as they were before the first pose, so that every pose
    /// starts from them (issue 32, R4-1). With <c>applyRootMotion</c> ("Root is controlled by animations", UnityCsReference
    /// Modules/Animation/ScriptBindings/Animator.bindings.cs:409-410 at 2022.3.76f1, :413-414 at 6000.0.78f1) each
    /// <c>Animator.Update(dt)</c> moves the Animator's GameObject by the root's delta for that step (<c>deltaPosition</c>,
    /// "delta position for the last evaluated frame", :384 / :388), and the transform is not one of the bound properties
    /// <c>Rebind()</c> writes back (:1200 / :1205; native). Without this, every <see cref="ContentClock.Show"/> would add
    /// the displacement from 0 to t on top of where the previous call left the object, so views, motion-blur sub-frames,
    /// the time measurement and the per-step geometry would depend on the call history. Unity's own Animation window
    /// samples a root-motion Animator as absolute motion for the same reason: it puts an
    /// <c>AnimationMotionXToDeltaPlayable</c> with <c>SetAbsoluteMotion(true)</c> at the graph's root when
    /// <c>animator.applyRootMotion</c> (Editor/Mono/Animation/AnimationWindow/AnimationWindowControl.cs:615-624 at
    /// 2022.3.76f1, :545-554 at 6000.0.78f1). Here the equivalent is to start each evaluation from the recorded
    /// <c>localPosition</c>/<c>localRotation</c> (Runtime/Transform/ScriptBindings/Transform.bindings.cs:29, 60 on both
    /// tags): the root then ends at start + the clip's motion from 0 to t, whatever was shown before.
    /// </summary>
    sealed class RootMotionStart
    {
        readonly List<(Transform Transform, Vector3 Position, Quaternion Rotation)> _start = new List<(Transform, Vector3, Quaternion)>();

        /// <summary>Records the transform of each Animator in <paramref name="animators"/> that applies root motion.</summary>
        public void Record(IEnumerable<Animator> animators)
        {
            _start.Clear();
            foreach (var animator in animators)
                if (animator != null && animator.applyRootMotion)
                {
                    var t = animator.transform;
                    _start.Add((t, t.localPosition, t.localRotation));
                }
        }

        /// <summary>Puts every recorded transform back where it was recorded (those destroyed since are skipped).</summary>
        public void Restore()
        {
            foreach (var (transform, position, rotation) in _start)
            {
                if (transform == null) continue;
                transform.localPosition = position;
                transform.localRotation = rotation;
            }
        }

        /// <summary>Puts every recorded transform back and forgets them (the clock moves on to other objects).</summary>
        public void RestoreAndForget()
        {
            Restore();
            _start.Clear();
        }

        /// <summary>Animators recorded (those applying root motion).</summary>
        public int Count => _start.Count;
    }
}
