using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The capture as the window shows it. Editor-wide, not per window: the running capture is
    /// <see cref="ActiveCapture"/>'s, so a window closed and reopened mid-run attaches to it (progress, Cancel) instead
    /// of starting a second one, and the last result is shared, so a reopened window shows how a run ended while no
    /// window was open. That result is also kept in SessionState, which outlives domain reloads (UnityCsReference
    /// 2022.3 Editor/Mono/EditorGUIUtility.bindings.cs:190-212, 6000.0 :192-215): after Play mode or a script reload
    /// stopped a run, the window still says why and where its partial files are, even if the Console was cleared.
    /// </summary>
    sealed class CaptureController
    {
        const string Key = "NerfDatasetCreator.LastCapture.";

        static DatasetCaptureResult s_lastResult;
        static bool s_lastResultLoaded;

        /// <summary>Raised when a capture starts or ends (any window's, or a script's through this controller).</summary>
        public static event Action Changed;

        /// <summary>True while any capture runs in this editor (this window's, another's, a script's).</summary>
        public bool IsRunning => ActiveCapture.IsRunning;

        /// <summary>Done / total and the rate of the running capture, or null.</summary>
        public ThroughputMeter Meter => ActiveCapture.Session?.Meter;

        public DatasetCaptureResult LastResult
        {
            get
            {
                if (!s_lastResultLoaded)
                {
                    s_lastResult = Load();
                    s_lastResultLoaded = true;
                }
                return s_lastResult;
            }
        }

        /// <summary>Problems found when Create was pressed (the disk or the scene may have changed since the last check).</summary>
        public IReadOnlyList<ValidationProblem> StartProblems { get; private set; } = Array.Empty<ValidationProblem>();

        /// <summary>
        /// Starts a capture: in the background (editor updates; the editor stays usable) or in the foreground (this
        /// call blocks behind a cancellable progress bar and renders at full speed). Call outside OnGUI (from
        /// EditorApplication.delayCall): it sets up cameras and render textures.
        /// </summary>
        public void Start(DatasetSettings settings, GameObject target, string projectRoot, bool foreground)
        {
            StartProblems = Array.Empty<ValidationProblem>();
            if (IsRunning)
            {
                StartProblems = new[] { new ValidationProblem("capture", "running", ActiveCapture.BusyMessage, "") };
                Changed?.Invoke();
                return;
            }
            var prepared = DatasetCapture.Prepare(settings.Clone(), target, projectRoot);
            if (!prepared.IsValid)
            {
                StartProblems = prepared.Problems;
                Changed?.Invoke();
                return;
            }
            Store(null);
            if (foreground)
            {
                var result = DatasetCapture.RunBlocking(prepared, new ProgressBarReporter());
                DatasetCapture.Log(result);
                Store(result);
            }
            else
            {
                // The result is logged by StartInBackground; the window may be closed by the time it comes.
                // Stored when the dataset is in place and again with the self-check's verdict (review R4-9).
                DatasetCapture.StartInBackground(prepared, Store, captured: Store);
                Changed?.Invoke();
            }
        }

        public void Cancel() => ActiveCapture.Session?.Cancel();

        public void ClearResult()
        {
            StartProblems = Array.Empty<ValidationProblem>();
            Store(null);
        }

        static void Store(DatasetCaptureResult result)
        {
            s_lastResult = result;
            s_lastResultLoaded = true;
            if (result == null)
            {
                SessionState.EraseInt(Key + "Kind");
            }
            else
            {
                SessionState.SetInt(Key + "Kind", result.Succeeded ? 1 : result.Cancelled ? 2 : 3);
                SessionState.SetString(Key + "Message", result.Message ?? "");
                SessionState.SetString(Key + "DatasetFolder", result.DatasetFolder ?? "");
                SessionState.SetString(Key + "PartialFolder", result.PartialFolder ?? "");
                SessionState.SetInt(Key + "Views", result.Views);
            }
            Changed?.Invoke();
        }

        static DatasetCaptureResult Load()
        {
            var kind = SessionState.GetInt(Key + "Kind", 0);
            if (kind == 0) return null;
            string Text(string name) => SessionState.GetString(Key + name, "") is var s && s.Length > 0 ? s : null;
            return new DatasetCaptureResult(kind == 1, kind == 2, Text("DatasetFolder"), Text("PartialFolder"),
                Text("Message") ?? "", SessionState.GetInt(Key + "Views", 0), 0);
        }
    }
}
