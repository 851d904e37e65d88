using System;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.SceneManagement;
using UnityEngine.TestTools;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Batch mode finds a config's "scene" relative to the config file (Core ScenePath), which is what lets the
    /// sample's configs work where Package Manager imports the sample. Checked without rendering: the config names
    /// a target that does not exist, so Execute opens the scene and then refuses with "the target is missing".
    /// </summary>
    [TestFixture]
    public class BatchScenePathTests
    {
        const string SampleScene = "Assets/Samples/NeRFSample/NeRFSample.unity";

        SceneSetup[] _setup;
        string _folder;

        [SetUp]
        public void SetUp()
        {
            if (SystemInfo.graphicsDeviceType == GraphicsDeviceType.Null) Assert.Ignore("no graphics device: Execute stops at that check first");
            for (var i = 0; i < SceneManager.sceneCount; i++)
                if (SceneManager.GetSceneAt(i).isDirty)
                    Assert.Ignore("A scene with unsaved changes is open; this test opens the sample scene in its place. Save or close it, then run again.");
            _setup = EditorSceneManager.GetSceneManagerSetup();
            // A '~' folder beside the sample scene: inside the project, never imported by Unity.
            var projectRoot = Directory.GetParent(Application.dataPath).FullName;
            _folder = Path.Combine(projectRoot, "Assets", "Samples", "NeRFSample", "batch-scene-path-" + Guid.NewGuid().ToString("N") + "~");
            Directory.CreateDirectory(_folder);
        }

        [TearDown]
        public void TearDown()
        {
            if (_setup != null && _setup.Length > 0 && _setup.All(s => !string.IsNullOrEmpty(s.path)))
                EditorSceneManager.RestoreSceneManagerSetup(_setup);
            else
                EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);
            if (_folder != null && Directory.Exists(_folder)) Directory.Delete(_folder, true);
        }

        string Config(string scene)
        {
            var path = Path.Combine(_folder, "config.json");
            File.WriteAllText(path, DatasetSettingsJson.Write(new DatasetSettings { Scene = scene, Target = "No object is called this " + Guid.NewGuid().ToString("N") }));
            return path;
        }

        [Test]
        public void ASceneRelativeToTheConfigIsOpened()
        {
            LogAssert.Expect(LogType.Error, new Regex("nothing was captured: the target is missing"));
            var code = BatchCapture.Execute(new[] { "-nerfConfig", Config("../NeRFSample.unity") });
            Assert.That(code, Is.EqualTo(BatchCapture.InvalidInput));
            Assert.That(SceneManager.GetActiveScene().path, Is.EqualTo(SampleScene));
        }

        [Test]
        public void AnAssetsPathIsStillFromTheProjectFolder()
        {
            LogAssert.Expect(LogType.Error, new Regex("nothing was captured: the target is missing"));
            var code = BatchCapture.Execute(new[] { "-nerfConfig", Config(SampleScene) });
            Assert.That(code, Is.EqualTo(BatchCapture.InvalidInput));
            Assert.That(SceneManager.GetActiveScene().path, Is.EqualTo(SampleScene));
        }

        [Test]
        public void ASceneOutsideTheProjectIsInvalidInput()
        {
            LogAssert.Expect(LogType.Error, new Regex("nothing was captured: the scene is outside the project"));
            var code = BatchCapture.Execute(new[] { "-nerfConfig", Config("../../../../../Outside.unity") });
            Assert.That(code, Is.EqualTo(BatchCapture.InvalidInput));
        }
    }
}
