using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Part of step 5 (outputs): per-view exposure and white balance of the colour images (Documentation~/exposure.md).
    /// The stage itself is Core's (ExposureWhiteBalance in ViewFileWriter), so nothing here renders; these are the
    /// settings' controls, validated by Core's ExposureSettingsValidator and shown under them like every other step.
    /// An explicit list ("exposure.values") is edited as rows of EV and R, G, B gains (Core's <see cref="ExposureValueRows"/>),
    /// each row's problems under it, as the labels section does with its class rules.
    /// </summary>
    static class ExposureSection
    {
        static readonly string[] ModeLabels = { "Off", "Random (seeded per view)", "List (one entry per view, repeating)" };

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
                    DrawValues(c, e);
                e.WriteClean = EditorGUILayout.Toggle(new GUIContent("Write clean image", "Also write each modified view unmodified as r_<i>_clean.png (frame key clean_path)."), e.WriteClean);
                // The list's problems are shown under its rows (DrawValues); the rest of the section's here.
                if (e.Mode == ExposureMode.List) ValidationMessages.Rest(c, WindowFields.Exposure, new[] { ExposureValueRows.ListField });
                else ValidationMessages.For(c, WindowFields.Exposure);
            }
        }

        /// <summary>List mode: one row per entry (EV, then the R, G, B gains), a remove button per row and "Add value".</summary>
        static void DrawValues(WindowContext c, ExposureSettings e)
        {
            var values = e.Values ?? (e.Values = new List<ViewExposure>());
            EditorGUILayout.LabelField(ExposureValueRows.Summary(values.Count), EditorStyles.wordWrappedMiniLabel);
            var shown = ExposureValueRows.Shown(values.Count);
            var remove = -1;
            for (var i = 0; i < shown; i++)
            {
                var v = values[i];
                EditorGUILayout.BeginHorizontal();
                var ev = EditorGUILayout.DoubleField(new GUIContent(i == 0 ? "EV, gains R G B" : " ",
                    "Exposure in stops (+1 doubles the light), then the linear white-balance gains of red, green and blue (1 = unchanged)."), v.Ev);
                // The gains without labels of their own, beside the EV: the row reads as one entry (as the labels
                // section's class rules do). DoubleField without a label: UnityCsReference Editor/Mono/EditorGUILayout.cs
                // line 510 in 2022.3 and 6000.0, "public static double DoubleField(double value, params GUILayoutOption[] options)".
                var indent = EditorGUI.indentLevel;
                EditorGUI.indentLevel = 0;
                var r = EditorGUILayout.DoubleField(v.R);
                var g = EditorGUILayout.DoubleField(v.G);
                var b = EditorGUILayout.DoubleField(v.B);
                EditorGUI.indentLevel = indent;
                if (GUILayout.Button(new GUIContent("−", "Remove this value"), GUILayout.Width(22))) remove = i;
                EditorGUILayout.EndHorizontal();
                values[i] = new ViewExposure(ev, r, g, b);
                ValidationMessages.For(c, ExposureValueRows.Field(i));
            }
            if (remove >= 0) values.RemoveAt(remove);
            EditorGUILayout.BeginHorizontal();
            // 15 points a level: EditorGUI.kIndentPerLevel (UnityCsReference Editor/Mono/EditorGUI.cs line 121 in 2022.3, 127 in 6000.0), as LabelsSection does.
            GUILayout.Space(EditorGUI.indentLevel * 15);
            if (GUILayout.Button(new GUIContent("Add value", "Append a copy of the last value (EV 0, gains 1 for the first)."), GUILayout.Width(120)))
                values.Add(ExposureValueRows.Next(values));
            EditorGUILayout.EndHorizontal();
            // Problems about the list itself, and about entries beyond the rows drawn (named by their field).
            ValidationMessages.Rest(c, ExposureValueRows.ListField, ExposureValueRows.ShownFields(values.Count), withField: values.Count > shown);
        }
    }
}
