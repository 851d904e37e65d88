using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The window's settings for this project, kept in <c>UserSettings/NeRFDatasetCreator.asset</c> (per project and
    /// per user, not in EditorPrefs, which every project on the machine shares). Unity's serializer stores the
    /// public-field <see cref="DatasetSettings"/> model as it is: doubles, longs, enums and nested [Serializable]
    /// classes are all serializable field types (Unity Manual: Script serialization). The target is kept as its
    /// hierarchy path in <see cref="DatasetSettings.Target"/>: a reference to a scene object cannot be stored in a
    /// file outside the scene and still mean that object after Unity restarts.
    /// </summary>
    [FilePath("UserSettings/NeRFDatasetCreator.asset", FilePathAttribute.Location.ProjectFolder)]
    public sealed class NerfDatasetCreatorSettings : ScriptableSingleton<NerfDatasetCreatorSettings>
    {
        [SerializeField] DatasetSettings settings = new DatasetSettings();

        /// <summary>The live settings. Change them through <see cref="Apply"/> so that the change can be undone and is saved.</summary>
        public DatasetSettings Settings => settings ?? (settings = new DatasetSettings());

        /// <summary>Replaces the settings with a copy of <paramref name="changed"/> as one undo step named <paramref name="undoName"/>, and saves.</summary>
        public void Apply(DatasetSettings changed, string undoName)
        {
            if (changed == null) throw new System.ArgumentNullException(nameof(changed));
            // ScriptableSingleton makes its instance HideAndDontSave; Unity's own hidden editor state is undone the
            // same way (AnimationWindowKeySelection, UnityCsReference 2022.3/6000.0), and an EditMode test checks it.
            Undo.RecordObject(this, undoName);
            settings = changed.Clone();
            SaveToProject();
        }

        /// <summary>What the settings file holds: loaded or last saved. Not serialized: it describes the file, not the settings.</summary>
        [System.NonSerialized] SavedText _file;

        SavedText FileText
        {
            get
            {
                if (_file == null)
                {
                    // ScriptableSingleton loads the file when the instance is created, so this is what it holds.
                    _file = new SavedText();
                    _file.Saved(DatasetSettingsJson.Write(Settings));
                }
                return _file;
            }
        }

        /// <summary>Writes the settings file (as text, so that it diffs readably).</summary>
        public void SaveToProject()
        {
            Save(true);
            FileText.Saved(DatasetSettingsJson.Write(Settings));
        }

        /// <summary>
        /// Writes the settings file only if the settings differ from it: after an undo or redo, which Unity reports for
        /// every undo in the editor, not only the window's own. Returns whether it wrote.
        /// </summary>
        public bool SaveIfChanged()
        {
            if (!FileText.Differs(DatasetSettingsJson.Write(Settings))) return false;
            SaveToProject();
            return true;
        }
    }
}
