using System.Collections.Generic;
using System.Linq;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Part of step 5 (Outputs): the lens the images are taken through (Core's <see cref="LensSettings"/>, <c>"lens"</c>
    /// in config files; Documentation~/lens-distortion.md) — the model and its coefficients. The capture itself is
    /// Core's (LensCapture, LensResampler), so nothing here renders. Which fields are drawn and what a model change does
    /// to the coefficients are Core's <see cref="LensChoices"/>; validation is Core's (<see cref="LensSettingsValidator"/>),
    /// shown under each field like every other step.
    /// </summary>
    static class LensSection
    {
        static readonly GUIContent[] ModelLabels = LensChoices.ModelLabels.Select(l => new GUIContent(l)).ToArray();

        public static void Draw(WindowContext c)
        {
            var lens = c.Settings.Lens ?? (c.Settings.Lens = new LensSettings());
            EditorGUILayout.LabelField("Lens distortion", EditorStyles.boldLabel);
            using (new EditorGUI.IndentLevelScope())
            {
                var index = LensChoices.IndexOf(lens.Model);
                var chosen = EditorGUILayout.Popup(new GUIContent("Model",
                    "Take every image through an exactly known lens; the model and coefficients are written where nerfstudio, instant-ngp and COLMAP read them. " +
                    "Field of view, width and height describe the frame before the lens."), index, ModelLabels);
                if (chosen != index && chosen >= 0) LensChoices.ChangeModel(lens, LensChoices.ModelAt(chosen));
                ValidationMessages.For(c, LensChoices.Field("model"));
                var shown = LensChoices.Shown(lens);
                foreach (var key in shown)
                {
                    LensChoices.Set(lens, key, EditorGUILayout.DoubleField(new GUIContent(key, LensChoices.Tooltip(lens.Model, key)), LensChoices.Get(lens, key)));
                    ValidationMessages.For(c, LensChoices.Field(key));
                }
                if (lens.Enabled)
                    EditorGUILayout.LabelField("OpenCV's normalised coordinates, y down. Each view is rendered wider and resampled through the lens.",
                        EditorStyles.wordWrappedMiniLabel);
                // The whole lens's problems (the wide render, a rolling shutter, the loaders' warnings), once, below its fields.
                var fields = new List<string> { LensChoices.Field("model") };
                fields.AddRange(shown.Select(LensChoices.Field));
                ValidationMessages.Rest(c, WindowFields.Lens, fields);
            }
        }
    }
}
