using System;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The editor's one running capture. Every <see cref="CaptureSession"/> claims this slot when it begins and frees
    /// it when it is disposed, so the window (any instance of it, reopened or not), batch mode, tests and scripts can
    /// never run two captures at once. While a capture runs, entering Play mode, a domain reload and quitting end it
    /// synchronously, inside the editor event itself: none of them is followed by an editor update that could do it
    /// later.
    /// <list type="bullet">
    /// <item><c>EditorApplication.playModeStateChanged</c> (ExitingEditMode) is raised from native code when Play mode
    /// is requested (Internal_PlayModeStateChanged, UnityCsReference 2022.3 Editor/Mono/EditorApplication.cs:459-467,
    /// 6000.0 :484-492). What follows it — the scene backup and, unless Enter Play Mode Options disable it, the domain
    /// reload — is native and unseen, so the capture is ended before the handler returns, releasing the reload lock
    /// that would otherwise block or defer that reload.</item>
    /// <item><c>AssemblyReloadEvents.beforeAssemblyReload</c> (OnBeforeAssemblyReload, AssemblyReloadEvents.cs:27-32 in
    /// both branches) runs just before the old domain is unloaded. A capture holds the reload lock, so a script edit
    /// waits for the capture's end; this handler covers a reload that happens anyway.</item>
    /// <item><c>EditorApplication.quitting</c> (Internal_EditorApplicationQuit, 2022.3 EditorApplication.cs:116-126,
    /// 6000.0 :125-135).</item>
    /// </list>
    /// None of those three loops catches exceptions, so a throwing handler would skip every later subscriber: the
    /// handlers here never throw. Whatever the order in which they arrive, the first one ends the capture and the
    /// others find nothing running. Ending a capture unsubscribes these handlers from inside the event being raised,
    /// which is safe: the loops iterate a snapshot of the subscribers (EventWithPerformanceTracker.cs:77-128, 2022.3).
    /// </summary>
    public static class ActiveCapture
    {
        static CaptureSession s_session;

        /// <summary>The running capture, or null.</summary>
        public static CaptureSession Session => s_session;

        public static bool IsRunning => s_session != null;

        /// <summary>The sentence a refused second capture reports.</summary>
        public static string BusyMessage => "Another capture is already running in this editor" +
            (s_session == null || string.IsNullOrEmpty(s_session.TargetName) ? "" : " (of '" + s_session.TargetName + "')") +
            ". Only one capture runs at a time: wait for it to finish, or cancel it (NeRF Dataset Creator window or Background Tasks).";

        /// <summary>Throws <see cref="CaptureException"/> when a capture is running.</summary>
        public static void ThrowIfBusy()
        {
            if (s_session != null) throw new CaptureException(BusyMessage);
        }

        internal static void Claim(CaptureSession session)
        {
            ThrowIfBusy();
            s_session = session;
            EditorApplication.playModeStateChanged += OnPlayModeStateChanged;
            AssemblyReloadEvents.beforeAssemblyReload += OnBeforeAssemblyReload;
            EditorApplication.quitting += OnQuitting;
        }

        internal static void Release(CaptureSession session)
        {
            if (s_session != session) return;
            s_session = null;
            EditorApplication.playModeStateChanged -= OnPlayModeStateChanged;
            AssemblyReloadEvents.beforeAssemblyReload -= OnBeforeAssemblyReload;
            EditorApplication.quitting -= OnQuitting;
        }

        static void OnPlayModeStateChanged(PlayModeStateChange change)
        {
            if (change == PlayModeStateChange.ExitingEditMode) Interrupt("Unity is entering Play mode");
        }

        static void OnBeforeAssemblyReload() => Interrupt("Unity is reloading scripts");

        static void OnQuitting() => Interrupt("Unity is quitting");

        /// <summary>
        /// Ends the running capture now, as those editor events do: the preview scene, render textures, readbacks
        /// and writer threads are released and the editor state restored before this returns (unless it is called
        /// from inside the capture's own step, which then stops at its next check). The partial dataset stays in its
        /// working folder, which the result names in the Console. Never throws.
        /// </summary>
        public static void Interrupt(string reason)
        {
            var session = s_session;
            if (session == null) return;
            try
            {
                session.Interrupt(reason);
            }
            catch (Exception e)
            {
                Debug.LogException(e);
            }
        }
    }
}
