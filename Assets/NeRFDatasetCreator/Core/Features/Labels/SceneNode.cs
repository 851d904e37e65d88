using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One GameObject on the way from a scene root down to a renderer, as the Unity layer reads it: everything the
    /// label rules need, nothing of Unity's. Filled by the Editor from <c>Transform.GetSiblingIndex</c>,
    /// <c>GameObject.tag</c>, <c>LayerMask.LayerToName(layer)</c> and <c>PrefabUtility</c>.
    /// </summary>
    public sealed class SceneNode
    {
        public SceneNode(string name, int siblingIndex, string tag = "", string layer = "", string prefabAsset = "")
        {
            Name = name ?? "";
            if (siblingIndex < 0) throw new ArgumentOutOfRangeException(nameof(siblingIndex), siblingIndex, "a sibling index is never negative");
            SiblingIndex = siblingIndex;
            Tag = tag ?? "";
            Layer = layer ?? "";
            PrefabAsset = prefabAsset ?? "";
        }

        /// <summary>The GameObject's name.</summary>
        public string Name { get; }

        /// <summary>Its place among its siblings (or among the scene's roots): <c>Transform.GetSiblingIndex()</c>.</summary>
        public int SiblingIndex { get; }

        /// <summary><c>GameObject.tag</c> ("Untagged" when none was set).</summary>
        public string Tag { get; }

        /// <summary>The layer's name, <c>LayerMask.LayerToName(gameObject.layer)</c>.</summary>
        public string Layer { get; }

        /// <summary>
        /// Set only when this GameObject is the root of a prefab instance (<c>PrefabUtility.IsAnyPrefabInstanceRoot</c>):
        /// the project path of its prefab asset (<c>PrefabUtility.GetPrefabAssetPathOfNearestInstanceRoot</c>), e.g.
        /// <c>Assets/Props/Car.prefab</c>. Empty otherwise.
        /// </summary>
        public string PrefabAsset { get; }

        public bool IsPrefabInstanceRoot => PrefabAsset.Length > 0;
    }
}
