using System;
using System.IO;
using System.Linq;
using NUnit.Framework;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// <c>unity_frame</c>'s Editor facts (issue 34, <see cref="UnityFrameCapture"/>): the target's scene and hierarchy path,
    /// its GlobalObjectId where the scene is saved, its local-to-world row-major and the colour space; and a capture records
    /// them in dataset_config.json.
    /// </summary>
    [TestFixture]
    public class UnityFrameCaptureTests
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
            _folder = "Assets/nerf-unity-frame-" + Guid.NewGuid().ToString("N");
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

        /// <summary>Root (at (1, 2, 3), turned 90° about Y) / Lego (scaled 2) in a new scene.</summary>
        static GameObject Lego()
        {
            var scene = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);
            SceneManager.SetActiveScene(scene);
            var root = new GameObject("Root");
            root.transform.position = new Vector3(1, 2, 3);
            root.transform.rotation = Quaternion.Euler(0, 90, 0);
            var lego = new GameObject("Lego");
            lego.transform.SetParent(root.transform, false);
            lego.transform.localScale = new Vector3(2, 2, 2);
            return lego;
        }

        [Test]
        public void AnUnsavedScenesTargetHasItsPathAndMatrixButNoId()
        {
            var lego = Lego();
            var facts = UnityFrameCapture.Of(lego);
            Assert.That(facts.TargetScenePath, Is.EqualTo(":/Root/Lego"));
            Assert.That(facts.TargetGlobalObjectId, Is.Null, "an object of a scene never saved has no asset GUID");
            // Rotation 90° about Y takes x to −z and z to x; scale 2: row-major
            // [0 0 2 1; 0 2 0 2; −2 0 0 3; 0 0 0 1], the translation in the last column.
            var expected = new double[] { 0, 0, 2, 1, 0, 2, 0, 2, -2, 0, 0, 3, 0, 0, 0, 1 };
            for (var i = 0; i < 16; i++) Assert.That(facts.TargetLocalToWorld[i], Is.EqualTo(expected[i]).Within(1e-5), "entry " + i);
            Assert.That(facts.ColorSpace, Is.EqualTo(QualitySettings.activeColorSpace == ColorSpace.Linear ? "Linear" : "Gamma"));
        }

        [Test]
        public void ASavedScenesTargetHasTheScenesPathAndItsGlobalObjectId()
        {
            var lego = Lego();
            var path = _folder + "/Lego.unity";
            Assert.That(EditorSceneManager.SaveScene(lego.scene, path), Is.True);
            var facts = UnityFrameCapture.Of(lego);
            Assert.That(facts.TargetScenePath, Is.EqualTo(path + ":/Root/Lego"));
            Assert.That(facts.TargetGlobalObjectId, Is.EqualTo(GlobalObjectId.GetGlobalObjectIdSlow(lego).ToString()));
            Assert.That(facts.TargetGlobalObjectId, Does.StartWith("GlobalObjectId_V1-2-" + AssetDatabase.AssetPathToGUID(path)), "type 2 = scene object, then the scene's GUID");
        }

        [Test]
        public void AWholeSceneCaptureRecordsOnlyTheColourSpace()
        {
            var facts = UnityFrameCapture.Of(null);
            Assert.That(facts.TargetScenePath, Is.Null);
            Assert.That(facts.TargetLocalToWorld, Is.Null);
            Assert.That(facts.ColorSpace, Is.EqualTo(QualitySettings.activeColorSpace.ToString()));
        }

        [Test]
        [Category("GPU")]
        public void ACaptureWritesTheFactsIntoDatasetConfig()
        {
            TestScene.RequireRendering();
            var lego = Lego();
            var sphere = TestScene.LitSphere("Sphere");
            sphere.transform.SetParent(lego.transform, false);
            var path = _folder + "/Capture.unity";
            Assert.That(EditorSceneManager.SaveScene(lego.scene, path), Is.True);
            var project = Path.Combine(Path.GetTempPath(), "nerf-unity-frame-" + Guid.NewGuid().ToString("N"));
            try
            {
                var settings = new DatasetSettings { Name = "frame", Width = 16, Height = 16, Distance = 3 };
                settings.Train.Count = 2;
                settings.Val.Count = 1;
                settings.Test.Count = 1;
                var result = DatasetCapture.RunBlocking(DatasetCapture.Prepare(settings, sphere, project), new SilentProgress());
                Assert.That(result.Succeeded, Is.True, result.Message);
                var config = File.ReadAllText(Path.Combine(result.DatasetFolder, "dataset_config.json"));
                // Independent of the record's key names: the facts' values appear in the file.
                Assert.That(config, Does.Contain(path + ":/Root/Lego/Sphere"));
                Assert.That(config, Does.Contain(GlobalObjectId.GetGlobalObjectIdSlow(sphere).ToString()));
            }
            finally
            {
                if (Directory.Exists(project)) Directory.Delete(project, true);
            }
        }

        sealed class SilentProgress : ICaptureProgress
        {
            public void Report(ThroughputMeter meter) { }
            public bool CancelRequested => false;
            public void Close() { }
        }
    }
}
