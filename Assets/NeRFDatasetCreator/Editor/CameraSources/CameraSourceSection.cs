using System.IO;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// A split's camera source in the Rig step: its formation, or the cameras of an existing dataset (a transforms
    /// JSON file or a COLMAP text model folder), re-rendered in this scene (see <see cref="CameraSourceSettings"/>).
    /// </summary>
    static class CameraSourceSection
    {
        static readonly string[] KindLabels = { "Formation", "Imported cameras" };
        static readonly string[] FileSplitLabels = { "All cameras", "train", "val", "test" };
        static readonly string[] FileSplitValues = { "", "train", "val", "test" };

        /// <summary>Draws the source; true when the split's cameras are imported (then count and formation are not used).</summary>
        public static bool Draw(WindowContext c, DatasetSplit split)
        {
            var settings = c.Settings.Split(split);
            var source = settings.Source ?? (settings.Source = new CameraSourceSettings());
            var field = WindowFields.SplitField(split, "source");
            var kind = EditorGUILayout.Popup("Cameras", source.IsImported ? 1 : 0, KindLabels);
            source.Kind = kind == 1 ? CameraSourceKind.ImportedPoses : CameraSourceKind.Formation;
            if (!source.IsImported) return false;

            EditorGUILayout.BeginHorizontal();
            source.Path = EditorGUILayout.TextField(new GUIContent("File or model folder", "A transforms JSON (Blender, nerfstudio, instant-ngp, this plugin) or a COLMAP text model folder such as sparse/0; relative to the project folder."), source.Path ?? "");
            if (GUILayout.Button("File…", GUILayout.Width(48))) c.Later(() => Pick(source, folder: false));
            if (GUILayout.Button("Folder…", GUILayout.Width(60))) c.Later(() => Pick(source, folder: true));
            EditorGUILayout.EndHorizontal();
            var index = System.Array.IndexOf(FileSplitValues, source.FileSplit ?? "");
            index = EditorGUILayout.Popup("Cameras of the file", index < 0 ? 0 : index, FileSplitLabels);
            source.FileSplit = FileSplitValues[index];
            source.UseFileIntrinsics = EditorGUILayout.Toggle(new GUIContent("Use the file's camera", "Render with the file's field of view and image size instead of the Camera step's."), source.UseFileIntrinsics);
            ValidationMessages.For(c, field);
            return true;
        }

        static void Pick(CameraSourceSettings source, bool folder)
        {
            var start = string.IsNullOrEmpty(source.Path) ? "" : Path.GetDirectoryName(Path.GetFullPath(source.Path));
            var chosen = folder
                ? EditorUtility.OpenFolderPanel("COLMAP text model folder (cameras.txt, images.txt)", start, "")
                : EditorUtility.OpenFilePanel("Transforms file", start, "json");
            if (string.IsNullOrEmpty(chosen)) return;
            // Inside the project the path is kept relative, so the config works on every machine that has the project.
            var project = Path.GetFullPath(Directory.GetCurrentDirectory()).Replace('\\', '/').TrimEnd('/') + "/";
            source.Path = chosen.Replace('\\', '/').StartsWith(project, System.StringComparison.Ordinal) ? chosen.Substring(project.Length) : chosen;
        }
    }
}
