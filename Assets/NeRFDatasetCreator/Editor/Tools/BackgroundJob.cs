using System;
using System.Threading;
using System.Threading.Tasks;
using UnityEditor;

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
    /// </summary>
    static class BackgroundJob
    {
        /// <param name="name">The task's name in Background Tasks.</param>
        /// <param name="description">Its second line.</param>
        /// <param name="cancellable">Shows Cancel, which cancels the token <paramref name="work"/> receives.</param>
        /// <param name="work">Runs on the worker with a (steps done, steps total) reporter and the token; null reporter steps mean an indefinite task.</param>
        /// <param name="done">Called on the main thread (from <c>EditorApplication.update</c>) with the finished task, however it ended; returns the task's final status.</param>
        public static void Start<T>(string name, string description, bool reportsSteps, bool cancellable,
            Func<Action<int, int>, CancellationToken, T> work, Func<Task<T>, Progress.Status> done)
        {
            var id = Progress.Start(name, description, reportsSteps ? Progress.Options.None : Progress.Options.Indefinite);
            var cancel = new CancellationTokenSource();
            if (cancellable)
                Progress.RegisterCancelCallback(id, () =>
                {
                    cancel.Cancel();
                    return true;
                });
            EditorApplication.LockReloadAssemblies();
            Action<int, int> report = (steps, total) => Progress.Report(id, steps, Math.Max(1, total));
            var task = Task.Run(() => work(report, cancel.Token));
            EditorApplication.CallbackFunction poll = null;
            poll = () =>
            {
                if (!task.IsCompleted) return;
                EditorApplication.update -= poll;
                EditorApplication.UnlockReloadAssemblies();
                var status = Progress.Status.Failed;
                try
                {
                    status = done(task);
                }
                finally
                {
                    cancel.Dispose();
                    if (Progress.Exists(id)) Progress.Finish(id, status);
                }
            };
            EditorApplication.update += poll;
        }
    }
}
