using UnityEditor;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Step 4: animated content (Documentation~/dynamic-capture.md) — the mode (static, monocular, multi-view), what
    /// drives time, the range in seconds and the steps as a count or a frame rate. Validation is Core's
    /// (TimeSettingsValidator, TimePlanning), shown under each field like every other step.
    /// </summary>
    static class TimeSection
    {
        public static void Draw(WindowContext c)
        {
            if (!SectionHeader.Foldout(c, WindowStep.Time, "Time")) return;
            var time = c.Settings.Time;
            time.Mode = (TimeMode)EditorGUILayout.Popup("Mode", (int)time.Mode, WindowText.TimeModeLabels);
            ValidationMessages.For(c, WindowFields.TimeModeField);
            if (!time.Enabled)
            {
                EditorGUILayout.LabelField("The target is captured as it stands. Pick a mode to capture animated content over time.", EditorStyles.wordWrappedMiniLabel);
                return;
            }
            using (new EditorGUI.IndentLevelScope())
            {
                // MaskField sets bit i for option i and returns -1 for "Everything" (Scripting API: EditorGUILayout.MaskField);
                // WindowTextTests checks that option i is the flag 1 << i.
                var mask = EditorGUILayout.MaskField("Driven by", (int)time.Sources, WindowText.TimeSourceLabels);
                time.Sources = (TimeSources)(mask & (int)TimeSources.All);
                ValidationMessages.For(c, WindowFields.TimeSourcesField);

                time.StartSeconds = EditorGUILayout.DoubleField("Start (s)", time.StartSeconds);
                ValidationMessages.For(c, WindowFields.TimeStart);
                time.EndAtClipLength = EditorGUILayout.Toggle("End at clip length", time.EndAtClipLength);
                if (!time.EndAtClipLength) time.EndSeconds = EditorGUILayout.DoubleField("End (s)", time.EndSeconds);
                ValidationMessages.For(c, WindowFields.TimeEnd);

                var byRate = time.Fps > 0;
                var choice = EditorGUILayout.Popup("Steps", byRate ? 1 : 0, WindowText.TimeStepsLabels);
                if (choice == 1 && !byRate)
                {
                    time.Fps = 30;
                    time.Steps = 0;
                }
                else if (choice == 0 && byRate) time.Fps = 0;
                if (time.Fps > 0)
                {
                    time.Fps = EditorGUILayout.DoubleField("Frames per second", time.Fps);
                }
                else
                {
                    time.Steps = EditorGUILayout.IntField(time.Mode == TimeMode.Monocular ? "Steps (0: train count)" : "Steps", time.Steps);
                }
                ValidationMessages.For(c, WindowFields.TimeSteps);
                ValidationMessages.For(c, WindowFields.TimeFps);

                EditorGUILayout.LabelField(time.Mode == TimeMode.Monocular
                        ? "One train view per step along the train formation; val and test views between the train times."
                        : "Every camera of each split at every step: views = cameras × steps.",
                    EditorStyles.wordWrappedMiniLabel);
                EditorGUILayout.LabelField("Physics and scripts that move objects in Update are not captured: bake such motion into a clip.",
                    EditorStyles.wordWrappedMiniLabel);
            }
        }
    }
}
