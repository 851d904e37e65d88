using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>"1  Target ✓" — a numbered step title that says whether the step still has an error.</summary>
    static class SectionHeader
    {
        public static void Draw(WindowContext context, WindowStep step, string title)
        {
            EditorGUILayout.Space();
            var incomplete = context.Problems.StepHasErrors(step);
            EditorGUILayout.LabelField(((int)step) + "  " + title + (incomplete ? "  — needs attention" : ""), EditorStyles.boldLabel);
        }

        /// <summary>A small filled square in a split's preview colour, for the legend and the rig's split titles.</summary>
        public static void Swatch(Color color)
        {
            var rect = GUILayoutUtility.GetRect(12, 12, GUILayout.Width(12));
            rect.y += 3;
            rect.height = 12;
            EditorGUI.DrawRect(rect, color);
        }
    }
}
