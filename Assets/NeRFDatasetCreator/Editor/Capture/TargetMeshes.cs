using System.Collections.Generic;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The meshes a capture of a target renders — one rule for checking the target, measuring it and sampling its
    /// surface: enabled MeshRenderers with a MeshFilter mesh and SkinnedMeshRenderers with a shared mesh, on the target
    /// and its children that are active below it (the target's own active state is ignored: its copy is activated),
    /// at LOD 0 only (<see cref="LodZero"/>). Particles, lines, sprites and terrains are not among them.
    /// </summary>
    static class TargetMeshes
    {
        public static IEnumerable<KeyValuePair<Renderer, Mesh>> Of(GameObject target)
        {
            if (target == null) yield break;
            var beyondLod0 = LodZero.BeyondLod0(target);
            foreach (var renderer in target.GetComponentsInChildren<Renderer>(true))
            {
                if (!renderer.enabled || !ActiveBelow(renderer.transform, target.transform) || beyondLod0.Contains(renderer)) continue;
                Mesh mesh = null;
                if (renderer is SkinnedMeshRenderer skinned) mesh = skinned.sharedMesh;
                else if (renderer is MeshRenderer)
                {
                    var filter = renderer.GetComponent<MeshFilter>();
                    if (filter != null) mesh = filter.sharedMesh;
                }
                if (mesh != null) yield return new KeyValuePair<Renderer, Mesh>(renderer, mesh);
            }
        }

        /// <summary>Whether <paramref name="t"/> is active, ignoring the target's own and its parents' active states.</summary>
        static bool ActiveBelow(Transform t, Transform target)
        {
            for (; t != null && t != target; t = t.parent)
                if (!t.gameObject.activeSelf) return false;
            return true;
        }

        /// <summary>
        /// World-space bounds of the meshes, from each mesh's own bounds and its transform — plain data, so they are
        /// right for an inactive target too (Renderer.bounds is only kept up to date for active renderers). Skinned
        /// meshes are measured in their bind pose. Null when there is no mesh.
        /// </summary>
        /// <param name="includeSkinned">False leaves skinned meshes out (a dynamic capture measures them posed, see TimeMeasurement).</param>
        public static Bounds? WorldBounds(GameObject target, bool includeSkinned = true)
        {
            Bounds? all = null;
            foreach (var pair in Of(target))
            {
                if (!includeSkinned && pair.Key is SkinnedMeshRenderer) continue;
                var local = pair.Value.bounds;
                var toWorld = pair.Key.transform.localToWorldMatrix;
                for (var corner = 0; corner < 8; corner++)
                {
                    var p = local.center + Vector3.Scale(local.extents, new Vector3(
                        (corner & 1) == 0 ? -1 : 1, (corner & 2) == 0 ? -1 : 1, (corner & 4) == 0 ? -1 : 1));
                    var world = toWorld.MultiplyPoint3x4(p);
                    if (all.HasValue)
                    {
                        var grown = all.Value;
                        grown.Encapsulate(world);
                        all = grown;
                    }
                    else all = new Bounds(world, Vector3.zero);
                }
            }
            return all;
        }
    }
}
