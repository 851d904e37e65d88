using System;
using System.Threading.Tasks;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Runs one <c>nerf-dataset</c> command line inside the editor — validate, convert, merge or clean, through Core's
    /// <see cref="ToolTranscript"/>, so no .NET SDK is needed and the messages are the tool's own — on a worker
    /// thread, with a task in Unity's Background Tasks window and status bar (<see cref="BackgroundJob"/>). The editor
    /// stays usable; one command runs at a time. Script reloading waits until the command ends, so a command is never cut
    /// off by a recompile; Play mode or quitting waits for it a few seconds and then reports it cut off
    /// (<see cref="BackgroundJob.InterruptWaitMilliseconds"/>). Its lines go to the Console as one entry headed by the
    /// equivalent terminal command.
    /// There is no Cancel: every command finishes in one step or is finished or rolled back by the next run
    /// (Documentation~/reliability.md), which a stop in the middle would only postpone.
    /// </summary>
    public static class DatasetToolRunner
    {
        static bool _running;
        static string _title;

        /// <summary>Raised on the main thread when a command starts and when it ends.</summary>
        public static event Action Changed;

        public static bool IsRunning => _running;

        /// <summary>What the running command is ("convert to colmap"), or null.</summary>
        public static string RunningTitle => IsRunning ? _title : null;

        /// <summary>The last finished command in this editor session, or null.</summary>
        public static ToolTranscript Last { get; private set; }

        /// <summary>Starts <paramref name="arguments"/>; false (and nothing started) while another command runs.</summary>
        public static bool Start(string title, string[] arguments)
        {
            if (arguments == null) throw new ArgumentNullException(nameof(arguments));
            if (IsRunning) return false;
            _title = title;
            _running = true;
            // Core only (no Unity API) runs on the worker; ToolCommands turns anything unexpected into an error line.
            // Progress.Options.Indefinite: a command does not know its length in advance.
            BackgroundJob.Start("NeRF dataset: " + title, ToolTranscript.DescribeCommandLine(arguments), reportsSteps: false, cancellable: false,
                (report, cancel) => ToolTranscript.Run(arguments), Finished);
            Changed?.Invoke();
            return true;
        }

        static Progress.Status Finished(Task<ToolTranscript> task)
        {
            _running = false;
            Last = task.Status == TaskStatus.RanToCompletion ? task.Result : null;
            if (Last != null) Log(Last);
            else if (!task.IsCompleted)
                // Play mode, a script reload or quitting ended the job while the command still ran (BackgroundJob).
                Debug.LogError("NeRF Dataset Creator: " + _title + " was cut off by Unity before it ended. Run it again: its next run finishes or rolls back what this one started.");
            else Debug.LogError("NeRF Dataset Creator: " + _title + " stopped: " + task.Exception?.GetBaseException().Message);
            Changed?.Invoke();
            return Last != null && Last.Succeeded ? Progress.Status.Succeeded : Progress.Status.Failed;
        }

        /// <summary>One Console entry: the terminal command, then every line the command printed.</summary>
        public static void Log(ToolTranscript transcript)
        {
            var text = "NeRF Dataset Creator: " + transcript.CommandLine + " (exit " + transcript.ExitCode + ")\n" + string.Join("\n", transcript.Lines);
            if (transcript.Succeeded) Debug.Log(text);
            else Debug.LogError(text);
        }
    }
}
