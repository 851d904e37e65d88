using NUnit.Framework;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// A scene of the test's own, made active, and closed again afterwards, without touching the user's scenes.
    /// Unity refuses to add a scene next to an untitled one ("Cannot create a new scene additively with an untitled
    /// scene unsaved"), which is what a batch-mode test run starts with: a lone untitled scene that is unmodified or
    /// empty is replaced instead (nothing is lost); otherwise the test is ignored rather than discard unsaved work.
    /// </summary>
    public static class TestScene
    {
        /// <summary>Ignores the test where nothing can be rendered: no graphics device (-nographics), or HDRP.</summary>
        public static void RequireRendering()
        {
            if (SystemInfo.graphicsDeviceType == GraphicsDeviceType.Null)
                Assert.Ignore("no graphics device (Unity runs with -nographics): nothing can be rendered");
            if (CaptureEnvironment.IsHdrp) Assert.Ignore("HDRP is not supported by the capture");
        }

        /// <summary>Unity's primitive sphere (radius 0.5, at the origin) in the active scene, with a directional light.</summary>
        public static GameObject LitSphere(string name)
        {
            var sphere = GameObject.CreatePrimitive(PrimitiveType.Sphere);
            sphere.name = name;
            var light = new GameObject(name + " light", typeof(Light));
            light.GetComponent<Light>().type = LightType.Directional;
            light.transform.rotation = Quaternion.Euler(50, -30, 0);
            return sphere;
        }

        public static Scene Open()
        {
            var mode = NewSceneMode.Additive;
            for (var i = 0; i < SceneManager.sceneCount; i++)
            {
                var open = SceneManager.GetSceneAt(i);
                if (!string.IsNullOrEmpty(open.path)) continue;
                // Replaceable: the only scene, and either unchanged since it was made or empty.
                if (SceneManager.sceneCount > 1 || (open.isDirty && open.rootCount > 0))
                    Assert.Ignore("An unsaved untitled scene is open, and Unity cannot add the test's scene next to it. " +
                                  "Save or close it, then run this test again.");
                mode = NewSceneMode.Single;
            }
            var scene = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, mode);
            SceneManager.SetActiveScene(scene);
            return scene;
        }

        public static void Close(Scene scene)
        {
            if (!scene.IsValid()) return;
            // The last loaded scene cannot be closed: give it back as the empty untitled scene it replaced.
            if (SceneManager.sceneCount > 1) EditorSceneManager.CloseScene(scene, true);
            else EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);
        }
    }
}
