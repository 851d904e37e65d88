using System;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Presets (project assets) and config files for batch mode, with the report of the last config load.</summary>
    static class PresetSection
    {
        public sealed class Actions
        {
            public Action SavePreset;
            public Action<NerfDatasetPreset> LoadPreset;
            public Action SaveConfig;
            public Action LoadConfig;
        }

        public static NerfDatasetPreset Draw(WindowContext c, NerfDatasetPreset preset, ConfigReport report, Actions actions)
        {
            c.Foldouts.PresetsAndConfig = EditorGUILayout.Foldout(c.Foldouts.PresetsAndConfig, "Presets and batch config", true);
            if (!c.Foldouts.PresetsAndConfig) return preset;
            using (new EditorGUI.DisabledScope(c.Busy))
            {
                EditorGUILayout.BeginHorizontal();
                preset = (NerfDatasetPreset)EditorGUILayout.ObjectField(preset, typeof(NerfDatasetPreset), false);
                using (new EditorGUI.DisabledScope(preset == null))
                    if (GUILayout.Button("Load preset", GUILayout.Width(90)))
                    {
                        var chosen = preset;
                        c.Later(() => actions.LoadPreset(chosen));
                    }
                if (GUILayout.Button("Save preset…", GUILayout.Width(95))) c.Later(actions.SavePreset);
                EditorGUILayout.EndHorizontal();

                EditorGUILayout.BeginHorizontal();
                if (GUILayout.Button("Save config for batch…")) c.Later(actions.SaveConfig);
                if (GUILayout.Button("Load config…")) c.Later(actions.LoadConfig);
                EditorGUILayout.EndHorizontal();
            }
            report.Draw();
            return preset;
        }
    }
}
