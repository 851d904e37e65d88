using System.Collections.Generic;
using UnityEditor;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The labels of a capture: describes the user's renderers under the target (every root object of the loaded scenes
    /// for a whole-scene capture) as Core <see cref="SceneObjectInfo"/> chains, lets Core's <see cref="LabelTable"/> give
    /// them ids, and returns the ids per renderer for the labels pass (<see cref="CaptureOptions.Labels"/>). Only reads
    /// the scene. Unity facts, from UCR 2022.3 / 6000.0: <c>Transform.GetSiblingIndex</c>
    /// (Runtime/Transform/ScriptBindings/Transform.bindings.cs:418 / :388), <c>LayerMask.LayerToName</c>
    /// (Runtime/Export/Scripting/LayerMask.bindings.cs:44), <c>PrefabUtility.IsAnyPrefabInstanceRoot</c> and
    /// <c>GetPrefabAssetPathOfNearestInstanceRoot</c> (Editor/Mono/Prefabs/PrefabUtility.cs:1844, 1856 / 2084, 2096).
    /// A root's sibling index is its place among its own scene's roots (the per-scene root list of
    /// <c>Scene.GetRootGameObjects</c>, Runtime/Export/SceneManager/Scene.cs:85-109 on both lines; <c>GetSiblingIndex</c>
    /// itself is native), so two loaded scenes repeat root indices: a whole-scene capture with several loaded scenes puts
    /// each chain under its scene (Core's <see cref="LabelScenes"/>, review R4-4). <c>SceneManager.sceneCount</c> and
    /// <c>GetSceneAt</c> (Runtime/Export/SceneManager/SceneManager.bindings.cs:55, 99 on both lines) give the loaded scenes
    /// in the hierarchy window's order.
    /// </summary>
    public static class SceneLabels
    {
        public sealed class Result
        {
            public LabelTable Table;
            public Dictionary<Renderer, RendererLabelIds> Ids;
        }

        /// <param name="everyRenderer">
        /// A dynamic capture: every mesh renderer is described, enabled or not, so an object an animation switches on at
        /// some time step has its id from the start — the same in every shard, whatever views it renders. A static
        /// capture describes what its camera draws (enabled, active, not shadows-only).
        /// </param>
        public static Result Collect(LabelSettings settings, GameObject target, CaptureIsolation isolation, int cullingMask, bool everyRenderer)
        {
            var infos = new List<SceneObjectInfo>();
            var renderers = new List<Renderer>();
            var loaded = LoadedScenes();
            var qualify = isolation == CaptureIsolation.WholeScene && LabelScenes.Qualifies(loaded.Count);
            foreach (var source in Sources(target, isolation, loaded))
            {
                var beyondLod0 = LodZero.BeyondLod0(source);
                foreach (var renderer in source.GetComponentsInChildren<Renderer>(true))
                {
                    if (!(renderer is MeshRenderer || renderer is SkinnedMeshRenderer) || beyondLod0.Contains(renderer)) continue;
                    if (renderer.shadowCastingMode == ShadowCastingMode.ShadowsOnly || (cullingMask & (1 << renderer.gameObject.layer)) == 0) continue;
                    if (!everyRenderer && (!renderer.enabled || !ActiveBelow(renderer.transform, source.transform))) continue;
                    var info = Describe(renderer, isolation == CaptureIsolation.WholeScene ? null : target.transform);
                    if (qualify)
                    {
                        var scene = renderer.gameObject.scene;
                        info = LabelScenes.InScene(info, scene.name, loaded.IndexOf(scene));
                    }
                    infos.Add(info);
                    renderers.Add(renderer);
                }
            }
            var table = LabelTable.Build(settings, infos);
            var ids = new Dictionary<Renderer, RendererLabelIds>();
            for (var i = 0; i < renderers.Count; i++)
            {
                var instance = table.InstanceIdOf(infos[i]);
                ids[renderers[i]] = new RendererLabelIds(instance, table.ClassIdOf(instance));
            }
            return new Result { Table = table, Ids = ids };
        }

        /// <summary>What a capture copies (CaptureStage's sources): the target, or every active root object of the loaded scenes.</summary>
        static IEnumerable<GameObject> Sources(GameObject target, CaptureIsolation isolation, List<Scene> loaded)
        {
            if (isolation == CaptureIsolation.TargetOnly)
            {
                if (target != null) yield return target;
                yield break;
            }
            foreach (var scene in loaded)
            foreach (var root in scene.GetRootGameObjects())
                if ((root.hideFlags & HideFlags.DontSave) == 0 && root.activeInHierarchy) yield return root;
        }

        /// <summary>The loaded scenes in the hierarchy window's order; a scene's place here is its label node's index.</summary>
        static List<Scene> LoadedScenes()
        {
            var loaded = new List<Scene>();
            for (var i = 0; i < SceneManager.sceneCount; i++)
            {
                var scene = SceneManager.GetSceneAt(i);
                if (scene.isLoaded) loaded.Add(scene);
            }
            return loaded;
        }

        /// <summary>Active below <paramref name="source"/>: the target's copy is activated whatever the target's own state (as TargetMeshes).</summary>
        static bool ActiveBelow(Transform t, Transform source)
        {
            for (; t != null && t != source; t = t.parent)
                if (!t.gameObject.activeSelf) return false;
            return true;
        }

        /// <summary>The chain from the renderer's scene root down to its GameObject; <paramref name="target"/> null for the whole scene.</summary>
        internal static SceneObjectInfo Describe(Renderer renderer, Transform target)
        {
            var chain = new List<SceneNode>();
            var targetDepth = 0;
            for (var t = renderer.transform; t != null; t = t.parent) chain.Add(Node(t.gameObject));
            chain.Reverse();
            if (target != null)
            {
                var depth = 0;
                for (var t = target; t != null; t = t.parent) depth++;
                targetDepth = depth;
            }
            return new SceneObjectInfo(chain, targetDepth, renderer.gameObject.GetInstanceID());
        }

        static SceneNode Node(GameObject go)
        {
            // Only a prefab instance's root names its asset: the object the "prefab" instance rule and class source group by.
            var prefab = PrefabUtility.IsAnyPrefabInstanceRoot(go) ? PrefabUtility.GetPrefabAssetPathOfNearestInstanceRoot(go) : "";
            return new SceneNode(go.name, go.transform.GetSiblingIndex(), go.tag, LayerMask.LayerToName(go.layer), prefab);
        }
    }
}
