using System.Globalization;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Step 1: the object to capture, its size, and the camera distance (fixed, suggested or automatic).</summary>
    static class TargetSection
    {
        public static void Draw(WindowContext c)
        {
            if (!SectionHeader.Foldout(c, WindowStep.Target, "Target")) return;
            var s = c.Settings;

            EditorGUI.BeginChangeCheck();
            var picked = (GameObject)EditorGUILayout.ObjectField("Object", c.Target, typeof(GameObject), true);
            if (EditorGUI.EndChangeCheck()) Pick(c, picked);
            EditorGUILayout.BeginHorizontal();
            if (GUILayout.Button("Use selection"))
            {
                if (Selection.activeGameObject == null)
                    c.PickNotice = "Nothing is selected: click the object in the Hierarchy or the Scene view first.";
                else
                {
                    Pick(c, Selection.activeGameObject);
                    GUI.changed = true;
                }
            }
            using (new EditorGUI.DisabledScope(c.TargetInfo == null || !c.TargetInfo.HasRenderers))
                if (GUILayout.Button("Frame in Scene view"))
                {
                    var bounds = c.TargetInfo.Bounds;
                    c.Later(() =>
                    {
                        var view = SceneView.lastActiveSceneView;
                        if (view != null) view.Frame(bounds, false);
                    });
                }
            EditorGUILayout.EndHorizontal();
            if (!string.IsNullOrEmpty(c.PickNotice)) EditorGUILayout.HelpBox(c.PickNotice, MessageType.Warning);
            ValidationMessages.For(c, WindowFields.Target);
            ValidationMessages.For(c, WindowFields.Scene);

            if (c.TargetInfo != null)
            {
                var size = c.TargetInfo.Bounds.size;
                if (c.TargetInfo.HasRenderers)
                    EditorGUILayout.LabelField("Bounds size", WindowText.Length(size.x) + " × " + WindowText.Length(size.y) + " × " + WindowText.Length(size.z));
                EditorGUILayout.LabelField(WindowText.TargetSummary(c.TargetInfo.Measure, s), EditorStyles.wordWrappedMiniLabel);
            }

            s.AutoDistance = EditorGUILayout.Toggle("Automatic distance", s.AutoDistance);
            if (s.AutoDistance)
            {
                s.AutoDistanceMargin = EditorGUILayout.DoubleField("Margin (≥ 1)", s.AutoDistanceMargin);
                ValidationMessages.For(c, WindowFields.AutoDistanceMargin);
            }
            else
            {
                EditorGUILayout.BeginHorizontal();
                s.Distance = EditorGUILayout.DoubleField("Distance", s.Distance);
                var suggested = c.TargetInfo == null ? null : WindowText.SuggestedDistance(c.TargetInfo.Measure, s);
                using (new EditorGUI.DisabledScope(!suggested.HasValue))
                    if (GUILayout.Button(suggested.HasValue ? "Use " + WindowText.Length(suggested.Value) : "Use suggested", GUILayout.Width(90)))
                    {
                        s.Distance = double.Parse(WindowText.Length(suggested.Value), CultureInfo.InvariantCulture);
                        GUI.changed = true;
                    }
                EditorGUILayout.EndHorizontal();
            }
            ValidationMessages.For(c, WindowFields.Distance);
        }

        /// <summary>
        /// Takes a scene object as the target and stores its hierarchy path and scene; refuses assets (a prefab or
        /// model in the Project window), because only an object in the scene can be rendered where it stands.
        /// </summary>
        static void Pick(WindowContext c, GameObject picked)
        {
            if (picked != null && EditorUtility.IsPersistent(picked))
            {
                c.PickNotice = "'" + picked.name + "' is an asset (a prefab or model in the Project window), not an object in the scene. " +
                               "Drag it into the scene, then pick that instance.";
                return;
            }
            var pathProblem = SceneObjectPath.Check(WindowFields.Target, picked);
            c.PickNotice = pathProblem == null ? null : WindowText.Problem(pathProblem);
            c.Target = picked;
            c.Settings.Target = SceneObjectPath.Of(picked);
            c.Settings.Scene = picked == null ? "" : picked.scene.path;
        }
    }
}
