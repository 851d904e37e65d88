using System;
using System.Collections.Generic;
using System.Threading;
using System.Threading.Tasks;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Core work (no Unity API) on a worker thread while the editor stays usable: a task in Unity's Background Tasks
    /// window and status bar (Progress API, https://docs.unity3d.com/2022.3/Documentation/ScriptReference/Progress.html;
    /// <c>Progress.Start/Report/Finish</c> are bound thread-safe, UnityCsReference 2022.3 and 6000.0
    /// <c>Editor/Mono/Progress/Progress.bindings.cs:99-102, 126-150</c>, so the worker reports directly), and script
    /// reloading held until the work ends (<c>EditorApplication.LockReloadAssemblies</c>, UnityCsReference 2022.3
    /// <c>Editor/Mono/EditorApplication.bindings.cs:154/158</c>, 6000.0 <c>:148/152</c>): a reload would drop the static
    /// poll below and cut the worker off mid-write. The self-check after a capture and the Tools window's commands run
    /// through it.
    /// <para>
    /// Play mode, a domain reload and quitting are handled as <see cref="ActiveCapture"/> handles them for a capture
    /// (review R4-9): whether the reload lock also holds back Play mode's domain reload is native and unseen, and C#
    /// progress items are "Managed" and "get canceled when a domain reload occurs" (Progress.bindings.cs:104-106 on
    /// 2022.3.76f1 and 6000.0.78f1), so the job must not outlive those events unnoticed. On
    /// <c>EditorApplication.playModeStateChanged</c> (ExitingEditMode; raised by Internal_PlayModeStateChanged,
    /// Editor/Mono/EditorApplication.cs:459 on 2022.3.76f1, :484 on 6000.0.78f1), <c>AssemblyReloadEvents.beforeAssemblyReload</c>
    /// (OnBeforeAssemblyReload, Editor/Mono/AssemblyReloadEvents.cs:28 on both) and <c>EditorApplication.quitting</c>
    /// (Internal_EditorApplicationQuit, EditorApplication.cs:116 / :125) every running job is cancelled (its token), waited
    /// for at most <see cref="InterruptWaitMilliseconds"/>, and finished inside that event: its <c>done</c> runs there with
    /// the task as it is (a finished one with its result, a cancelled self-check says so and wrote no report), the reload
    /// lock is released and the Progress item finished. A worker still running after the wait (a command without a
    /// Cancel) is left to the reload; convert, merge and clean are finished or rolled back by their next run
    /// (Documentation~/reliability.md). None of those event loops catches exceptions, so the handlers never throw.
    /// </para>
    /// </summary>
    public static class BackgroundJob
    {
        /// <summary>How long an editor event waits for a cancelled job before finishing it as it is.</summary>
        public const int InterruptWaitMilliseconds = 5000;

        static readonly List<IJob> s_running = new List<IJob>();

        /// <summary>How many jobs run now.</summary>
        public static int Running => s_running.Count;

        interface IJob
        {
            void Interrupt(string reason, int waitMilliseconds);
        }

        /// <param name="name">The task's name in Background Tasks.</param>
        /// <param name="description">Its second line.</param>
        /// <param name="cancellable">Shows Cancel, which cancels the token <paramref name="work"/> receives.</param>
        /// <param name="work">Runs on the worker with a (steps done, steps total) reporter and the token; null reporter steps mean an indefinite task.
        /// The token is also cancelled when Play mode, a domain reload or quitting ends the job.</param>
        /// <param name="done">Called once on the main thread — from <c>EditorApplication.update</c>, or from inside the editor
        /// event that ended the job — with the task, however it ended (it may still be running after such an event);
        /// returns the task's final status.</param>
        public static void Start<T>(string name, string description, bool reportsSteps, bool cancellable,
            Func<Action<int, int>, CancellationToken, T> work, Func<Task<T>, Progress.Status> done)
        {
            var job = new Job<T>(name, done);
            var id = job.Id = Progress.Start(name, description, reportsSteps ? Progress.Options.None : Progress.Options.Indefinite);
            if (cancellable)
                Progress.RegisterCancelCallback(id, () =>
                {
                    job.Cancel.Cancel();
                    return true;
                });
            EditorApplication.LockReloadAssemblies();
            Action<int, int> report = (steps, total) => Progress.Report(id, steps, Math.Max(1, total));
            var token = job.Cancel.Token;
            job.Task = Task.Run(() => work(report, token));
            s_running.Add(job);
            if (s_running.Count == 1)
            {
                EditorApplication.playModeStateChanged += OnPlayModeStateChanged;
                AssemblyReloadEvents.beforeAssemblyReload += OnBeforeAssemblyReload;
                EditorApplication.quitting += OnQuitting;
            }
            EditorApplication.update += job.Poll;
        }

        /// <summary>
        /// Ends every running job now, as Play mode, a domain reload and quitting do: cancels its token, waits for it at
        /// most <paramref name="waitMilliseconds"/>, and calls its <c>done</c> before returning. Never throws.
        /// </summary>
        public static void InterruptAll(string reason, int waitMilliseconds = InterruptWaitMilliseconds)
        {
            foreach (var job in s_running.ToArray()) job.Interrupt(reason, waitMilliseconds);
        }

        static void OnPlayModeStateChanged(PlayModeStateChange change)
        {
            if (change == PlayModeStateChange.ExitingEditMode) InterruptAll("Unity is entering Play mode");
        }

        static void OnBeforeAssemblyReload() => InterruptAll("Unity is reloading scripts");

        static void OnQuitting() => InterruptAll("Unity is quitting");

        static void Remove(IJob job)
        {
            if (!s_running.Remove(job) || s_running.Count > 0) return;
            EditorApplication.playModeStateChanged -= OnPlayModeStateChanged;
            AssemblyReloadEvents.beforeAssemblyReload -= OnBeforeAssemblyReload;
            EditorApplication.quitting -= OnQuitting;
        }

        sealed class Job<T> : IJob
        {
            readonly string _name;
            readonly Func<Task<T>, Progress.Status> _done;
            bool _ended;

            public Job(string name, Func<Task<T>, Progress.Status> done)
            {
                _name = name;
                _done = done;
            }

            public int Id;
            public readonly CancellationTokenSource Cancel = new CancellationTokenSource();
            public Task<T> Task;

            public void Poll()
            {
                if (Task.IsCompleted) End();
            }

            public void Interrupt(string reason, int waitMilliseconds)
            {
                try
                {
                    if (!Task.IsCompleted)
                    {
                        Cancel.Cancel();
                        try
                        {
                            Task.Wait(Math.Max(0, waitMilliseconds));
                        }
                        catch (AggregateException)
                        {
                            // A cancelled or failed task: done reads it.
                        }
                        if (!Task.IsCompleted)
                            Debug.LogWarning("NeRF Dataset Creator: " + _name + " was still running when " + reason +
                                             "; it is cut off there. A self-check wrote no report; run it again. A convert, merge or clean is finished or rolled back by its next run.");
                    }
                    End();
                }
                catch (Exception e)
                {
                    Debug.LogException(e); // never out of an editor event: a throwing handler skips the later subscribers
                }
            }

            /// <summary>Once only: unsubscribe, release the reload lock, report, finish the Progress item.</summary>
            void End()
            {
                if (_ended) return;
                _ended = true;
                EditorApplication.update -= Poll;
                Remove(this);
                EditorApplication.UnlockReloadAssemblies();
                var status = Progress.Status.Failed;
                try
                {
                    status = _done(Task);
                }
                finally
                {
                    if (Task.IsCompleted) Cancel.Dispose(); // a worker still running may yet read its token
                    if (Progress.Exists(Id)) Progress.Finish(Id, status);
                }
            }
        }
    }
}
