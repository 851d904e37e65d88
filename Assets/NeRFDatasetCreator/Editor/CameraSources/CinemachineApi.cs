using System;
using System.Collections;
using System.Collections.Generic;
using System.Reflection;
using UnityEngine;
using UnityEngine.Playables;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Cinemachine and Timeline, read by type and member name: the package references neither (a
    /// <c>versionDefines</c> reference would never be compile-checked here). Cinemachine 2.x (namespace
    /// <c>Cinemachine</c>, assembly Cinemachine; its Timeline mixer <c>CinemachineMixer</c> in the global namespace) and
    /// 3.x (namespace <c>Unity.Cinemachine</c>; <c>CinemachinePlayableMixer</c>) have the same members for what is used
    /// here; every name below is cited in Documentation~/camera-sources.md (com.unity.cinemachine at tags
    /// releases/2.10.3 and releases/3.1.1). A member that is missing is reported by name, never guessed around.
    /// </summary>
    sealed class CinemachineApi
    {
        const BindingFlags Static = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Static;
        const BindingFlags Instance = BindingFlags.Public | BindingFlags.Instance;

        public Type Brain { get; private set; }
        public Type VirtualCameraBase { get; private set; }
        public string Version { get; private set; }
        Type _core;
        Type _mixer;
        Type _cache;

        /// <summary>Whether <paramref name="camera"/> is driven by a CinemachineBrain (of either version) on its GameObject.</summary>
        public static Component BrainOn(Camera camera)
        {
            foreach (var behaviour in camera.GetComponents<MonoBehaviour>())
                if (behaviour != null && IsBrainType(behaviour.GetType())) return behaviour;
            return null;
        }

        static bool IsBrainType(Type type)
        {
            for (var t = type; t != null; t = t.BaseType)
                if (t.FullName == "Cinemachine.CinemachineBrain" || t.FullName == "Unity.Cinemachine.CinemachineBrain") return true;
            return false;
        }

        /// <summary>The API of the Cinemachine that <paramref name="brain"/> belongs to.</summary>
        public static CinemachineApi Of(Component brain)
        {
            var api = new CinemachineApi();
            var type = brain.GetType(); // a user's subclass of the brain: its Cinemachine base names the version
            while (type.FullName != "Cinemachine.CinemachineBrain" && type.FullName != "Unity.Cinemachine.CinemachineBrain") type = type.BaseType;
            api.Brain = type;
            var assembly = type.Assembly;
            var v3 = type.Namespace == "Unity.Cinemachine";
            api.Version = v3 ? "3.x" : "2.x";
            var ns = v3 ? "Unity.Cinemachine." : "Cinemachine.";
            api.VirtualCameraBase = assembly.GetType(ns + "CinemachineVirtualCameraBase");
            api._core = assembly.GetType(ns + "CinemachineCore");
            api._cache = assembly.GetType(ns + "TargetPositionCache");
            api._mixer = assembly.GetType(v3 ? "Unity.Cinemachine.CinemachinePlayableMixer" : "CinemachineMixer");
            return api;
        }

        /// <summary>The soloed virtual camera (a static all brains obey), or null.</summary>
        public object SoloCamera =>
            (Version == "3.x" ? _core : Brain)?.GetProperty("SoloCamera", Static)?.GetValue(null);

        /// <summary>
        /// Sets Cinemachine's statics for a scrubbing evaluation and returns what restores them: the uniform
        /// delta-time override off (-1), Timeline's cached scrubbing off, no master director (so the mixer passes
        /// deltaTime -1, as when the Timeline window scrubs without a cache).
        /// </summary>
        public IDisposable Scrubbing()
        {
            var restore = new List<Action>();
            Set(_core, "UniformDeltaTimeOverride", -1f, restore);
            Set(_cache, "UseCache", false, restore);
            Set(_mixer, "GetMasterPlayableDirector", null, restore);
            return new Restorer(restore);
        }

        static void Set(Type type, string name, object value, List<Action> restore)
        {
            var field = type?.GetField(name, Static);
            if (field == null) return; // absent in this version: nothing of it to neutralise
            var old = field.GetValue(null);
            field.SetValue(null, value);
            restore.Add(() => field.SetValue(null, old));
        }

        sealed class Restorer : IDisposable
        {
            readonly List<Action> _actions;
            public Restorer(List<Action> actions) { _actions = actions; }
            public void Dispose()
            {
                for (var i = _actions.Count - 1; i >= 0; i--) _actions[i]();
                _actions.Clear();
            }
        }

        /// <summary>The brain's own update: vcams, blends, then its Camera's transform and lens (public in both versions).</summary>
        public void ManualUpdate(Component brain) => Invoke(brain, "ManualUpdate");

        /// <summary>The virtual cameras the brain's output comes from: its active camera and, in a blend, both sides, nested blends opened.</summary>
        public List<Component> LiveCameras(Component brain)
        {
            var live = new List<Component>();
            Collect(Get(brain, "ActiveVirtualCamera"), live, 0);
            var blend = Get(brain, "ActiveBlend");
            if (blend != null) CollectBlend(blend, live, 0);
            return live;
        }

        static void CollectBlend(object blend, List<Component> live, int depth)
        {
            Collect(Get(blend, "CamA"), live, depth + 1);
            Collect(Get(blend, "CamB"), live, depth + 1);
        }

        static void Collect(object camera, List<Component> live, int depth)
        {
            if (camera == null || depth > 16) return;
            if (camera is Component c)
            {
                if (c != null && !live.Contains(c)) live.Add(c);
                return;
            }
            // A blend in progress as one side of another (Cinemachine's internal BlendSourceVirtualCamera.Blend,
            // 2.10.3 CinemachineBlend.cs:290–293); another kind of camera has no pose of its own to check.
            var property = camera.GetType().GetProperty("Blend", Instance);
            var inner = property == null ? null : property.GetValue(camera);
            if (inner != null) CollectBlend(inner, live, depth);
        }

        /// <summary>The virtual camera's longest damping in seconds (<c>GetMaxDampTime()</c>), 0 when it has none.</summary>
        public static float MaxDampTime(Component vcam) => Invoke(vcam, "GetMaxDampTime") is float f ? f : 0f;

        public static Transform Follow(Component vcam) => Get(vcam, "Follow") as Transform;
        public static Transform LookAt(Component vcam) => Get(vcam, "LookAt") as Transform;

        /// <summary>
        /// The Cinemachine tracks of <paramref name="director"/>'s Timeline bound to <paramref name="brain"/>, unmuted,
        /// with their clips as shot spans (TimelineAsset.GetOutputTracks, TrackAsset.muted / GetClips, TimelineClip.start /
        /// end / displayName: com.unity.timeline, read by name).
        /// </summary>
        public static List<KeyValuePair<string, List<ShotSpan>>> TracksDriving(PlayableDirector director, Component brain)
        {
            var result = new List<KeyValuePair<string, List<ShotSpan>>>();
            var asset = director.playableAsset;
            if (asset == null || !(Invoke(asset, "GetOutputTracks") is IEnumerable tracks)) return result;
            foreach (var track in tracks)
            {
                if (!(track is Object trackObject) || trackObject.GetType().Name != "CinemachineTrack") continue;
                if (Get(track, "muted") is bool muted && muted) continue;
                if (director.GetGenericBinding(trackObject) != brain) continue;
                var shots = new List<ShotSpan>();
                if (Invoke(track, "GetClips") is IEnumerable clips)
                    foreach (var clip in clips)
                        shots.Add(new ShotSpan(Get(clip, "displayName") as string ?? "shot", ToDouble(Get(clip, "start")), ToDouble(Get(clip, "end"))));
                result.Add(new KeyValuePair<string, List<ShotSpan>>(asset.name + " / " + trackObject.name, shots));
            }
            return result;
        }

        static double ToDouble(object value) => value is IConvertible c ? c.ToDouble(System.Globalization.CultureInfo.InvariantCulture) : double.NaN;

        static object Get(object o, string name)
        {
            var type = o.GetType();
            var property = type.GetProperty(name, Instance);
            if (property != null && property.GetIndexParameters().Length == 0) return property.GetValue(o);
            var field = type.GetField(name, Instance);
            if (field != null) return field.GetValue(o);
            throw new MissingMemberException(type.FullName, name);
        }

        static object Invoke(object o, string name)
        {
            var method = o.GetType().GetMethod(name, Instance, null, Type.EmptyTypes, null);
            if (method == null) throw new MissingMemberException(o.GetType().FullName, name);
            return method.Invoke(o, null);
        }
    }
}
