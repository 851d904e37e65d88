using System;
using System.IO;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Step 7: what will be made, anything still wrong, how to run, the Create button, progress with Cancel, and the result.</summary>
    static class CreateSection
    {
        static readonly GUIContent RunLabel = new GUIContent("Run",
            "Background: the editor stays usable, but renders only on editor updates, which slow down while Unity is not focused. " +
            "Foreground: blocks the editor behind a progress bar with Cancel and renders at full speed.");
        static readonly GUIContent[] RunModes = { new GUIContent("In the background (editor stays usable)"), new GUIContent("In the foreground (blocking, fastest)") };

        /// <summary>Draws the step; returns the chosen run mode (true = foreground).</summary>
        public static bool Draw(WindowContext c, CaptureController capture, Action create, bool foreground)
        {
            SectionHeader.Draw(c, WindowStep.Create, "Create dataset");
            EditorGUILayout.LabelField(WindowText.RunSummary(c.Settings), EditorStyles.wordWrappedLabel);

            // Problems that no control above shows (the graphics device, the render pipeline, …) are listed here.
            ValidationMessages.Show(c.Problems.NotCoveredBy(WindowFields.All(c.Settings)), MessageType.Error, withField: true);
            ValidationMessages.Show(capture.StartProblems, MessageType.Error, withField: true);

            if (capture.IsRunning)
            {
                var meter = capture.Meter;
                var rect = EditorGUILayout.GetControlRect();
                EditorGUI.ProgressBar(rect, meter == null ? 0 : (float)meter.Fraction,
                    meter == null ? "Starting…" : WindowText.Progress(meter.Done, meter.Total, meter.ViewsPerSecond));
                if (GUILayout.Button("Cancel")) capture.Cancel();
                return foreground;
            }

            if (PostCaptureCheck.IsRunning)
                EditorGUILayout.LabelField("Checking the dataset just written (progress in Background Tasks)…", EditorStyles.wordWrappedMiniLabel);
            foreground = EditorGUILayout.Popup(RunLabel, foreground ? 1 : 0, RunModes) == 1;

            var first = c.Problems.FirstIncompleteStep();
            if (first.HasValue)
                EditorGUILayout.LabelField("Fix step " + (int)first.Value + " (" + first.Value + ") first; its problems are marked in red.",
                    EditorStyles.wordWrappedMiniLabel);
            using (new EditorGUI.DisabledScope(c.Problems.HasErrors || c.Target == null))
                if (GUILayout.Button("Create dataset", GUILayout.Height(28)))
                    c.Later(create);

            var result = capture.LastResult;
            if (result == null) return foreground;
            var type = result.Succeeded ? (result.CheckFailed ? MessageType.Warning : MessageType.Info) : result.Cancelled ? MessageType.Warning : MessageType.Error;
            EditorGUILayout.HelpBox(result.Message, type);
            var folder = result.Succeeded ? result.DatasetFolder : result.PartialFolder;
            if (!string.IsNullOrEmpty(folder) && Directory.Exists(folder) && GUILayout.Button(RevealLabel(result.Succeeded)))
                c.Later(() => EditorUtility.RevealInFinder(folder));
            return foreground;
        }

        static string RevealLabel(bool succeeded)
        {
            var where = Application.platform == RuntimePlatform.OSXEditor ? "Reveal in Finder"
                : Application.platform == RuntimePlatform.WindowsEditor ? "Show in Explorer" : "Open containing folder";
            return succeeded ? where : where + " (partial files)";
        }
    }
}
