using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class SavedTextTests
    {
        [Test]
        public void OnlyAChangeSinceTheLastSaveNeedsWriting()
        {
            var saved = new SavedText();
            var settings = DatasetSettingsJson.Write(new DatasetSettings());
            Assert.That(saved.Differs(settings), Is.True, "nothing recorded yet");
            saved.Saved(settings);
            Assert.That(saved.Differs(DatasetSettingsJson.Write(new DatasetSettings())), Is.False, "an undo elsewhere leaves the settings as they were");
            Assert.That(saved.Differs(DatasetSettingsJson.Write(new DatasetSettings { Width = 400 })), Is.True, "an undo of the plugin's own edit");
        }
    }
}
