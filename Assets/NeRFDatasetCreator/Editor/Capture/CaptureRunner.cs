using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Ways to drive a <see cref="CaptureSession"/>: to the end in one call, or a slice per editor update.</summary>
    public static class CaptureRunner
    {
        /// <summary>
        /// Captures every pose before returning (the window's foreground mode, batch mode, tests, scripts), with a
        /// cancellable progress bar unless another reporter is given. Nothing else runs on the main thread meanwhile,
        /// so views render back to back at full speed, whatever the editor's focus: no editor update, Play-mode change
        /// or domain reload can come between them (they all run on the main thread, which this call holds). The bar is
        /// <c>EditorUtility.DisplayCancelableProgressBar</c>, native (UnityCsReference 2022.3
        /// Editor/Mono/EditorUtility.bindings.cs:186, 6000.0 :188); should it ever raise an editor event while it
        /// draws, <see cref="ActiveCapture"/> only marks the session and the next check stops the run.
        /// Throws <see cref="CaptureCancelledException"/>, <see cref="CaptureException"/> or
        /// <see cref="InvalidParameterException"/>; the scene is restored and the consumer aborted in every case.
        /// </summary>
        public static CaptureSummary RunBlocking(GameObject target, IReadOnlyList<UnityPose> poses, CaptureOptions options,
            IViewConsumer consumer, ICaptureProgress progress = null)
        {
            progress = progress ?? new ProgressBarReporter();
            try
            {
                using (var session = CaptureSession.Begin(target, poses, options, consumer, progress))
                {
                    while (session.Step(0.25))
                    {
                    }
                    var summary = session.Summary;
                    Debug.Log(summary + " [foreground: blocking run]");
                    return summary;
                }
            }
            finally
            {
                progress.Close();
            }
        }

        /// <summary>
        /// Starts a capture that renders for about <paramref name="sliceSeconds"/> per editor update, so the editor stays
        /// usable; progress and Cancel appear in Unity's Background Tasks. Editor updates slow down when the editor is
        /// not focused (EditorApplication.update docs), and so does this capture: use <see cref="RunBlocking"/> for
        /// full speed. <paramref name="done"/> gets the summary, or the exception (a
        /// <see cref="CaptureCancelledException"/> after a cancel, or when entering Play mode, a domain reload or
        /// quitting ended the run: then synchronously, from inside that editor event, see <see cref="ActiveCapture"/>).
        /// Setup errors are thrown from this call. Returns the session, whose <c>Cancel()</c> stops it.
        /// </summary>
        public static CaptureSession RunInBackground(GameObject target, IReadOnlyList<UnityPose> poses, CaptureOptions options,
            IViewConsumer consumer, Action<CaptureSummary, Exception> done, double sliceSeconds = 0.05)
        {
            var progress = new BackgroundProgressReporter();
            CaptureSession session;
            try
            {
                session = CaptureSession.Begin(target, poses, options, consumer, progress);
            }
            catch (Exception)
            {
                progress.FinalStatus = Progress.Status.Failed;
                progress.Close();
                throw;
            }

            EditorApplication.CallbackFunction tick = null;
            var ended = false;
            void End(CaptureSummary summary, Exception error)
            {
                // Once only: an exception thrown by done() must not make the tick's catch end the run a second time.
                if (ended) return;
                ended = true;
                EditorApplication.update -= tick;
                session.Dispose();
                // A cancel (the window's button, Background Tasks, or Play mode / a reload / quitting) is a cancel, not a failure.
                progress.FinalStatus = error == null ? Progress.Status.Succeeded
                    : error is OperationCanceledException ? Progress.Status.Canceled : Progress.Status.Failed;
                progress.Close();
                if (summary != null) Debug.Log(summary + " [background: one slice per editor update]");
                done?.Invoke(summary, error);
            }
            tick = () =>
            {
                try
                {
                    if (!session.Step(sliceSeconds)) End(session.Summary, null);
                }
                catch (Exception e)
                {
                    if (ended) throw; // from done(): the run is over; Unity logs it
                    End(null, e);
                }
            };
            // Play mode, a domain reload or quitting: end now, inside that event; no editor update may come before it.
            session.Interrupted = error => End(null, error);
            EditorApplication.update += tick;
            return session;
        }
    }
}
