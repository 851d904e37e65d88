using System.Linq;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Part of step 5 (Outputs): the instance and semantic id maps with labels.json (Core's <see cref="LabelSettings"/>,
    /// <c>"labels"</c> in config files; Documentation~/labels.md) — what an instance is, where a class comes from, and the
    /// rules that map tags, layers, prefabs or name patterns to class names. Nothing is added to the scene. Validation is
    /// Core's (<see cref="LabelSettingsValidator"/>), shown under each control like every other step.
    /// </summary>
    static class LabelsSection
    {
        /// <summary>Labels of <see cref="InstanceRule"/>, in its order.</summary>
        static readonly GUIContent[] InstanceLabels =
        {
            new GUIContent("Each renderer", "Every GameObject with a mesh renderer under the target is its own object."),
            new GUIContent("Each prefab instance", "The outermost prefab instance holding a renderer is one object (a car, not its forty meshes); renderers in no prefab count one by one."),
            new GUIContent("Each direct child", "Each direct child of the target is one object with everything below it (in an environment capture: each scene root)."),
        };

        /// <summary>Labels of <see cref="ClassSource"/>, in its order.</summary>
        static readonly GUIContent[] ClassLabels =
        {
            new GUIContent("Tag", "The object's tag (Untagged included)."),
            new GUIContent("Layer", "The object's layer name."),
            new GUIContent("Prefab", "The prefab asset the object is an instance of (its project path)."),
            new GUIContent("Name", "The object's name, matched against the rules' patterns."),
        };

        const string ListField = "labels.classes";

        public static void Draw(WindowContext c)
        {
            var labels = c.Settings.Labels ?? (c.Settings.Labels = new LabelSettings());
            EditorGUILayout.LabelField("Labels", EditorStyles.boldLabel);
            using (new EditorGUI.IndentLevelScope())
            {
                labels.Enabled = EditorGUILayout.Toggle(new GUIContent("Instance + semantic maps",
                    "Per view r_<i>_instance_0000.png and r_<i>_semantic_0000.png (16-bit grey, 0 = background) and labels.json: " +
                    "every object with the same id in every view, split, time step and shard."), labels.Enabled);
                if (!labels.Enabled) return;
                labels.Instances = (InstanceRule)EditorGUILayout.Popup(new GUIContent("One object is"), (int)labels.Instances, InstanceLabels);
                ValidationMessages.For(c, "labels.instances");
                labels.ClassFrom = (ClassSource)EditorGUILayout.Popup(new GUIContent("Class from"), (int)labels.ClassFrom, ClassLabels);
                ValidationMessages.For(c, "labels.classFrom");
                DrawRules(c, labels);
                labels.OtherClass = EditorGUILayout.TextField(new GUIContent("Other objects' class",
                    "The class of objects no rule matches; empty leaves them 0 in the semantic maps (they keep their instance ids)."), labels.OtherClass ?? "");
                ValidationMessages.For(c, "labels.otherClass");
            }
        }

        static void DrawRules(WindowContext c, LabelSettings labels)
        {
            EditorGUILayout.LabelField(labels.Classes.Count == 0
                    ? "No rules: every distinct " + ClassLabels[(int)labels.ClassFrom].text.ToLowerInvariant() + " is a class of its own."
                    : "The first rule whose pattern matches decides (* = any characters, ? = one).",
                EditorStyles.wordWrappedMiniLabel);
            var remove = -1;
            for (var i = 0; i < labels.Classes.Count; i++)
            {
                var rule = labels.Classes[i] ?? (labels.Classes[i] = new ClassRule());
                EditorGUILayout.BeginHorizontal();
                rule.Match = EditorGUILayout.TextField(i == 0 ? "Match → class" : " ", rule.Match ?? "");
                // The class field without a label, beside the pattern: the pair reads as one rule.
                var indent = EditorGUI.indentLevel;
                EditorGUI.indentLevel = 0;
                rule.Class = EditorGUILayout.TextField(rule.Class ?? "");
                EditorGUI.indentLevel = indent;
                if (GUILayout.Button(new GUIContent("−", "Remove this rule"), GUILayout.Width(22))) remove = i;
                EditorGUILayout.EndHorizontal();
                ValidationMessages.For(c, "labels.classes[" + i.ToString(System.Globalization.CultureInfo.InvariantCulture) + "]");
            }
            if (remove >= 0) labels.Classes.RemoveAt(remove);
            EditorGUILayout.BeginHorizontal();
            GUILayout.Space(EditorGUI.indentLevel * 15);
            if (GUILayout.Button(new GUIContent("Add class rule", "A tag, layer, prefab path or name pattern and the class its objects belong to."), GUILayout.Width(120)))
                labels.Classes.Add(new ClassRule());
            EditorGUILayout.EndHorizontal();
            // Problems about the list itself (each rule's are shown under it).
            ValidationMessages.Show(c.Problems.ErrorsFor(ListField).Where(p => p.Field == ListField).ToList(), MessageType.Error);
            ValidationMessages.Show(c.Problems.WarningsFor(ListField).Where(p => p.Field == ListField).ToList(), MessageType.Warning);
        }
    }
}
