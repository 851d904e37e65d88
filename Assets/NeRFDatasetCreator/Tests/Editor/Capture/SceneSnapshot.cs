using System.Collections.Generic;
using System.Linq;
using System.Text;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Everything a capture must leave as it was in the user's loaded scenes: which objects exist (by instance id)
    /// and, per object, name, parent, layer, tag, active state, hide flags, pose, components and their enabled
    /// states and materials; per scene its root count and dirty flag.
    /// </summary>
    static class SceneSnapshot
    {
        public static string Take()
        {
            var text = new StringBuilder();
            for (var s = 0; s < SceneManager.sceneCount; s++)
            {
                var scene = SceneManager.GetSceneAt(s);
                text.Append("scene ").Append(scene.path).Append(" loaded=").Append(scene.isLoaded)
                    .Append(" dirty=").Append(scene.isDirty).Append(" roots=").Append(scene.rootCount).Append('\n');
                if (!scene.isLoaded) continue;
                foreach (var root in scene.GetRootGameObjects())
                foreach (var t in root.GetComponentsInChildren<Transform>(true))
                    Describe(t.gameObject, text);
            }
            text.Append("active RT=").Append(RenderTexture.active == null ? "null" : RenderTexture.active.name);
            return text.ToString();
        }

        static void Describe(GameObject go, StringBuilder text)
        {
            var t = go.transform;
            text.Append(go.GetInstanceID()).Append(' ').Append(go.name)
                .Append(" parent=").Append(t.parent == null ? 0 : t.parent.gameObject.GetInstanceID())
                .Append(" layer=").Append(go.layer).Append(" tag=").Append(go.tag)
                .Append(" active=").Append(go.activeSelf).Append(" flags=").Append(go.hideFlags)
                .Append(" pos=").Append(t.localPosition.ToString("R")).Append(" rot=").Append(t.localRotation.ToString("R"))
                .Append(" scale=").Append(t.localScale.ToString("R"));
            foreach (var c in go.GetComponents<Component>())
            {
                if (c == null) continue;
                text.Append(" | ").Append(c.GetType().Name).Append('#').Append(c.GetInstanceID());
                if (c is Behaviour b) text.Append(" enabled=").Append(b.enabled);
                if (c is Renderer r)
                    text.Append(" enabled=").Append(r.enabled).Append(" materials=")
                        .Append(string.Join(",", r.sharedMaterials.Select(m => m == null ? "null" : m.GetInstanceID().ToString())));
            }
            text.Append('\n');
        }

        public static List<string> Lines(string snapshot) => snapshot.Split('\n').ToList();
    }
}
