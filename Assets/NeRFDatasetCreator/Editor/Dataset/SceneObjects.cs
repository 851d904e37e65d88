using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Finds scene objects by hierarchy path ("Root/Child/Grandchild") or, failing that, by name.</summary>
    static class SceneObjects
    {
        /// <summary>The first match in the loaded scenes, inactive objects included; null when none.</summary>
        public static GameObject Find(string pathOrName)
        {
            if (string.IsNullOrWhiteSpace(pathOrName)) return null;
            var path = pathOrName.Trim().Trim('/');
            var slash = path.IndexOf('/');
            var rootName = slash < 0 ? path : path.Substring(0, slash);
            GameObject byName = null;
            for (var s = 0; s < SceneManager.sceneCount; s++)
            {
                var scene = SceneManager.GetSceneAt(s);
                if (!scene.isLoaded) continue;
                foreach (var root in scene.GetRootGameObjects())
                {
                    if (root.name == rootName)
                    {
                        if (slash < 0) return root;
                        var child = root.transform.Find(path.Substring(slash + 1));
                        if (child != null) return child.gameObject;
                    }
                    if (byName == null && slash < 0) byName = FindByName(root.transform, path);
                }
            }
            return byName;
        }

        static GameObject FindByName(Transform t, string name)
        {
            if (t.name == name) return t.gameObject;
            for (var i = 0; i < t.childCount; i++)
            {
                var found = FindByName(t.GetChild(i), name);
                if (found != null) return found;
            }
            return null;
        }
    }
}
