using System;
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Playables;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Poses animated content at a content time, deterministically and never from the wall clock, on the capture's
    /// copies (the user's objects never move). Each call evaluates from scratch, so the result depends on the time alone,
    /// not on the order of the calls (UnityCsReference 2022.3):
    /// <list type="bullet">
    /// <item>Animator: <c>Rebind()</c> (Modules/Animation/ScriptBindings/Animator.bindings.cs:1200) resets it to its
    /// default state, <c>Update(0)</c> enters it, then <c>Update(dt)</c> (line 1198) in fixed sub-steps of at most
    /// <see cref="AnimatorStepSeconds"/> up to t — the state machine (transitions, blend trees) runs as in play mode at that frame rate.
    /// An Animator that applies root motion first gets its GameObject's transform back as it was before the first pose
    /// (<see cref="RootMotionStart"/>): root motion moves it by deltas that <c>Rebind</c> does not undo.</item>
    /// <item>Legacy Animation: its clip's <c>SampleAnimation(go, t)</c> (Modules/Animation/ScriptBindings/
    /// AnimationClip.bindings.cs:25–27), which applies the clip's own wrap mode.</item>
    /// <item>PlayableDirector (Timeline): <c>time = t</c>, then <c>Evaluate()</c> (Modules/Director/ScriptBindings/
    /// PlayableDirector.bindings.cs:78, 84) — after the Animators, so a Timeline's animation tracks win as in play mode.</item>
    /// <item>ParticleSystem: stopped and cleared, a fixed <c>randomSeed</c> with <c>useAutoRandomSeed</c> off
    /// (Modules/ParticleSystem/ScriptBindings/ParticleSystem.bindings.cs:65, 73), then <c>Simulate(t, withChildren: true,
    /// restart: true, fixedTimeStep: false)</c> (line 156 on 2022.3.76f1 and 6000.0.78f1) from the root systems. Not the
    /// fixed time step: "fixedTimeStep: Only update the system at fixed intervals, based on the value in 'Fixed Time' in
    /// the Time options" (Scripting API ParticleSystem.Simulate), which snapped content time to
    /// <c>Time.fixedDeltaTime</c> (0.02 s by default), so motion-blur sub-frames and view times within one fixed step
    /// showed the same particles (review R4-8). "restart: true … reset to 0 time, and then advanced by this value" keeps
    /// each call independent of the ones before.</item>
    /// </list>
    /// </summary>
    public sealed class ContentClock
    {
        /// <summary>The Animator's largest sub-step: 1/60 s, a common play-mode frame time.</summary>
        public const double AnimatorStepSeconds = 1.0 / 60.0;

        readonly TimeSources _sources;
        readonly uint _particleSeed;
        GameObject _root;
        readonly List<Animator> _animators = new List<Animator>();
        readonly List<Animation> _animations = new List<Animation>();
        readonly List<PlayableDirector> _directors = new List<PlayableDirector>();
        readonly List<ParticleSystem> _particles = new List<ParticleSystem>();
        readonly RootMotionStart _rootMotion = new RootMotionStart();
        double _shown = double.NaN;

        public ContentClock(TimeSources sources, long datasetSeed)
        {
            _sources = sources;
            _particleSeed = unchecked((uint)SeededRandom.Derive(datasetSeed, "particles"));
        }

        /// <summary>The label of the particle seed: <c>SeededRandom.Derive(seed, "particles")</c>.</summary>
        public uint ParticleSeed => _particleSeed;

        /// <summary>Poses everything under <paramref name="root"/> (the copies) at <paramref name="seconds"/>; repeated calls at the same time do nothing.</summary>
        public void Show(GameObject root, double seconds)
        {
            if (root != _root)
            {
                Attach(root);
                _shown = double.NaN;
            }
            if (seconds == _shown) return;
            var t = (float)seconds;
            _rootMotion.Restore(); // root motion then adds the clip's motion from 0 to t to the start, not to the last pose
            foreach (var animator in _animators)
            {
                if (animator == null || animator.runtimeAnimatorController == null) continue;
                animator.Rebind();
                animator.Update(0f);
                var steps = (int)Math.Ceiling(seconds / AnimatorStepSeconds - 1e-9);
                for (var i = 0; i < steps; i++) animator.Update((float)(seconds / steps));
            }
            foreach (var animation in _animations)
                if (animation != null && animation.clip != null) animation.clip.SampleAnimation(animation.gameObject, t);
            foreach (var director in _directors)
            {
                if (director == null || director.playableAsset == null) continue;
                director.time = seconds;
                director.Evaluate();
            }
            foreach (var system in _particles)
                if (system != null) system.Simulate(t, withChildren: true, restart: true, fixedTimeStep: false); // at t exactly (R4-8)
            _shown = seconds;
        }

        void Attach(GameObject root)
        {
            _rootMotion.RestoreAndForget(); // the previous root's root-motion objects go back where they started
            _root = root;
            _animators.Clear();
            _animations.Clear();
            _directors.Clear();
            _particles.Clear();
            if (root == null) return;
            if ((_sources & TimeSources.Animator) != 0)
            {
                _animators.AddRange(root.GetComponentsInChildren<Animator>(true));
                // The clock only ever poses copies (the capture's, TimeMeasurement's, AnimatedCameraSampler's), in preview
                // scenes no Scene or Game view shows: an Animator culled by visibility ("Animation is completely disabled
                // when renderers are not visible", Scripting API AnimatorCullingMode.CullCompletely) might skip the
                // steps below. Same setting as CaptureStage.RenderAsPosed; only copies change.
                foreach (var animator in _animators) animator.cullingMode = AnimatorCullingMode.AlwaysAnimate;
            }
            _rootMotion.Record(_animators); // before the first pose
            if ((_sources & TimeSources.Animation) != 0) _animations.AddRange(root.GetComponentsInChildren<Animation>(true));
            if ((_sources & TimeSources.Timeline) != 0) _directors.AddRange(root.GetComponentsInChildren<PlayableDirector>(true));
            if ((_sources & TimeSources.Particles) != 0)
            {
                var all = root.GetComponentsInChildren<ParticleSystem>(true);
                foreach (var system in all)
                {
                    // The seed can only be set on a stopped system.
                    system.Stop(false, ParticleSystemStopBehavior.StopEmittingAndClear);
                    system.useAutoRandomSeed = false;
                    system.randomSeed = _particleSeed;
                }
                // Simulate(withChildren: true) from the roots only: a child simulated again would restart.
                foreach (var system in all)
                    if (system.transform.parent == null || system.transform.parent.GetComponentInParent<ParticleSystem>(true) == null)
                        _particles.Add(system);
            }
        }

        /// <summary>
        /// The length of the longest Timeline or clip on <paramref name="target"/> and its children (0 when none): the
        /// end of <c>time.end: "clip"</c>. Reads the user's objects, never changes them.
        /// </summary>
        public static double ClipLength(GameObject target, TimeSources sources)
        {
            if (target == null) return 0;
            double longest = 0;
            if ((sources & TimeSources.Timeline) != 0)
                foreach (var director in target.GetComponentsInChildren<PlayableDirector>(true))
                    if (director.playableAsset != null) longest = Math.Max(longest, director.playableAsset.duration);
            if ((sources & TimeSources.Animator) != 0)
                foreach (var animator in target.GetComponentsInChildren<Animator>(true))
                    if (animator.runtimeAnimatorController != null)
                        foreach (var clip in animator.runtimeAnimatorController.animationClips)
                            if (clip != null) longest = Math.Max(longest, clip.length);
            if ((sources & TimeSources.Animation) != 0)
                foreach (var animation in target.GetComponentsInChildren<Animation>(true))
                    if (animation.clip != null) longest = Math.Max(longest, animation.clip.length);
            if ((sources & TimeSources.Particles) != 0)
                foreach (var system in target.GetComponentsInChildren<ParticleSystem>(true))
                    longest = Math.Max(longest, system.main.duration);
            return longest;
        }
    }
}
