using System;
using System.IO;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Step 6: the dataset's name and where its folder goes (outside Assets by default), what may be replaced, and for which loaders.</summary>
    static class OutputFolderSection
    {
        public static void Draw(WindowContext c, string projectRoot, Action<string> chooseFolder)
        {
            if (!SectionHeader.Foldout(c, WindowStep.OutputFolder, "Output folder")) return;
            var s = c.Settings;
            s.Name = EditorGUILayout.TextField("Dataset name", s.Name);
            ValidationMessages.For(c, WindowFields.Name);

            EditorGUILayout.BeginHorizontal();
            s.OutputFolder = EditorGUILayout.TextField("Parent folder", s.OutputFolder);
            if (GUILayout.Button("…", GUILayout.Width(28)))
            {
                var start = Resolve(s, projectRoot, parentOnly: true);
                c.Later(() => chooseFolder(start));
            }
            if (GUILayout.Button("Default", GUILayout.Width(60)))
            {
                s.OutputFolder = "";
                GUI.changed = true;
            }
            EditorGUILayout.EndHorizontal();
            EditorGUILayout.LabelField("Writes to " + Resolve(s, projectRoot, parentOnly: false), EditorStyles.wordWrappedMiniLabel);
            ValidationMessages.For(c, WindowFields.OutputFolder);

            s.Overwrite = (OverwritePolicy)EditorGUILayout.EnumPopup("If it exists", s.Overwrite);
            EditorGUILayout.LabelField(s.Overwrite == OverwritePolicy.Never
                    ? "Never: an existing dataset is left alone and the run is refused."
                    : "Replace: the old dataset is replaced only once the new one is complete.",
                EditorStyles.wordWrappedMiniLabel);
            ValidationMessages.For(c, WindowFields.Overwrite);

            s.Loaders = (TargetLoaders)EditorGUILayout.EnumFlagsField("Made for", s.Loaders);
            ValidationMessages.For(c, WindowFields.Loaders);
        }

        /// <summary>The dataset folder (or its parent) the settings name, or why the path cannot be used.</summary>
        static string Resolve(DatasetSettings s, string projectRoot, bool parentOnly)
        {
            try
            {
                var folder = SafeOutput.ResolveOutputFolder(s, projectRoot);
                return parentOnly ? Path.GetDirectoryName(folder) : folder;
            }
            catch (Exception e) when (e is ArgumentException || e is NotSupportedException || e is PathTooLongException)
            {
                return parentOnly ? projectRoot : "(not a valid path: " + e.Message + ")";
            }
        }
    }
}
