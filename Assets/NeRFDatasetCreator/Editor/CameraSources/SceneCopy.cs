using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.Playables;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Every root object of a scene, copied into a preview scene with the references <b>between</b> roots pointing at
    /// the copies. <c>Object.Instantiate</c> remaps references inside the copied hierarchy only; a Cinemachine rig spans
    /// roots — the brain on the camera, the virtual cameras, the PlayableDirector whose Cinemachine track binds the
    /// brain and whose shots name the virtual cameras by ExposedReference, the follow targets — so after copying, every
    /// object reference of every copied component that names an original is set to its copy through
    /// <c>SerializedObject</c>: that covers the director's scene bindings (<c>m_SceneBindings</c>, as DirectorEditor
    /// reads them, UnityCsReference 2022.3 Editor/Mono/Inspector/DirectorEditor.cs:83, 233–235) and its exposed
    /// references (<c>m_ExposedReferences</c>, the table <c>SetReferenceValue</c> fills, Modules/Director/ScriptBindings/
    /// PlayableDirector.bindings.cs:95). A scene holds no serialized reference into another scene, so one scene's roots are
    /// a closed set. The user's objects are only read; the copies are built under an inactive holder and scripts are
    /// disabled (all but those the caller keeps) before anything is activated, as the capture does. <see cref="OfObject"/> is the
    /// same for one object, for the dynamic capture's measurement and the animated-camera sampler.
    /// </summary>
    sealed class SceneCopy : IDisposable
    {
        readonly Dictionary<Object, Object> _toCopy = new Dictionary<Object, Object>();
        readonly Dictionary<Object, Object> _toOriginal = new Dictionary<Object, Object>();

        public Scene Preview { get; private set; }
        public GameObject Holder { get; private set; }

        public static SceneCopy Of(Scene scene, Func<MonoBehaviour, bool> keepEnabled)
        {
            var copy = Begin("NeRF Dataset Creator scene copy");
            try
            {
                var pairs = new List<KeyValuePair<GameObject, GameObject>>();
                foreach (var root in scene.GetRootGameObjects())
                {
                    var clone = Object.Instantiate(root, copy.Holder.transform, true);
                    clone.name = root.name;
                    pairs.Add(new KeyValuePair<GameObject, GameObject>(root, clone));
                    copy.Map(root, clone);
                }
                copy.Remap();
                foreach (var pair in pairs) Quiet(pair.Value, keepEnabled);
                copy.Holder.SetActive(true);
                return copy;
            }
            catch
            {
                copy.Dispose();
                throw;
            }
        }

        /// <summary>
        /// A copy of one object and its children (<see cref="Root"/>), active even if the original is not, every script
        /// disabled: what the dynamic capture's measurement and the animated-camera sampler pose with
        /// <see cref="ContentClock"/>. References inside the hierarchy are remapped by <c>Object.Instantiate</c> itself.
        /// LOD 0 only, as the capture's own copy (<see cref="LodZero.Apply"/> with the original's parents, review R4-7): the
        /// copy sits under the holder alone, so an LODGroup above the original is not above the copy, and
        /// <c>LodZero.BeyondLod0(copy)</c> would no longer see that group's LOD 1+ renderers (<c>LODGroup.GetLODs</c> lists
        /// the renderers of each level, UCR Runtime/Export/Graphics/LOD.bindings.cs:35, 73-74 on 2022.3.76f1 and 6000.0.78f1).
        /// Without this the per-step geometry, the dynamic points3d.ply and the posed bounds held every LOD level at once.
        /// </summary>
        public static SceneCopy OfObject(GameObject original, string purpose)
        {
            var copy = Begin("NeRF Dataset Creator " + purpose);
            try
            {
                copy.Root = Object.Instantiate(original, copy.Holder.transform, true);
                Quiet(copy.Root, script => false);
                LodZero.Apply(original, copy.Root);
                copy.Root.SetActive(true);
                copy.Holder.SetActive(true);
                return copy;
            }
            catch
            {
                copy.Dispose();
                throw;
            }
        }

        /// <summary>The copied object of <see cref="OfObject"/>.</summary>
        public GameObject Root { get; private set; }

        /// <summary>A preview scene with an inactive holder: nothing copied under it wakes before its scripts are off.</summary>
        static SceneCopy Begin(string holderName)
        {
            var copy = new SceneCopy { Preview = EditorSceneManager.NewPreviewScene() };
            try
            {
                copy.Holder = EditorUtility.CreateGameObjectWithHideFlags(holderName, HideFlags.HideAndDontSave);
                SceneManager.MoveGameObjectToScene(copy.Holder, copy.Preview);
                copy.Holder.SetActive(false);
                return copy;
            }
            catch
            {
                copy.Dispose();
                throw;
            }
        }

        /// <summary>Hides the copied objects and disables every script <paramref name="keepEnabled"/> does not accept.</summary>
        static void Quiet(GameObject clone, Func<MonoBehaviour, bool> keepEnabled)
        {
            foreach (var t in clone.GetComponentsInChildren<Transform>(true)) t.gameObject.hideFlags = HideFlags.HideAndDontSave;
            foreach (var script in clone.GetComponentsInChildren<MonoBehaviour>(true))
                if (script != null && !keepEnabled(script)) script.enabled = false;
        }

        /// <summary>The copy of a user's object (GameObject or component), or null.</summary>
        public T CopyOf<T>(T original) where T : Object => original != null && _toCopy.TryGetValue(original, out var c) ? c as T : null;

        /// <summary>The user's object a copy was made from, or null.</summary>
        public T OriginalOf<T>(T copy) where T : Object => copy != null && _toOriginal.TryGetValue(copy, out var o) ? o as T : null;

        void Map(GameObject original, GameObject clone)
        {
            // Instantiate keeps the hierarchy's order, so both walks pair up object by object and component by component.
            var from = original.GetComponentsInChildren<Transform>(true);
            var to = clone.GetComponentsInChildren<Transform>(true);
            if (from.Length != to.Length) throw new InvalidOperationException("The copy of " + original.name + " does not match it.");
            for (var i = 0; i < from.Length; i++)
            {
                Add(from[i].gameObject, to[i].gameObject);
                var a = from[i].GetComponents<Component>();
                var b = to[i].GetComponents<Component>();
                if (a.Length != b.Length) throw new InvalidOperationException("The copy of " + from[i].name + " does not match it.");
                for (var k = 0; k < a.Length; k++)
                    if (a[k] != null && b[k] != null) Add(a[k], b[k]);
            }
        }

        void Add(Object original, Object clone)
        {
            _toCopy[original] = clone;
            _toOriginal[clone] = original;
        }

        void Remap()
        {
            foreach (var clone in _toOriginal.Keys)
            {
                if (!(clone is Component component)) continue;
                var so = new SerializedObject(component);
                var it = so.GetIterator();
                var changed = false;
                while (it.Next(true))
                {
                    if (it.propertyType != SerializedPropertyType.ObjectReference) continue;
                    var value = it.objectReferenceValue;
                    if (value != null && _toCopy.TryGetValue(value, out var mapped))
                    {
                        it.objectReferenceValue = mapped;
                        changed = true;
                    }
                }
                if (changed) so.ApplyModifiedPropertiesWithoutUndo();
                if (component is PlayableDirector director) RemapBindings(director);
            }
        }

        /// <summary>The same for the director's track bindings through its public API, should the serialized names change.</summary>
        void RemapBindings(PlayableDirector director)
        {
            if (director.playableAsset == null) return;
            foreach (var output in director.playableAsset.outputs)
            {
                var key = output.sourceObject;
                if (key == null) continue;
                var bound = director.GetGenericBinding(key);
                if (bound != null && _toCopy.TryGetValue(bound, out var mapped)) director.SetGenericBinding(key, mapped);
            }
        }

        public void Dispose()
        {
            if (Preview.IsValid()) EditorSceneManager.ClosePreviewScene(Preview);
            if (Holder != null) Object.DestroyImmediate(Holder);
            _toCopy.Clear();
            _toOriginal.Clear();
        }
    }
}
