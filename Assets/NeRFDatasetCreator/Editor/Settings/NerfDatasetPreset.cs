using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// A saved set of dataset settings as a project asset, to share a rig and camera between targets and people.
    /// Copies in and out are deep, so editing the window never changes a preset and loading one never ties the
    /// window to it.
    /// </summary>
    public sealed class NerfDatasetPreset : ScriptableObject
    {
        [SerializeField] DatasetSettings settings = new DatasetSettings();

        /// <summary>A copy of the preset's settings.</summary>
        public DatasetSettings CopySettings() => (settings ?? new DatasetSettings()).Clone();

        /// <summary>Stores a copy of <paramref name="source"/>.</summary>
        public void StoreSettings(DatasetSettings source)
        {
            if (source == null) throw new System.ArgumentNullException(nameof(source));
            settings = source.Clone();
        }

        /// <summary>
        /// What loading this preset into the window gives: the preset's settings, but the window's own target and
        /// scene, because a preset describes a rig, not which object it is for.
        /// </summary>
        public DatasetSettings ApplyTo(DatasetSettings current)
        {
            var result = CopySettings();
            if (current != null)
            {
                result.Target = current.Target;
                result.Scene = current.Scene;
            }
            return result;
        }
    }
}
