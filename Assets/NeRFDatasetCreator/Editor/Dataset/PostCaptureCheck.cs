using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Threading;
using System.Threading.Tasks;
using UnityEditor;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The self-check after every capture (issue 21): Core's <see cref="DatasetCheck.Run"/> — the checks of
    /// <c>nerf-dataset check</c> — on the dataset just written, on a worker thread (it only reads files), with its
    /// report written into the dataset as <see cref="DatasetCheck.ReportFileName"/>. Progress goes to Unity's Background
    /// Tasks (<see cref="BackgroundJob"/>).
    /// </summary>
    public static class PostCaptureCheck
    {
        const string Title = "NeRF dataset check";

        /// <summary>True while a background check runs (the window says so under Create).</summary>
        public static bool IsRunning => s_running > 0;

        static int s_running;

        /// <summary>
        /// Checks <paramref name="datasetFolder"/> on a worker thread and calls <paramref name="done"/> on the main thread
        /// (from <c>EditorApplication.update</c>) with the report; Cancel in Background Tasks stops it (the report then
        /// says so). The editor stays usable.
        /// </summary>
        public static void StartInBackground(string datasetFolder, Action<DatasetCheckReport> done)
        {
            Interlocked.Increment(ref s_running);
            BackgroundJob.Start(Title, Path.GetFileName(datasetFolder), reportsSteps: true, cancellable: true,
                (report, cancel) => CheckAndWrite(datasetFolder, report, cancel), task =>
                {
                    Interlocked.Decrement(ref s_running);
                    var result = Result(task, datasetFolder);
                    done?.Invoke(result);
                    return result.Cancelled ? Progress.Status.Canceled : result.Failed ? Progress.Status.Failed : Progress.Status.Succeeded;
                });
        }

        /// <summary>
        /// Checks <paramref name="datasetFolder"/> on a worker thread while this (main) thread waits, calling
        /// <paramref name="progress"/> here with (steps done, steps total) about ten times a second: batch mode, the
        /// window's foreground capture, the preflight and the tests.
        /// </summary>
        public static DatasetCheckReport RunBlocking(string datasetFolder, Action<int, int> progress = null)
        {
            int doneSteps = 0, totalSteps = 1;
            var task = Task.Run(() => CheckAndWrite(datasetFolder, (d, t) =>
            {
                Volatile.Write(ref totalSteps, Math.Max(1, t));
                Volatile.Write(ref doneSteps, d);
            }, CancellationToken.None));
            try
            {
                while (!task.Wait(100)) progress?.Invoke(Volatile.Read(ref doneSteps), Volatile.Read(ref totalSteps));
            }
            catch (AggregateException)
            {
                // The check itself crashed: Result words it as a failed report.
            }
            return Result(task, datasetFolder);
        }

        /// <summary>
        /// The check, and its report written into the dataset (the dataset is the capture's own, just written) by Core's
        /// one writer of it, <see cref="CheckReportFile"/>. Nothing is written once the token is cancelled — Cancel, or
        /// Play mode / a reload / quitting ending the job (<see cref="BackgroundJob"/>, review R4-9) — so such an event
        /// never finds the report being written for a check it has already reported as cancelled.
        /// </summary>
        static DatasetCheckReport CheckAndWrite(string datasetFolder, Action<int, int> progress, CancellationToken cancel)
        {
            var report = DatasetCheck.Run(datasetFolder, new DatasetCheckOptions(), progress, cancel);
            if (!cancel.IsCancellationRequested) CheckReportFile.WriteInto(datasetFolder, report);
            return report;
        }

        /// <summary>The task's report; a crash of the check itself (a bug, or the folder deleted under it) becomes a failed report naming it.</summary>
        static DatasetCheckReport Result(Task<DatasetCheckReport> task, string datasetFolder)
        {
            if (task.Status == TaskStatus.RanToCompletion) return task.Result;
            var error = task.Exception?.GetBaseException();
            var report = new DatasetCheckReport(datasetFolder);
            report.Add(new DatasetProblem("check", datasetFolder, -1,
                "could not be checked: " + (error?.Message ?? "the check did not finish") + ". Run `nerf-dataset check " + datasetFolder + "` to see why."));
            return report;
        }

        /// <summary>
        /// The report in a few lines for the log and the window: the verdict, each check's summary line, and the first
        /// problems (all of them are in <see cref="DatasetCheck.ReportFileName"/>).
        /// </summary>
        public static string Summary(DatasetCheckReport report, int maxProblems = 10)
        {
            var verdict = report.Cancelled ? "was cancelled"
                : report.Failed ? "FAILED: " + report.Problems.Count.ToString(CultureInfo.InvariantCulture) + " problem(s)"
                : "passed";
            var text = string.Format(CultureInfo.InvariantCulture, "Self-check of {0} views {1} ({2:0.0} s; {3} in the dataset):",
                report.ViewsChecked, verdict, report.TotalSeconds, DatasetCheck.ReportFileName);
            foreach (var line in report.SummaryLines) text += "\n  " + line;
            foreach (var problem in report.Problems.Take(maxProblems)) text += "\n  problem: " + problem;
            if (report.Problems.Count > maxProblems)
                text += "\n  … and " + (report.Problems.Count - maxProblems).ToString(CultureInfo.InvariantCulture) + " more.";
            return text;
        }
    }
}
