using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Step 2: a template camera or the built-in values; field of view, clip planes, resolution, supersampling, background.</summary>
    static class CameraSection
    {
        static readonly string[] ResolutionLabels = ResolutionPresets.Labels();

        public static void Draw(WindowContext c)
        {
            if (!SectionHeader.Foldout(c, WindowStep.Camera, "Camera")) return;
            var s = c.Settings;
            var camera = s.Camera;

            EditorGUI.BeginChangeCheck();
            var picked = (Camera)EditorGUILayout.ObjectField("Template camera", c.TemplateCamera, typeof(Camera), true);
            if (EditorGUI.EndChangeCheck())
            {
                if (picked != null && EditorUtility.IsPersistent(picked))
                    c.PickNotice = "'" + picked.name + "' is a camera in an asset, not in the scene. Pick a camera of the open scene.";
                else
                {
                    c.TemplateCamera = picked;
                    camera.CopyFromCamera = picked == null ? "" : SceneObjectPath.Of(picked.gameObject);
                    if (picked != null) CopyFrom(picked, camera);
                }
            }
            ValidationMessages.For(c, WindowFields.CopyFromCamera);

            var template = c.TemplateCamera;
            if (template != null)
            {
                EditorGUILayout.LabelField("Field of view and clip planes come from '" + template.name + "'; at capture its other camera settings are copied too.",
                    EditorStyles.wordWrappedMiniLabel);
                if (Differs(template, camera) && GUILayout.Button("'" + template.name + "' changed: copy its values again"))
                {
                    CopyFrom(template, camera);
                    GUI.changed = true;
                }
            }
            else
                EditorGUILayout.LabelField("Built-in camera (nerf_synthetic's field of view); or pick a camera of the scene as template.", EditorStyles.wordWrappedMiniLabel);

            using (new EditorGUI.DisabledScope(template != null))
            {
                camera.VerticalFovDegrees = EditorGUILayout.DoubleField("Vertical field of view (°)", camera.VerticalFovDegrees);
                ValidationMessages.For(c, WindowFields.VerticalFov);
                camera.NearClip = EditorGUILayout.DoubleField("Near clip", camera.NearClip);
                ValidationMessages.For(c, WindowFields.NearClip);
                camera.FarClip = EditorGUILayout.DoubleField("Far clip", camera.FarClip);
                ValidationMessages.For(c, WindowFields.FarClip);
            }

            var shown = ResolutionPresets.Shown(s.Width, s.Height, c.Foldouts.CustomResolution);
            var preset = EditorGUILayout.Popup("Resolution", shown, ResolutionLabels);
            if (preset != shown) c.Foldouts.CustomResolution = preset == ResolutionPresets.CustomIndex;
            ResolutionPresets.Apply(preset, s);
            if (preset == ResolutionPresets.CustomIndex)
            {
                s.Width = EditorGUILayout.IntField("Width", s.Width);
                s.Height = EditorGUILayout.IntField("Height", s.Height);
            }
            ValidationMessages.For(c, WindowFields.Width);
            ValidationMessages.For(c, WindowFields.Height);

            s.Supersampling = EditorGUILayout.IntSlider("Supersampling", s.Supersampling, DatasetSettings.MinSupersampling, DatasetSettings.MaxSupersampling);
            ValidationMessages.For(c, WindowFields.Supersampling);

            var background = s.Background ?? (s.Background = new BackgroundSettings());
            var mode = EditorGUILayout.Popup(new GUIContent("Background", "Transparent (alpha 0, what object datasets use), a solid colour, or the scene's sky (environment capture: alpha 255 everywhere)."),
                background.Transparent ? 0 : background.Sky ? 2 : 1, BackgroundLabels);
            background.Transparent = mode == 0;
            background.Sky = mode == 2;
            if (mode == 1)
            {
                var colour = EditorGUILayout.ColorField("Background colour", new Color((float)background.R, (float)background.G, (float)background.B, 1));
                // The field shows and returns the sRGB components, which is what the config's "#rrggbb" holds.
                if (!Mathf.Approximately(colour.r, (float)background.R)) background.R = colour.r;
                if (!Mathf.Approximately(colour.g, (float)background.G)) background.G = colour.g;
                if (!Mathf.Approximately(colour.b, (float)background.B)) background.B = colour.b;
            }
            ValidationMessages.For(c, WindowFields.Background);
        }

        static readonly string[] BackgroundLabels = { "Transparent", "Solid colour", "Sky (skybox)" };

        static void CopyFrom(Camera source, CameraSettings target)
        {
            target.VerticalFovDegrees = source.fieldOfView;
            target.NearClip = source.nearClipPlane;
            target.FarClip = source.farClipPlane;
        }

        static bool Differs(Camera source, CameraSettings settings) =>
            (float)settings.VerticalFovDegrees != source.fieldOfView || (float)settings.NearClip != source.nearClipPlane ||
            (float)settings.FarClip != source.farClipPlane;
    }
}
