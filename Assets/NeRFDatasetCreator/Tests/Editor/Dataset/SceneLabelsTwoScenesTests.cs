using System;
using System.Linq;
using NUnit.Framework;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Review R4-4 in the Editor: two saved scenes made from one template, Room_01 and Room_02, each with a root "Room"
    /// holding a cube "Wall" (both at sibling index 0). A whole-scene capture's labels (<see cref="SceneLabels.Collect"/>)
    /// give the two walls two ids and name their scenes; with Room_02 closed, the remaining wall keeps the scene-less path
    /// a single-scene capture always wrote. No rendering: only the scene is read. The scenes are saved to a folder of
    /// the test's own under Assets (Unity adds a scene next to an untitled one only when that one is saved), which
    /// TearDown deletes, restoring the user's scene setup.
    /// </summary>
    [TestFixture]
    public class SceneLabelsTwoScenesTests
    {
        SceneSetup[] _setup;
        string _folder;

        [SetUp]
        public void SetUp()
        {
            for (var i = 0; i < SceneManager.sceneCount; i++)
                if (SceneManager.GetSceneAt(i).isDirty)
                    Assert.Ignore("A scene with unsaved changes is open; this test replaces the open scenes. Save or close it, then run again.");
            _setup = EditorSceneManager.GetSceneManagerSetup();
            _folder = "Assets/nerf-label-scenes-" + Guid.NewGuid().ToString("N");
            AssetDatabase.CreateFolder("Assets", _folder.Substring("Assets/".Length));
        }

        [TearDown]
        public void TearDown()
        {
            if (_setup != null && _setup.Length > 0 && _setup.All(s => !string.IsNullOrEmpty(s.path)))
                EditorSceneManager.RestoreSceneManagerSetup(_setup);
            else
                EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);
            if (_folder != null) AssetDatabase.DeleteAsset(_folder);
        }

        /// <summary>A saved scene <paramref name="name"/> holding Room/Wall; the first replaces the open scenes.</summary>
        Scene Room(string name, NewSceneMode mode, out Renderer wall)
        {
            var scene = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, mode);
            SceneManager.SetActiveScene(scene);
            var room = new GameObject("Room");
            var cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
            cube.name = "Wall";
            cube.transform.SetParent(room.transform, false);
            wall = cube.GetComponent<Renderer>();
            Assert.That(EditorSceneManager.SaveScene(scene, _folder + "/" + name + ".unity"), Is.True, "saved " + name);
            Assert.That(room.transform.GetSiblingIndex(), Is.EqualTo(0));
            return scene;
        }

        static LabelSettings Settings(InstanceRule rule) => new LabelSettings { Enabled = true, Instances = rule, ClassFrom = ClassSource.Name };

        [TestCase(InstanceRule.Renderer, "Room_01/Room/Wall", "Room_02/Room/Wall")]
        [TestCase(InstanceRule.TargetChild, "Room_01/Room", "Room_02/Room")]
        public void TwoScenesWithTheSameRootGiveTheirWallsTwoIds(InstanceRule rule, string first, string second)
        {
            Room("Room_01", NewSceneMode.Single, out var wall1);
            var scene2 = Room("Room_02", NewSceneMode.Additive, out var wall2);
            var labels = SceneLabels.Collect(Settings(rule), null, CaptureIsolation.WholeScene, ~0, false);
            int id1 = labels.Ids[wall1].Instance, id2 = labels.Ids[wall2].Instance;
            Assert.That(id1, Is.Not.EqualTo(id2), "one id per wall");
            Assert.That(labels.Table.Instance(id1).Path, Is.EqualTo(first));
            Assert.That(labels.Table.Instance(id2).Path, Is.EqualTo(second));

            // One loaded scene: the path (and key) a single-scene capture has always written.
            EditorSceneManager.CloseScene(scene2, true);
            var single = SceneLabels.Collect(Settings(rule), null, CaptureIsolation.WholeScene, ~0, false);
            Assert.That(single.Table.Instances.Select(i => i.Path), Is.EqualTo(new[] { rule == InstanceRule.Renderer ? "Room/Wall" : "Room" }));
        }
    }
}
