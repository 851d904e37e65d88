using System.IO;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Under a successful capture's result: validate it and "Export for …" each trainer, in the editor, with the
    /// headless tool's commands and messages (<see cref="DatasetToolRunner"/>); more in Window ▸ NeRF Dataset Tools.
    /// </summary>
    static class ExportSection
    {
        static Vector2 _outputScroll;

        public static void Draw(DatasetCaptureResult result)
        {
            if (result == null || !result.Succeeded || string.IsNullOrEmpty(result.DatasetFolder) || !Directory.Exists(result.DatasetFolder)) return;
            EditorGUILayout.Space();
            EditorGUILayout.LabelField("Check and export this dataset", EditorStyles.boldLabel);
            using (new EditorGUI.DisabledScope(DatasetToolRunner.IsRunning))
            {
                EditorGUILayout.BeginHorizontal();
                if (GUILayout.Button(new GUIContent("Validate", "nerf-dataset validate on the dataset just written.")))
                {
                    var folder = result.DatasetFolder;
                    EditorApplication.delayCall += () => DatasetToolRunner.Start("validate", ValidateCommand.Arguments(folder));
                }
                if (GUILayout.Button(new GUIContent("More tools…", "Window ▸ NeRF Dataset Tools on this dataset: another export folder, merge, clean.")))
                {
                    var folder = result.DatasetFolder;
                    EditorApplication.delayCall += () => DatasetToolsWindow.Open(folder);
                }
                EditorGUILayout.EndHorizontal();
                EditorGUILayout.LabelField("Export for", EditorStyles.miniLabel);
                DatasetToolsWindow.DrawExportButtons(result.DatasetFolder, null);
            }
            DatasetToolsWindow.DrawLastRun(ref _outputScroll);
        }
    }
}
