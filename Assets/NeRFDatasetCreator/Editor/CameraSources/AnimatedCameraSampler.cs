using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using UnityEditor;
using UnityEngine;
using UnityEngine.Playables;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The poses of an animated scene camera at the times of Core's <see cref="AnimatedCameraSampling"/>, evaluated
    /// on a copy of the camera's root object in a preview scene, never by moving the user's scene. The copy is posed
    /// at each time by <see cref="ContentClock"/> — the dynamic capture's evaluator: Animators stepped from
    /// <c>Rebind()</c>, legacy clips by <c>AnimationClip.SampleAnimation(go, t)</c> (UnityCsReference 2022.3
    /// Modules/Animation/ScriptBindings/AnimationClip.bindings.cs:25), PlayableDirectors by <c>time = t</c> then
    /// <c>Evaluate()</c> (Modules/Director/ScriptBindings/PlayableDirector.bindings.cs:78, 84). The root
    /// (<c>Transform.root</c>, Runtime/Transform/ScriptBindings/Transform.bindings.cs:392) is copied whole so that
    /// whatever animates the camera — an Animator on a parent, a Timeline whose track binds the camera — is copied with
    /// it; Object.Instantiate remaps references inside the copied hierarchy to the copies, so the copied director
    /// drives the copied camera.
    /// <para>
    /// A camera with a CinemachineBrain is sampled by <see cref="CinemachineCameraSampler"/> instead: its Timeline's
    /// Cinemachine track and virtual cameras live on other root objects, so its whole scene is copied.
    /// </para>
    /// <para>
    /// Samples are cached until anything in the editor changes (<c>ObjectChangeEvents.changesPublished</c>,
    /// Editor/Mono/Undo/EditorObjectChangeEvents.cs:58): the window plans on every edit, and an Animator is stepped
    /// from the start for every sample.
    /// </para>
    /// </summary>
    public static class AnimatedCameraSampler
    {
        /// <summary>What may animate the camera (particles never do).</summary>
        public const TimeSources Drivers = TimeSources.Timeline | TimeSources.Animator | TimeSources.Animation;

        static readonly Dictionary<string, List<SceneCamera>> Cache = new Dictionary<string, List<SceneCamera>>();
        static readonly Dictionary<string, CinemachineCameraSampler.Result> CinemachineCache = new Dictionary<string, CinemachineCameraSampler.Result>();
        // The last samples per key, kept when the caches are cleared: the window's 10 Hz preview draws these (marked
        // stale) instead of sampling, which copies the camera's root or the whole scene (review S3-2).
        static readonly Dictionary<string, (List<SceneCamera> Cameras, IReadOnlyList<ValidationProblem> Warnings)> Last =
            new Dictionary<string, (List<SceneCamera>, IReadOnlyList<ValidationProblem>)>();
        static bool _listening;

        public static List<SceneCamera> Sample(CameraSourceSettings source, int width, int height, string field, out ValidationProblem problem) =>
            Sample(source, width, height, field, out problem, out _);

        /// <summary>The samples, and what was sampled but is not reproduced (a Cinemachine camera's damping) as <paramref name="warnings"/>.</summary>
        public static List<SceneCamera> Sample(CameraSourceSettings source, int width, int height, string field, out ValidationProblem problem,
            out IReadOnlyList<ValidationProblem> warnings)
        {
            problem = null;
            warnings = Array.Empty<ValidationProblem>();
            if (string.IsNullOrWhiteSpace(source.ObjectPath)) return new List<SceneCamera>(); // Core reports the empty path
            var found = SceneObjects.Find(source.ObjectPath);
            var camera = found == null ? null : found.GetComponent<Camera>();
            if (camera == null)
            {
                problem = new ValidationProblem(field + ".camera", source.ObjectPath,
                    found == null ? "names no object in the open scenes." : "names an object without a Camera.",
                    "Give the hierarchy path of the animated camera, with its scene open.");
                return null;
            }
            // A CinemachineBrain sets the camera's transform and lens itself: what animates it is the Timeline's
            // Cinemachine track and the virtual cameras, wherever they are in the scene.
            var brain = CinemachineApi.BrainOn(camera);
            if (brain != null)
            {
                Listen();
                var cmKey = Key(camera, source, width, height);
                if (!CinemachineCache.TryGetValue(cmKey, out var sampledByBrain))
                {
                    sampledByBrain = CinemachineCameraSampler.Sample(camera, brain, source, width, height, field, out problem);
                    if (problem != null) return null;
                    CinemachineCache[cmKey] = sampledByBrain;
                    Remember(camera, cmKey, sampledByBrain.Cameras, sampledByBrain.Warnings);
                }
                warnings = sampledByBrain.Warnings;
                return sampledByBrain.Cameras;
            }
            var root = camera.transform.root.gameObject;
            var length = ContentClock.ClipLength(root, Drivers);
            if (!(length > 0))
            {
                problem = new ValidationProblem(field + ".camera", source.ObjectPath,
                    "is not animated: no Animator, Animation or PlayableDirector with a clip on its root object \"" + root.name + "\" or below it.",
                    "Animate the camera or a parent with an Animation clip or a Timeline whose PlayableDirector is under the same root object.");
                return null;
            }
            double[] times;
            try
            {
                var rate = source.FrameRate > 0 ? source.FrameRate : FrameRate(root);
                times = AnimatedCameraSampling.Times(source.Start, AnimatedCameraSampling.ResolveEnd(source.End, length), source.Samples, source.FrameStep, rate, field);
            }
            catch (InvalidParameterException e)
            {
                problem = e.Problems[0];
                return null;
            }

            Listen();
            var key = Key(camera, source, width, height);
            if (Cache.TryGetValue(key, out var cached)) return cached;
            var sampled = SampleOnCopy(camera, root, times, width, height, field, out problem);
            if (problem == null)
            {
                Cache[key] = sampled;
                Remember(camera, key, sampled, Array.Empty<ValidationProblem>());
            }
            return sampled;
        }

        /// <summary>Keeps one entry per camera in <see cref="Last"/>: the preview reads only the current key, so older keys of the same camera would only grow the dictionary.</summary>
        static void Remember(Camera camera, string key, List<SceneCamera> cameras, IReadOnlyList<ValidationProblem> warnings)
        {
            var prefix = camera.GetInstanceID() + "|";
            foreach (var old in Last.Keys.Where(k => k.StartsWith(prefix, StringComparison.Ordinal) && k != key).ToList()) Last.Remove(old);
            Last[key] = (cameras, warnings);
        }

        static string Key(Camera camera, CameraSourceSettings source, int width, int height) =>
            string.Join("|", camera.GetInstanceID(), source.Start, source.End, source.Samples, source.FrameStep, source.FrameRate, width, height);

        /// <summary>
        /// The samples the last <see cref="Sample"/> of this source produced, without sampling (no copy, no animation
        /// step): for the window's preview, which runs ten times a second. <paramref name="stale"/> is true when the
        /// scene changed since (the cache was cleared) or nothing was sampled yet (null is returned then).
        /// </summary>
        public static List<SceneCamera> LastSampled(CameraSourceSettings source, int width, int height, out bool stale,
            out IReadOnlyList<ValidationProblem> warnings)
        {
            stale = true;
            warnings = Array.Empty<ValidationProblem>();
            if (string.IsNullOrWhiteSpace(source.ObjectPath)) return null;
            var found = SceneObjects.Find(source.ObjectPath);
            var camera = found == null ? null : found.GetComponent<Camera>();
            if (camera == null) return null;
            var key = Key(camera, source, width, height);
            stale = !Cache.ContainsKey(key) && !CinemachineCache.ContainsKey(key);
            if (!Last.TryGetValue(key, out var last)) return null;
            warnings = last.Warnings;
            return last.Cameras;
        }

        /// <summary>The camera's pose and field of view at each time, read from a posed copy. The user's objects are only read.</summary>
        public static List<SceneCamera> SampleOnCopy(Camera camera, GameObject root, IReadOnlyList<double> times, int width, int height, string field,
            out ValidationProblem problem)
        {
            problem = null;
            var relative = RelativePath(root.transform, camera.transform);
            var name = SceneObjectPath.Of(camera.gameObject);
            using (var sceneCopy = SceneCopy.OfObject(root, "animated camera"))
            {
                var copy = sceneCopy.Root;
                var copiedTransform = relative.Length == 0 ? copy.transform : copy.transform.Find(relative);
                var copied = copiedTransform == null ? null : copiedTransform.GetComponent<Camera>();
                if (copied == null) throw new InvalidOperationException("The copy of " + name + " was not found at " + relative + ".");
                var clock = new ContentClock(Drivers, 0);
                var result = new List<SceneCamera>(times.Count);
                foreach (var time in times)
                {
                    clock.Show(copy, time);
                    var read = SceneCameraSources.Read(copied, width, height, field + ".camera", out problem);
                    if (problem != null) return null;
                    result.Add(new SceneCamera(name + " @ " + time.ToString("0.####", System.Globalization.CultureInfo.InvariantCulture) + " s", read.Pose, read.VerticalFovDegrees));
                }
                return result;
            }
        }

        /// <summary>
        /// Frames per second of what drives the camera: the longest clip's <c>AnimationClip.frameRate</c>
        /// (AnimationClip.bindings.cs:48), else a Timeline's, read by name (<c>TimelineAsset.editorSettings.frameRate</c>:
        /// this package does not reference the Timeline package), else <see cref="AnimatedCameraSampling.DefaultFrameRate"/>.
        /// </summary>
        public static double FrameRate(GameObject root)
        {
            AnimationClip longest = null;
            foreach (var animator in root.GetComponentsInChildren<Animator>(true))
                if (animator.runtimeAnimatorController != null)
                    foreach (var clip in animator.runtimeAnimatorController.animationClips)
                        if (clip != null && (longest == null || clip.length > longest.length)) longest = clip;
            foreach (var animation in root.GetComponentsInChildren<Animation>(true))
                if (animation.clip != null && (longest == null || animation.clip.length > longest.length)) longest = animation.clip;
            if (longest != null && longest.frameRate > 0) return longest.frameRate;
            foreach (var director in root.GetComponentsInChildren<PlayableDirector>(true))
            {
                var rate = TimelineFrameRate(director);
                if (rate > 0) return rate;
            }
            return AnimatedCameraSampling.DefaultFrameRate;
        }

        /// <summary>The frame rate of a director's Timeline (<c>TimelineAsset.editorSettings.frameRate</c>, read by name), 0 when unknown.</summary>
        public static double TimelineFrameRate(PlayableDirector director)
        {
            var asset = director.playableAsset;
            if (asset == null) return 0;
            var settings = Member(asset, "editorSettings");
            var rate = settings == null ? null : Member(settings, "frameRate") ?? Member(settings, "fps");
            if (!(rate is IConvertible convertible)) return 0;
            var value = convertible.ToDouble(System.Globalization.CultureInfo.InvariantCulture);
            return value > 0 ? value : 0;
        }

        static object Member(object o, string name)
        {
            const BindingFlags flags = BindingFlags.Public | BindingFlags.Instance;
            var type = o.GetType();
            var property = type.GetProperty(name, flags);
            if (property != null) return property.GetValue(o);
            return type.GetField(name, flags)?.GetValue(o);
        }

        static string RelativePath(Transform root, Transform t)
        {
            var names = new List<string>();
            for (var at = t; at != null && at != root; at = at.parent) names.Add(at.name);
            names.Reverse();
            return string.Join("/", names);
        }

        static void Listen()
        {
            if (_listening) return;
            _listening = true;
            ObjectChangeEvents.changesPublished += (ref ObjectChangeEventStream stream) => ClearCache();
        }

        /// <summary>Forgets every cached sample (tests, or a change the events do not report).</summary>
        public static void ClearCache()
        {
            Cache.Clear();
            CinemachineCache.Clear();
        }
    }
}
