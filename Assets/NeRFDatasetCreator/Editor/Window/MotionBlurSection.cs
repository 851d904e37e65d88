using System.Globalization;
using System.Linq;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Part of step 5 (Outputs): motion blur and rolling shutter (Core's <see cref="MotionBlurSettings"/>,
    /// <c>"motionBlur"</c> in config files; Documentation~/motion-blur.md) — how the camera moves over the shutter, the
    /// shutter, the sub-frames and the rows' readout. The sub-frame renders are the capture's; these are the settings'
    /// controls, validated by Core's <see cref="MotionBlurSettingsValidator"/> and shown under each field.
    /// </summary>
    static class MotionBlurSection
    {
        static readonly GUIContent[] CameraLabels =
            MotionBlurChoices.CameraLabels.Select((l, i) => new GUIContent(l, MotionBlurChoices.CameraTooltips[i])).ToArray();

        public static void Draw(WindowContext c)
        {
            var m = c.Settings.MotionBlur ?? (c.Settings.MotionBlur = new MotionBlurSettings());
            EditorGUILayout.LabelField("Motion blur", EditorStyles.boldLabel);
            using (new EditorGUI.IndentLevelScope())
            {
                m.Enabled = EditorGUILayout.Toggle(new GUIContent("Expose over a shutter",
                    "Each colour image is the average of sub-frame renders over a shutter centred on the view's pose (which stays transform_matrix); " +
                    "the start and end poses are written as transform_matrix_start / _end and the sharp image as r_<i>_sharp_0000.png."), m.Enabled);
                if (!m.Enabled) return;
                m.Camera = (ShutterCameraMotion)EditorGUILayout.Popup(new GUIContent("Camera", "How the camera moves while the shutter is open."), (int)m.Camera, CameraLabels);
                ValidationMessages.For(c, MotionBlurChoices.Field("camera"));
                if (m.Camera == ShutterCameraMotion.Shake)
                {
                    m.ShakeDistance = EditorGUILayout.DoubleField(new GUIContent("Shake distance", "How far the camera centre moves over the shutter, in Unity units."), m.ShakeDistance);
                    ValidationMessages.For(c, MotionBlurChoices.Field("shakeDistance"));
                    m.ShakeDegrees = EditorGUILayout.DoubleField(new GUIContent("Shake angle (°)", "How far the camera turns over the shutter, in degrees."), m.ShakeDegrees);
                    ValidationMessages.For(c, MotionBlurChoices.Field("shakeDegrees"));
                }
                m.Shutter = EditorGUILayout.DoubleField(new GUIContent("Shutter",
                    "The exposure as a fraction of the spacing between consecutive views (and of a time step), in (0, 1]: 0.5 is film's 180° shutter."), m.Shutter);
                ValidationMessages.For(c, MotionBlurChoices.Field("shutter"));
                // IntField with a GUIContent label (tooltip): UnityCsReference Editor/Mono/EditorGUILayout.cs line 606 in
                // 2022.3 and 6000.0, "public static int IntField(GUIContent label, int value, params GUILayoutOption[] options)".
                m.SubFrames = EditorGUILayout.IntField(new GUIContent("Sub-frames",
                    "Renders averaged per view (2 … " + MotionBlurSettings.MaxSubFrames.ToString(CultureInfo.InvariantCulture) + "): more is smoother and slower (Documentation~/motion-blur.md, How many sub-frames)."), m.SubFrames);
                ValidationMessages.For(c, MotionBlurChoices.Field("subFrames"));
                m.Readout = EditorGUILayout.DoubleField(new GUIContent("Rolling shutter readout",
                    "The fraction of the shutter over which the rows start, top row first (0 … " + MotionBlurSettings.MaxReadout.ToString(CultureInfo.InvariantCulture) + "); 0 is a global shutter."), m.Readout);
                ValidationMessages.For(c, MotionBlurChoices.Field("readout"));
                ValidationMessages.Rest(c, WindowFields.MotionBlur, MotionBlurChoices.Shown(m));
            }
        }
    }
}
