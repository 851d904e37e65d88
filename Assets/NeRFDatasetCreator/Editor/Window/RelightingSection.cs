using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Part of step 5 (outputs): relighting sets (settings "relighting", issue 38): the same views under more lighting
    /// conditions, each an environment map at one or more rotations or one point / spot light. Positions and directions
    /// are in the output world (Blender's frame, +Z up), as the settings give them. The text-field parsing and new-condition
    /// names are Core's (<see cref="RelightingChoices"/>); the values are judged by the settings validator, whose problems
    /// show under the section. Laid out like <see cref="HdrSection"/>.
    /// </summary>
    static class RelightingSection
    {
        // The rotations text while the user types it, per condition (a half-typed "0, 9" must not be reformatted).
        static readonly Dictionary<LightingCondition, string> RotationText = new Dictionary<LightingCondition, string>();

        public static void Draw(WindowContext c)
        {
            var r = c.Settings.Relighting;
            if (r == null) c.Settings.Relighting = r = new RelightingSettings();
            if (r.Conditions == null) r.Conditions = new List<LightingCondition>();
            EditorGUILayout.LabelField("Relighting", EditorStyles.boldLabel);
            using (new EditorGUI.IndentLevelScope())
            {
                r.On = EditorGUILayout.Toggle(new GUIContent("Relit colour images",
                    "The same views under more lighting conditions, r_<i>_light_<key>.png beside each image, and lights/lights.json. " +
                    "The plain images keep the scene's own lighting."), r.On);
                if (r.On)
                {
                    LightingCondition remove = null;
                    foreach (var condition in r.Conditions)
                    {
                        if (condition == null) continue;
                        if (DrawCondition(condition)) remove = condition;
                    }
                    if (remove != null)
                    {
                        r.Conditions.Remove(remove);
                        RotationText.Remove(remove);
                    }
                    EditorGUILayout.BeginHorizontal();
                    GUILayout.Space(EditorGUI.indentLevel * 15f);
                    if (GUILayout.Button("Add environment")) r.Conditions.Add(RelightingChoices.NewCondition(LightingKind.Environment, r.Conditions));
                    if (GUILayout.Button("Add point light")) r.Conditions.Add(RelightingChoices.NewCondition(LightingKind.Point, r.Conditions));
                    if (GUILayout.Button("Add spot light")) r.Conditions.Add(RelightingChoices.NewCondition(LightingKind.Spot, r.Conditions));
                    EditorGUILayout.EndHorizontal();
                    EditorGUILayout.HelpBox(RelightingChoices.RendersPerView(r) + " more colour render(s) per view. Environment light is the sky's " +
                        "ambient and reflection, without environment shadows; point and spot lights cast shadows.", MessageType.None);
                }
                ValidationMessages.For(c, RelightingChoices.Field);
            }
        }

        /// <summary>One condition's rows; true when its Remove button was pressed.</summary>
        static bool DrawCondition(LightingCondition condition)
        {
            EditorGUILayout.BeginHorizontal();
            condition.Name = EditorGUILayout.TextField("Name", condition.Name);
            var removed = GUILayout.Button("Remove", GUILayout.Width(70));
            EditorGUILayout.EndHorizontal();
            using (new EditorGUI.IndentLevelScope())
            {
                condition.Kind = (LightingKind)EditorGUILayout.Popup("Kind", (int)condition.Kind, RelightingChoices.KindLabels);
                if (condition.Kind == LightingKind.Environment)
                {
                    var current = string.IsNullOrEmpty(condition.File) ? null : AssetDatabase.LoadAssetAtPath<Texture>(condition.File);
                    var picked = (Texture)EditorGUILayout.ObjectField(new GUIContent("Map", "An HDR cubemap or equirectangular texture of this project."),
                        current, typeof(Texture), false);
                    if (picked != current) condition.File = picked == null ? "" : AssetDatabase.GetAssetPath(picked);
                    if (!RotationText.TryGetValue(condition, out var text)) text = RelightingChoices.FormatRotations(condition.Rotations);
                    text = EditorGUILayout.TextField(new GUIContent("Rotations (°)", "Counter-clockwise about +Z seen from above, e.g. 0, 90, 180, 270."), text);
                    RotationText[condition] = text;
                    var rotations = RelightingChoices.ParseRotations(text, out var problem);
                    if (rotations != null) condition.Rotations = rotations;
                    else EditorGUILayout.HelpBox(problem, MessageType.Error);
                    condition.Intensity = EditorGUILayout.DoubleField("Intensity", condition.Intensity);
                }
                else
                {
                    condition.Position = Field("Position (output frame)", condition.Position);
                    if (condition.Kind == LightingKind.Spot)
                    {
                        var aimed = EditorGUILayout.Toggle(new GUIContent("Direction", "Off: the spot points at the output origin."), condition.Direction != null);
                        if (aimed) condition.Direction = Field("Points along", condition.Direction ?? new double[] { 0, 0, -1 });
                        else condition.Direction = null;
                        condition.SpotAngle = EditorGUILayout.DoubleField("Spot angle (°)", condition.SpotAngle);
                    }
                    condition.Intensity = EditorGUILayout.DoubleField("Intensity", condition.Intensity);
                    var colour = condition.Colour != null && condition.Colour.Length == 3 ? condition.Colour : new double[] { 1, 1, 1 };
                    var shownColour = new Color((float)colour[0], (float)colour[1], (float)colour[2]);
                    var pickedColour = EditorGUILayout.ColorField(new GUIContent("Colour (linear)"), shownColour, true, false, true);
                    if (pickedColour != shownColour) condition.Colour = new double[] { pickedColour.r, pickedColour.g, pickedColour.b };
                    condition.Shadows = EditorGUILayout.Toggle("Shadows", condition.Shadows);
                }
            }
            return removed;
        }

        static double[] Field(string label, double[] value)
        {
            var v = value != null && value.Length == 3 ? value : new double[] { 0, 0, 0 };
            var shown = new Vector3((float)v[0], (float)v[1], (float)v[2]);
            var picked = EditorGUILayout.Vector3Field(label, shown);
            // Unchanged: keep the settings' doubles (a float round trip would turn 0.1 into 0.100000001490116).
            return picked == shown ? v : new double[] { picked.x, picked.y, picked.z };
        }
    }
}
