using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Part of step 5 (outputs): per-view exposure and white balance of the colour images (Documentation~/exposure.md).
    /// The stage itself is Core's (ExposureWhiteBalance in ViewFileWriter), so nothing here renders; these are the
    /// settings' controls, validated by Core's ExposureSettingsValidator and shown under them like every other step.
    /// An explicit list is edited in a config file ("exposure.values"); the window shows its length.
    /// </summary>
    static class ExposureSection
    {
        static readonly string[] ModeLabels = { "Off", "Random (seeded per view)", "List (from the config file)" };

        public static void Draw(WindowContext c)
        {
            var e = c.Settings.Exposure;
            EditorGUILayout.LabelField("Exposure and white balance", EditorStyles.boldLabel);
            using (new EditorGUI.IndentLevelScope())
            {
                e.Mode = (ExposureMode)EditorGUILayout.Popup(new GUIContent("Mode",
                    "Scale each view's colour by 2^EV and per-channel white-balance gains in linear light, clipped at 1; recorded per frame as exposure_ev and white_balance."),
                    (int)e.Mode, ModeLabels);
                if (!e.Enabled)
                {
                    ValidationMessages.For(c, WindowFields.Exposure);
                    return;
                }
                EditorGUILayout.BeginHorizontal();
                EditorGUILayout.PrefixLabel("Splits");
                // Toggles without labels of their own: ToggleLeft keeps each split's name beside its box.
                e.Train = EditorGUILayout.ToggleLeft("train", e.Train, GUILayout.Width(60));
                e.Val = EditorGUILayout.ToggleLeft("val", e.Val, GUILayout.Width(60));
                e.Test = EditorGUILayout.ToggleLeft("test", e.Test, GUILayout.Width(60));
                EditorGUILayout.EndHorizontal();
                if (e.Mode == ExposureMode.Random)
                {
                    e.EvMin = EditorGUILayout.DoubleField("Lowest EV", e.EvMin);
                    e.EvMax = EditorGUILayout.DoubleField("Highest EV", e.EvMax);
                    e.GainMin = EditorGUILayout.DoubleField(new GUIContent("Lowest R/B gain", "Red and blue gains are drawn log-uniformly between these; green stays 1. [1, 1] turns white balance off."), e.GainMin);
                    e.GainMax = EditorGUILayout.DoubleField("Highest R/B gain", e.GainMax);
                }
                else
                    EditorGUILayout.LabelField((e.Values?.Count ?? 0) + " listed value(s); view i takes entry i mod the list's length. Edit them in a config file (exposure.values).",
                        EditorStyles.wordWrappedMiniLabel);
                e.WriteClean = EditorGUILayout.Toggle(new GUIContent("Write clean image", "Also write each modified view unmodified as r_<i>_clean.png (frame key clean_path)."), e.WriteClean);
                ValidationMessages.For(c, WindowFields.Exposure);
            }
        }
    }
}
