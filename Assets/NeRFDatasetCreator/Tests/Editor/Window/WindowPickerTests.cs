using System.IO;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// The window's pickers store what they pick (issue 23: the Imported cameras' File…/Folder… wrote into the GUI
    /// event's working copy, which was gone when the dialog returned). The dialog itself cannot run in a test; what it
    /// hands on is what these call. The user's stored settings are put back after each test.
    /// </summary>
    [TestFixture]
    public class WindowPickerTests
    {
        string _saved;
        NerfDatasetCreatorWindow _window;

        static NerfDatasetCreatorSettings Store => NerfDatasetCreatorSettings.instance;

        [SetUp]
        public void SetUp()
        {
            _saved = DatasetSettingsJson.Write(Store.Settings);
            _window = EditorWindow.GetWindow<NerfDatasetCreatorWindow>("NeRF Dataset Creator");
        }

        [TearDown]
        public void TearDown()
        {
            if (_window != null) _window.Close();
            Store.Apply(DatasetSettingsJson.Read(_saved).Settings, "Restore NeRF dataset settings after a test");
        }

        static string ProjectRoot => Path.GetDirectoryName(Application.dataPath);

        [Test]
        public void TheImportedCamerasPickIsStoredRelativeToTheProject()
        {
            var picked = Path.Combine(ProjectRoot, "Captures", "lego", "transforms_train.json").Replace('\\', '/');
            _window.UseImportedCameras(DatasetSplit.Test, picked);
            var source = Store.Settings.Test.Source;
            Assert.That(source.Kind, Is.EqualTo(CameraSourceKind.ImportedPoses));
            Assert.That(source.Path, Is.EqualTo("Captures/lego/transforms_train.json"));
        }

        [Test]
        public void TheImportedCamerasPickIsOneUndoStep()
        {
            var before = DatasetSettingsJson.Write(Store.Settings);
            Undo.IncrementCurrentGroup(); // the pick is its own undo group, as after a dialog in the editor
            _window.UseImportedCameras(DatasetSplit.Train, "/data/colmap/sparse/0");
            Assert.That(Store.Settings.Train.Source.Path, Is.EqualTo("/data/colmap/sparse/0"));
            Undo.PerformUndo();
            Assert.That(DatasetSettingsJson.Write(Store.Settings), Is.EqualTo(before));
        }

        [Test]
        public void TheOutputFolderPickIsStoredTheSameWay()
        {
            _window.UseOutputFolder("/data/nerf");
            Assert.That(Store.Settings.OutputFolder, Is.EqualTo("/data/nerf"));
        }
    }
}
