using System;
using System.Collections;
using System.IO;
using System.Text.RegularExpressions;
using System.Threading;
using System.Threading.Tasks;
using Newtonsoft.Json.Linq;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.TestTools;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Review R4-9: a <see cref="BackgroundJob"/> (the self-check, the Dataset Tools) ended by Play mode, a domain reload
    /// or quitting — <see cref="BackgroundJob.InterruptAll"/>, the body of those three handlers — is cancelled, waited
    /// for and finished inside the event: <c>done</c> runs before the event returns and never again afterwards, and a
    /// self-check ended so leaves either no check_report.json or a whole one.
    /// </summary>
    [TestFixture]
    public class BackgroundJobInterruptTests
    {
        string _root;

        [SetUp]
        public void SetUp()
        {
            Assume.That(BackgroundJob.Running, Is.EqualTo(0), "no other job runs (a self-check of an earlier capture)");
            _root = Path.Combine(Path.GetTempPath(), "nerf-job-interrupt-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_root);
        }

        [TearDown]
        public void TearDown()
        {
            if (Directory.Exists(_root)) Directory.Delete(_root, true);
        }

        [UnityTest]
        public IEnumerator ACooperativeJobIsCancelledAndFinishedInsideTheEvent()
        {
            var calls = 0;
            Task<int> seen = null;
            BackgroundJob.Start("interrupt test", "waits for its token", reportsSteps: false, cancellable: false,
                (report, cancel) =>
                {
                    cancel.WaitHandle.WaitOne(TimeSpan.FromMinutes(1));
                    return cancel.IsCancellationRequested ? -1 : 1;
                },
                task =>
                {
                    calls++;
                    seen = task;
                    return Progress.Status.Canceled;
                });
            Assert.That(BackgroundJob.Running, Is.EqualTo(1));
            BackgroundJob.InterruptAll("Unity is entering Play mode");
            Assert.That(calls, Is.EqualTo(1), "done ran inside the event");
            Assert.That(seen.IsCompleted, Is.True, "waited for");
            Assert.That(seen.Result, Is.EqualTo(-1), "the worker saw its token cancelled");
            Assert.That(BackgroundJob.Running, Is.EqualTo(0));
            for (var i = 0; i < 5; i++) yield return null;
            Assert.That(calls, Is.EqualTo(1), "the poll does not report it a second time");
        }

        [Test]
        public void AJobWithoutCancelIsWaitedForABoundedTimeThenReportedAsCutOff()
        {
            using (var release = new ManualResetEventSlim(false))
            {
                Task<int> seen = null;
                BackgroundJob.Start("stubborn test", "ignores its token", reportsSteps: false, cancellable: false,
                    (report, cancel) =>
                    {
                        release.Wait(TimeSpan.FromMinutes(1));
                        return 2;
                    },
                    task =>
                    {
                        seen = task;
                        return Progress.Status.Failed;
                    });
                LogAssert.Expect(LogType.Warning, new Regex("^NeRF Dataset Creator: stubborn test was still running when Unity is reloading scripts; it is cut off there"));
                BackgroundJob.InterruptAll("Unity is reloading scripts", 100);
                Assert.That(seen, Is.Not.Null, "done ran inside the event");
                Assert.That(seen.IsCompleted, Is.False, "after the bounded wait, as it was");
                Assert.That(BackgroundJob.Running, Is.EqualTo(0));
                release.Set();
                seen.Wait(TimeSpan.FromSeconds(10));
            }
        }

        [Test]
        public void AnInterruptedSelfCheckLeavesNoReportOrAWholeOneAndReportsInsideTheEvent()
        {
            // A planned dataset (the tool's plan command: JSON files, no images) — a real folder for the real check.
            var config = Path.Combine(_root, "c.json");
            File.WriteAllText(config, "{ \"splits\": { \"train\": { \"count\": 40 }, \"val\": { \"count\": 5 }, \"test\": { \"count\": 5 } } }");
            var folder = Path.Combine(_root, "planned");
            Assert.That(ToolTranscript.Run("plan", "--config", config, "--out", folder).Succeeded, Is.True);

            DatasetCheckReport report = null;
            PostCaptureCheck.StartInBackground(folder, r => report = r);
            Assert.That(PostCaptureCheck.IsRunning, Is.True);
            BackgroundJob.InterruptAll("Unity is entering Play mode");
            Assert.That(report, Is.Not.Null, "the window and the Console get the check's result inside the event");
            Assert.That(PostCaptureCheck.IsRunning, Is.False);
            var file = Path.Combine(folder, DatasetCheck.ReportFileName);
            if (report.Cancelled) Assert.That(File.Exists(file), Is.False, "a cancelled check writes no report");
            // A check that finished before the event may or may not have written its report; if it did, all of it.
            if (File.Exists(file)) Assert.That((bool)JObject.Parse(File.ReadAllText(file))["cancelled"], Is.False, "a whole report");
        }
    }
}
