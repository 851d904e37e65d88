using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Part of step 5 (Outputs): the sparse-view split files the capture writes (Core's <see cref="SparseViewsChoices"/>,
    /// <c>"sparseViews"</c> in config files; Documentation~/train-and-evaluate.md). One text field of view counts,
    /// validated by Core's <see cref="SparseViewsSettings"/> and shown under it.
    /// </summary>
    static class SparseViewsSection
    {
        public static void Draw(WindowContext c)
        {
            // DelayedTextField returns the edited text only on Enter or focus loss, so "3," half-typed is never parsed:
            // UnityCsReference Editor/Mono/EditorGUILayout.cs line 307 in 2022.3.76f1 and 6000.0.78f1,
            // "public static string DelayedTextField(GUIContent label, string text, params GUILayoutOption[] options)".
            var shown = SparseViewsChoices.Text(c.Settings.SparseViews);
            var typed = EditorGUILayout.DelayedTextField(new GUIContent(SparseViewsChoices.Label, SparseViewsChoices.Tooltip), shown);
            if (typed != shown)
            {
                // A list that is not whole numbers keeps the previous counts (the field shows them again).
                var counts = SparseViewsChoices.Parse(typed);
                if (counts != null) c.Settings.SparseViews = counts;
            }
            ValidationMessages.For(c, WindowFields.SparseViews);
        }
    }
}
