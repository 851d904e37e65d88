using System.Globalization;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>The Scene-view preview's legend: what each colour means, per-split visibility, and the picked camera.</summary>
    static class PreviewSection
    {
        public static void Draw(PreviewDriver driver)
        {
            EditorGUILayout.Space();
            EditorGUILayout.LabelField("Scene-view preview", EditorStyles.boldLabel);
            driver.Enabled = EditorGUILayout.Toggle("Draw the rig", driver.Enabled);
            if (!driver.Enabled) return;
            var preview = driver.Preview;
            foreach (PreviewSplit split in new[] { PreviewSplit.Train, PreviewSplit.Val, PreviewSplit.Test })
            {
                EditorGUILayout.BeginHorizontal();
                SectionHeader.Swatch(RigPreview.ColorOf(split));
                var label = SplitColors.NameOf(split) + " (" + driver.Counts[(int)split].ToString(CultureInfo.InvariantCulture) + ")";
                preview.SetVisible(split, GUILayout.Toggle(preview.IsVisible(split), label));
                EditorGUILayout.EndHorizontal();
            }
            EditorGUILayout.LabelField("Grey: the target's bounds and the sphere of the rig distance.", EditorStyles.wordWrappedMiniLabel);
            if (driver.Status.Length > 0) EditorGUILayout.LabelField(driver.Status, EditorStyles.wordWrappedMiniLabel);
            EditorGUILayout.LabelField(driver.PickedLabel.Length > 0
                ? "Picked camera: " + driver.PickedLabel + " (its image is " + driver.PickedLabel.Replace(' ', '/') + ".png)"
                : "Click a camera in the Scene view to see its split and index.", EditorStyles.wordWrappedMiniLabel);
        }
    }
}
