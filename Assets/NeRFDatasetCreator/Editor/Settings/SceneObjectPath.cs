using System.Collections.Generic;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Scene objects by hierarchy path (<see cref="HierarchyPath"/>), so the window can find its target and template
    /// camera again after Unity restarts, from the path stored in the settings file.
    /// </summary>
    public static class SceneObjectPath
    {
        /// <summary>"Root/Child/Object" for a scene object; empty for null.</summary>
        public static string Of(GameObject gameObject)
        {
            if (gameObject == null) return "";
            var names = new List<string>();
            for (var t = gameObject.transform; t != null; t = t.parent) names.Add(t.name);
            names.Reverse();
            return HierarchyPath.Join(names);
        }

        /// <summary>The warning for a path that will not find the object again (a name with '/'), or null.</summary>
        public static ValidationProblem Check(string field, GameObject gameObject)
        {
            if (gameObject == null) return null;
            var names = new List<string>();
            for (var t = gameObject.transform; t != null; t = t.parent) names.Add(t.name);
            return HierarchyPath.CheckNames(field, names);
        }

        /// <summary>The first object at <paramref name="path"/> in the loaded scenes, in scene order, or null.</summary>
        public static GameObject Find(string path)
        {
            var names = HierarchyPath.Split(path);
            if (names.Count == 0) return null;
            var below = names.Count > 1 ? string.Join(HierarchyPath.Separator.ToString(), System.Linq.Enumerable.Skip(names, 1)) : null;
            for (var s = 0; s < SceneManager.sceneCount; s++)
            {
                var scene = SceneManager.GetSceneAt(s);
                if (!scene.isLoaded) continue;
                foreach (var root in scene.GetRootGameObjects())
                {
                    if (root.name != names[0]) continue;
                    if (below == null) return root;
                    var found = root.transform.Find(below);
                    if (found != null) return found.gameObject;
                }
            }
            return null;
        }
    }
}
