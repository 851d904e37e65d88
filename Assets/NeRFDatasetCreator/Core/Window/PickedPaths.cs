using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What the window's file and folder pickers store. A picker runs after the GUI event that opened it, so it
    /// edits a fresh copy of the stored settings and returns it for the window to commit as one undo step (the
    /// copy a section draws into is gone by then: storing the pick there loses it).
    /// </summary>
    public static class PickedPaths
    {
        /// <summary>
        /// A picked path as the settings keep it: relative to <paramref name="projectRoot"/> (with '/') when inside it,
        /// so a config works on every machine that has the project; otherwise as picked.
        /// </summary>
        public static string ForSettings(string chosen, string projectRoot)
        {
            if (string.IsNullOrEmpty(chosen)) return "";
            var path = chosen.Replace('\\', '/');
            if (string.IsNullOrEmpty(projectRoot)) return path;
            var project = Path.GetFullPath(projectRoot).Replace('\\', '/').TrimEnd('/') + "/";
            // Case-sensitive: on a case-insensitive disk a mismatch only keeps the path absolute, which still works.
            return path.StartsWith(project, StringComparison.Ordinal) ? path.Substring(project.Length) : path;
        }

        /// <summary>A copy of <paramref name="stored"/> whose <paramref name="split"/> imports its cameras from <paramref name="chosen"/>.</summary>
        public static DatasetSettings WithImportedCameras(DatasetSettings stored, DatasetSplit split, string chosen, string projectRoot)
        {
            if (stored == null) throw new ArgumentNullException(nameof(stored));
            var edited = stored.Clone();
            var splitSettings = edited.Split(split);
            var source = splitSettings.Source == null ? new CameraSourceSettings() : splitSettings.Source.Clone();
            source.Kind = CameraSourceKind.ImportedPoses;
            source.Path = ForSettings(chosen, projectRoot);
            splitSettings.Source = source;
            return edited;
        }

        /// <summary>A copy of <paramref name="stored"/> whose datasets go under <paramref name="chosen"/>.</summary>
        public static DatasetSettings WithOutputFolder(DatasetSettings stored, string chosen)
        {
            if (stored == null) throw new ArgumentNullException(nameof(stored));
            var edited = stored.Clone();
            edited.OutputFolder = chosen ?? "";
            return edited;
        }
    }
}
