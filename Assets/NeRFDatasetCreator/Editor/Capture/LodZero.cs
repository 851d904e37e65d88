using System.Collections.Generic;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// A capture uses LOD 0 only, everywhere: the measured bounds, the rendered images and the point cloud. A renderer
    /// that only a higher LOD level of some LODGroup lists (LOD.renderers, UnityCsReference 2022.3
    /// Runtime/Export/Graphics/LOD.bindings.cs:34-35, GetLODs :73-74) is left out; a renderer in LOD 0 stays.
    /// LODGroups both on or under the target and above it count: a target picked below its LODGroup is copied without
    /// that group, so its copies would otherwise draw every level at once. Both the capture's copy (CaptureStage) and
    /// the posed copies of <see cref="SceneCopy.OfObject"/> (time measurement, per-step geometry) apply it. Lines as in
    /// 6000.0.78f1 too (LOD.bindings.cs:35, 73-74, 86-87).
    /// </summary>
    static class LodZero
    {
        /// <summary>Renderers of <paramref name="root"/> (and its children) that LOD 0 of their LODGroup does not draw.</summary>
        public static HashSet<Renderer> BeyondLod0(GameObject root)
        {
            var beyond = new HashSet<Renderer>();
            if (root == null) return beyond;
            var groups = new List<LODGroup>(root.GetComponentsInChildren<LODGroup>(true));
            foreach (var parent in root.GetComponentsInParent<LODGroup>(true))
                if (!groups.Contains(parent)) groups.Add(parent);
            foreach (var group in groups)
            {
                var lods = group.GetLODs();
                if (lods.Length < 2) continue;
                var lod0 = new HashSet<Renderer>();
                foreach (var r in lods[0].renderers) if (r != null) lod0.Add(r);
                for (var level = 1; level < lods.Length; level++)
                    foreach (var r in lods[level].renderers)
                        if (r != null && !lod0.Contains(r)) beyond.Add(r);
            }
            return beyond;
        }

        /// <summary>
        /// On a fresh copy (<c>Object.Instantiate</c> of <paramref name="source"/>, same hierarchy): disables the
        /// renderers whose originals are beyond LOD 0, and forces LOD 0 on the copy's own LODGroups, so that distance
        /// never switches a view to another level or culls it (LODGroup.ForceLOD, LOD.bindings.cs:86-87 in 2022.3, :87 in
        /// 6000.0; Scripting API: "Force a LOD level on this LOD group"). LODGroups are not disabled: that turns off all
        /// their renderers (LOD.bindings.cs:66).
        /// </summary>
        public static void Apply(GameObject source, GameObject copy)
        {
            var beyond = BeyondLod0(source);
            if (beyond.Count > 0)
            {
                var originals = source.GetComponentsInChildren<Renderer>(true);
                var copies = copy.GetComponentsInChildren<Renderer>(true);
                if (originals.Length == copies.Length)
                    for (var i = 0; i < originals.Length; i++)
                        if (beyond.Contains(originals[i])) copies[i].enabled = false;
            }
            foreach (var group in copy.GetComponentsInChildren<LODGroup>(true)) group.ForceLOD(0);
        }
    }
}
