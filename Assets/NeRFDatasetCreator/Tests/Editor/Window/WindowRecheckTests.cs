using System.Collections;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.TestTools;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Review S3-2: the window's re-checks must not run at its 10 Hz tick. A dynamic capture of an animated cube with an
    /// animated camera as the test split's source makes every check copy the target (time measurement) and the camera's
    /// root (sampling); an open, idle window must run <see cref="DatasetCapture.Prepare"/> once, not again and again
    /// (which it would if the copies' own hierarchy or object-change events re-triggered it).
    /// </summary>
    public class WindowRecheckTests
    {
        [UnityTest]
        public IEnumerator AnIdleWindowOnADynamicConfigPreparesOnce()
        {
            var scene = TestScene.Open();
            var store = NerfDatasetCreatorSettings.instance;
            var saved = store.Settings.Clone();
            NerfDatasetCreatorWindow window = null;
            try
            {
                var cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
                cube.name = "Recheck cube";
                var slide = new AnimationClip { name = "slide", legacy = true };
                slide.SetCurve("", typeof(Transform), "localPosition.x", AnimationCurve.Linear(0, 0, 2, 2));
                var animation = cube.AddComponent<Animation>();
                animation.AddClip(slide, slide.name);
                animation.clip = slide;
                var rig = new GameObject("Recheck rig");
                var cam = new GameObject("Cam", typeof(Camera));
                cam.transform.SetParent(rig.transform, false);
                var fly = new AnimationClip { name = "fly", legacy = true };
                fly.SetCurve("Cam", typeof(Transform), "localPosition.z", AnimationCurve.Linear(0, -8, 2, -6));
                var rigAnimation = rig.AddComponent<Animation>();
                rigAnimation.AddClip(fly, fly.name);
                rigAnimation.clip = fly;

                var settings = new DatasetSettings { Name = "recheck", Width = 64, Height = 64, Supersampling = 1, Distance = 8, Seed = 1 };
                settings.Target = SceneObjectPath.Of(cube);
                settings.Scene = cube.scene.path;
                settings.Loaders = TargetLoaders.GaussianSplatting;
                settings.Train.Count = 4;
                settings.Val.Count = 0;
                settings.Test.Source = new CameraSourceSettings { Kind = CameraSourceKind.AnimatedCamera, ObjectPath = "Recheck rig/Cam", Samples = 3 };
                settings.Time.Mode = TimeMode.Monocular;
                settings.Time.EndAtClipLength = true;
                store.Apply(settings, "NeRF recheck test");

                window = EditorWindow.GetWindow<NerfDatasetCreatorWindow>("NeRF Dataset Creator");
                var before = DatasetCapture.PrepareCalls;
                var until = EditorApplication.timeSinceStartup + 2.5;
                while (EditorApplication.timeSinceStartup < until) yield return null;
                var calls = DatasetCapture.PrepareCalls - before;
                Assert.That(calls, Is.LessThanOrEqualTo(1), "an idle window re-checked " + calls + " times in 2.5 s");
                Assert.That(calls, Is.EqualTo(1), "the window checks the configuration once after it opens");
            }
            finally
            {
                if (window != null) window.Close();
                store.Apply(saved, "NeRF recheck test");
                TestScene.Close(scene);
            }
        }
    }
}
