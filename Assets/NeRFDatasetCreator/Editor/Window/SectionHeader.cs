using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>"1  Target — needs attention" — a numbered step title that says whether the step still has an error.</summary>
    static class SectionHeader
    {
        /// <summary>A title that does not fold (step 7, whose Create button should never be hidden).</summary>
        public static void Draw(WindowContext context, WindowStep step, string title)
        {
            EditorGUILayout.Space();
            EditorGUILayout.LabelField(Title(context, step, title), EditorStyles.boldLabel);
        }

        /// <summary>
        /// A foldout header for steps 1–6; true when the step is open and its controls should be drawn. A closed step
        /// with an error still says "needs attention". The header is EditorGUILayout.BeginFoldoutHeaderGroup ended at
        /// once: in UnityCsReference (Editor/Mono/GUI/FoldoutHeader.cs, 2022.3 and 6000.0) Begin draws a toggle in
        /// EditorStyles.foldoutHeader and sets a static flag that only forbids nesting another header, and End clears
        /// it — no layout group — so the step's controls (with their own plain Foldouts, such as the rig's Advanced)
        /// follow outside it. Docs: https://docs.unity3d.com/2022.3/Documentation/ScriptReference/EditorGUILayout.BeginFoldoutHeaderGroup.html
        /// </summary>
        public static bool Foldout(WindowContext context, WindowStep step, string title)
        {
            EditorGUILayout.Space();
            var open = WindowStepFoldouts.IsOpen(step);
            var now = EditorGUILayout.BeginFoldoutHeaderGroup(open, Title(context, step, title));
            EditorGUILayout.EndFoldoutHeaderGroup();
            if (now != open) WindowStepFoldouts.SetOpen(step, now);
            return now;
        }

        static string Title(WindowContext context, WindowStep step, string title) =>
            ((int)step) + "  " + title + (context.Problems.StepHasErrors(step) ? "  — needs attention" : "");

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
