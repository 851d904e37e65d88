using System;
using System.Collections.Generic;
using System.IO;
using UnityEditor;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The window's file actions: the output folder picker, preset assets and batch config files. Each runs from
    /// EditorApplication.delayCall (never inside OnGUI, where a modal dialog breaks the layout) and changes the
    /// settings as one undo step.
    /// </summary>
    public sealed partial class NerfDatasetCreatorWindow
    {
        void ChooseFolder(string start)
        {
            var chosen = EditorUtility.OpenFolderPanel("Parent folder of the dataset", start ?? ProjectRoot, "");
            if (string.IsNullOrEmpty(chosen) || this == null) return;
            UseOutputFolder(chosen);
        }

        /// <summary>What the output folder's "…" picker does with the chosen folder: one undo step on the stored settings.</summary>
        public void UseOutputFolder(string chosen) => Commit(PickedPaths.WithOutputFolder(Store.Settings, chosen), "Choose NeRF dataset folder");

        void ChooseCameras(DatasetSplit split, string start, bool folder)
        {
            var chosen = CameraSourceSection.ShowPicker(start, folder);
            if (string.IsNullOrEmpty(chosen) || this == null) return;
            UseImportedCameras(split, chosen);
        }

        /// <summary>
        /// What the Imported cameras' File… and Folder… pickers do with the chosen path: the split imports its cameras
        /// from it (kept relative to the project when inside it), as one undo step on the stored settings.
        /// </summary>
        public void UseImportedCameras(DatasetSplit split, string chosen) =>
            Commit(PickedPaths.WithImportedCameras(Store.Settings, split, chosen, ProjectRoot), "Choose imported cameras");

        void SavePreset()
        {
            var path = EditorUtility.SaveFilePanelInProject("Save NeRF dataset preset", Store.Settings.Name + " preset", "asset",
                "A preset keeps every setting of the window (camera, rig, outputs, folder) as a project asset.");
            if (string.IsNullOrEmpty(path)) return;
            var asset = CreateInstance<NerfDatasetPreset>();
            asset.StoreSettings(Store.Settings);
            AssetDatabase.CreateAsset(asset, path);
            AssetDatabase.SaveAssets();
            preset = asset;
            report.Set("Saved preset " + path + ".", MessageType.Info);
            Repaint();
        }

        void LoadPreset(NerfDatasetPreset chosen)
        {
            if (chosen == null || this == null) return;
            Commit(chosen.ApplyTo(Store.Settings), "Load NeRF dataset preset");
            report.Set("Loaded preset " + AssetDatabase.GetAssetPath(chosen) + " (the target stays as it was).", MessageType.Info);
            Repaint();
        }

        void SaveConfig()
        {
            var path = EditorUtility.SaveFilePanel("Save config for batch mode", ProjectRoot, Store.Settings.Name + ".json", "json");
            if (string.IsNullOrEmpty(path)) return;
            try
            {
                File.WriteAllText(path, DatasetSettingsJson.Write(Store.Settings));
                report.Set("Saved " + path + ". Batch mode: Unity -batchmode -projectPath <project> -executeMethod " +
                           "NerfDatasetCreator.Editor.BatchCapture.Run -nerfConfig " + path + " -logFile -", MessageType.Info);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                report.Set("Could not write " + path + ": " + e.Message, MessageType.Error);
            }
            if (this != null) Repaint();
        }

        void LoadConfig()
        {
            var path = EditorUtility.OpenFilePanel("Load NeRF dataset config", ProjectRoot, "json");
            if (string.IsNullOrEmpty(path) || this == null) return;
            SettingsReadResult read;
            try
            {
                read = DatasetSettingsJson.ReadFile(path);
            }
            catch (SettingsFormatException e)
            {
                report.Set(WindowText.ConfigError(e), MessageType.Error);
                Repaint();
                return;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                report.Set("Could not read " + path + ": " + e.Message + " The window's settings are unchanged.", MessageType.Error);
                Repaint();
                return;
            }
            var loaded = read.Settings;
            var warnings = new List<ValidationProblem>(read.Warnings);
            var found = SceneObjectPath.Find(loaded.Target);
            if (found == null)
            {
                var kept = target == null ? "so no target is set" : "so the window keeps its target '" + target.name + "'";
                if (!string.IsNullOrEmpty(loaded.Target))
                    warnings.Add(new ValidationProblem("target", "\"" + loaded.Target + "\"", "is not in the open scenes, " + kept + ".",
                        "Open the config's scene (" + (loaded.Scene.Length == 0 ? "not named" : loaded.Scene) + ") and load the config again, or pick the target."));
                if (target != null)
                {
                    loaded.Target = SceneObjectPath.Of(target);
                    loaded.Scene = target.scene.path;
                }
            }
            Commit(loaded, "Load NeRF dataset config");
            ResolveSceneObjects();
            report.Set("Loaded " + path + ".", warnings.Count == 0 ? MessageType.Info : MessageType.Warning, warnings);
            Repaint();
        }
    }
}
