using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The window's pickers store a fresh copy of the stored settings (issue 23: the imported-cameras pick was lost).</summary>
    [TestFixture]
    public class PickedPathsTests
    {
        [Test]
        public void APathInsideTheProjectIsKeptRelative()
        {
            Assert.That(PickedPaths.ForSettings("/home/u/Game/Captures/lego/transforms_train.json", "/home/u/Game"), Is.EqualTo("Captures/lego/transforms_train.json"));
            Assert.That(PickedPaths.ForSettings("/home/u/Game/", "/home/u/Game/"), Is.EqualTo(""));
            Assert.That(PickedPaths.ForSettings("/data/colmap/sparse/0", "/home/u/Game"), Is.EqualTo("/data/colmap/sparse/0"));
            Assert.That(PickedPaths.ForSettings("/home/u/GameOther/a.json", "/home/u/Game"), Is.EqualTo("/home/u/GameOther/a.json"), "a sibling whose name starts alike is outside");
            Assert.That(PickedPaths.ForSettings(@"C:\Users\u\Game\cams\t.json", null), Is.EqualTo("C:/Users/u/Game/cams/t.json"));
        }

        [Test]
        public void ImportedCamerasAreStoredInACopyAndTheStoredSettingsAreUntouched()
        {
            var stored = new DatasetSettings();
            var edited = PickedPaths.WithImportedCameras(stored, DatasetSplit.Val, "/home/u/Game/cams/transforms.json", "/home/u/Game");
            Assert.That(edited.Val.Source.Kind, Is.EqualTo(CameraSourceKind.ImportedPoses));
            Assert.That(edited.Val.Source.Path, Is.EqualTo("cams/transforms.json"));
            Assert.That(edited.Train.Source.IsFormation, Is.True, "other splits keep their source");
            Assert.That(stored.Val.Source.IsFormation, Is.True, "the stored settings change only when the window commits the copy");
            Assert.That(stored.Val.Source.Path, Is.EqualTo(""));
            // The edit is one the config file keeps, so the window's Commit (which compares the JSON) stores it.
            Assert.That(DatasetSettingsJson.Write(edited), Is.Not.EqualTo(DatasetSettingsJson.Write(stored)));
            Assert.That(DatasetSettingsJson.Read(DatasetSettingsJson.Write(edited)).Settings.Val.Source.Path, Is.EqualTo("cams/transforms.json"));
        }

        [Test]
        public void AnImportedSourceKeepsItsOtherChoices()
        {
            var stored = new DatasetSettings();
            stored.Train.Source = new CameraSourceSettings { Kind = CameraSourceKind.ImportedPoses, Path = "old.json", FileSplit = "test", UseFileIntrinsics = true };
            var edited = PickedPaths.WithImportedCameras(stored, DatasetSplit.Train, "/p/new.json", "/q");
            Assert.That(edited.Train.Source.Path, Is.EqualTo("/p/new.json"));
            Assert.That(edited.Train.Source.FileSplit, Is.EqualTo("test"));
            Assert.That(edited.Train.Source.UseFileIntrinsics, Is.True);
            Assert.That(stored.Train.Source.Path, Is.EqualTo("old.json"));
        }

        [Test]
        public void TheOutputFolderPickIsACopyToo()
        {
            var stored = new DatasetSettings();
            var edited = PickedPaths.WithOutputFolder(stored, "/data/nerf");
            Assert.That(edited.OutputFolder, Is.EqualTo("/data/nerf"));
            Assert.That(stored.OutputFolder, Is.EqualTo(""));
        }
    }
}
