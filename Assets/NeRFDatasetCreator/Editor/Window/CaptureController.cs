using System;
using System.Collections.Generic;
using NerfDatasetCreator.Editor.Capture;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The window's one capture at a time: prepares it from a copy of the settings, runs it in the background
    /// (<see cref="DatasetCapture.StartInBackground"/>: the editor stays usable, progress and Cancel also appear in
    /// Background Tasks) and keeps the result for the result line.
    /// </summary>
    sealed class CaptureController
    {
        CaptureSession _session;
        int _run;

        public bool IsRunning => _session != null;

        /// <summary>Done / total and the rate of the running capture, or null.</summary>
        public ThroughputMeter Meter => _session?.Meter;

        public DatasetCaptureResult LastResult { get; private set; }

        /// <summary>Problems found when Create was pressed (the disk or the scene may have changed since the last check).</summary>
        public IReadOnlyList<ValidationProblem> StartProblems { get; private set; } = Array.Empty<ValidationProblem>();

        /// <summary>Starts a capture. Call outside OnGUI (from EditorApplication.delayCall): it sets up cameras and render textures.</summary>
        public void Start(DatasetSettings settings, GameObject target, string projectRoot, Action changed)
        {
            if (IsRunning) return;
            LastResult = null;
            StartProblems = Array.Empty<ValidationProblem>();
            var prepared = DatasetCapture.Prepare(settings.Clone(), target, projectRoot);
            if (!prepared.IsValid)
            {
                StartProblems = prepared.Problems;
                changed();
                return;
            }
            var run = ++_run;
            var ended = false;
            var session = DatasetCapture.StartInBackground(prepared, result =>
            {
                // Also called before StartInBackground returns when the capture could not start.
                ended = true;
                // Also to the Console: the window may have been closed while the run went on, and then this result
                // (where the dataset or the partial files are, or why it failed) would be shown nowhere.
                if (result.Succeeded) Debug.Log(result.Message);
                else if (result.Cancelled) Debug.LogWarning(result.Message);
                else Debug.LogError(result.Message);
                if (run != _run) return;
                _session = null;
                LastResult = result;
                changed();
            });
            if (!ended) _session = session;
            changed();
        }

        public void Cancel() => _session?.Cancel();

        public void ClearResult()
        {
            LastResult = null;
            StartProblems = Array.Empty<ValidationProblem>();
        }
    }
}
