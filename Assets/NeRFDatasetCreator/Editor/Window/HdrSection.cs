using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Part of step 5 (outputs): linear HDR colour beside the PNGs, <c>r_&lt;i&gt;_hdr.exr</c> (settings "hdr"). The stage
    /// is Core's (HdrColour in ViewFileWriter) on the colour pair the capture already reads back as half floats, so
    /// nothing here renders; the controls are the settings', validated by Core's HdrSettingsValidator and shown under
    /// them. The IMGUI calls are the ones ExposureSection uses for its split toggles.
    /// </summary>
    static class HdrSection
    {
        public static void Draw(WindowContext c)
        {
            var h = c.Settings.Hdr;
            EditorGUILayout.LabelField("Linear HDR colour", EditorStyles.boldLabel);
            using (new EditorGUI.IndentLevelScope())
            {
                h.On = EditorGUILayout.Toggle(new GUIContent("Write r_<i>_hdr.exr",
                    "Beside each PNG, the view's linear colour as a float EXR with straight alpha: not clipped at 1, before exposure, no tone mapping (frame key hdr_path). Linear colour-space projects only."),
                    h.On);
                if (h.Enabled)
                {
                    EditorGUILayout.BeginHorizontal();
                    EditorGUILayout.PrefixLabel("Splits");
                    h.Train = EditorGUILayout.ToggleLeft("train", h.Train, GUILayout.Width(60));
                    h.Val = EditorGUILayout.ToggleLeft("val", h.Val, GUILayout.Width(60));
                    h.Test = EditorGUILayout.ToggleLeft("test", h.Test, GUILayout.Width(60));
                    EditorGUILayout.EndHorizontal();
                }
                ValidationMessages.For(c, WindowFields.Hdr);
            }
        }
    }
}
