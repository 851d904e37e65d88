using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Part of step 5 (outputs): the material passes (settings "materials", issue 38): base colour, metallic, roughness,
    /// specular and emission per view, with the coverage mask. The controls are the settings'; the note says what the
    /// active pipeline reads (Core <see cref="MaterialPassChoices"/>). Laid out like <see cref="HdrSection"/>.
    /// </summary>
    static class MaterialsSection
    {
        public static void Draw(WindowContext c)
        {
            var m = c.Settings.Materials;
            if (m == null) c.Settings.Materials = m = new MaterialPassSettings();
            EditorGUILayout.LabelField("Material passes", EditorStyles.boldLabel);
            using (new EditorGUI.IndentLevelScope())
            {
                m.On = EditorGUILayout.Toggle(new GUIContent("Write material passes",
                    "Per view, the shaders' own surface parameters: linear float EXR (the truth) beside an 8-bit PNG, and r_<i>_material_coverage.png " +
                    "(255 where the shader is read exactly). Roughness is perceptual: 1 − smoothness."), m.On);
                if (m.Enabled)
                {
                    var labels = MaterialPassChoices.PassLabels;
                    m.Albedo = EditorGUILayout.ToggleLeft(labels[0], m.Albedo);
                    m.Metallic = EditorGUILayout.ToggleLeft(labels[1], m.Metallic);
                    m.Roughness = EditorGUILayout.ToggleLeft(labels[2], m.Roughness);
                    m.Specular = EditorGUILayout.ToggleLeft(labels[3], m.Specular);
                    m.Emission = EditorGUILayout.ToggleLeft(labels[4], m.Emission);
                    EditorGUILayout.HelpBox(MaterialPassChoices.PipelineNote(CaptureEnvironment.RenderPipelineName) + " " +
                        MaterialPassChoices.FilesPerView(m) + " files per view.", MessageType.None);
                }
                ValidationMessages.For(c, MaterialPassChoices.Field);
            }
        }
    }
}
