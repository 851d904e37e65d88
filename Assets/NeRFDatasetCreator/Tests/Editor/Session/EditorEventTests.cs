using System;
using System.Collections;
using System.IO;
using System.Linq;
using NUnit.Framework;
using UnityEditor;
using UnityEditor.Compilation;
using UnityEngine;
using UnityEngine.TestTools;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Real editor events in the middle of a background capture: entering Play mode, a script recompilation, and
    /// the window closed and reopened. Play mode and recompilation usually reload the domain, which ends this test's
    /// own state: the Test Framework resumes the test after the yield with its locals lost, so what the checks need
    /// afterwards is kept in SessionState (which outlives domain reloads) and the aftermath is checked — the editor
    /// state restored, no capture object left, the dataset complete or its partial folder kept.
    /// Quitting cannot be tested without ending the test run; its handler shares the path tested in
    /// <see cref="ActiveCaptureTests"/>.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class EditorEventTests
    {
        const string Key = "NerfDatasetCreator.Tests.EditorEvents.";
        const string SphereName = "NeRF editor-event test sphere";

        /// <summary>True only in the domain that set it: false again after a domain reload.</summary>
        static bool s_sameDomain;

        static GameObject StartOfTest(string datasetName)
        {
            TestScene.RequireRendering();
            TestScene.Open();
            var sphere = TestScene.LitSphere(SphereName);
            SessionState.SetString(Key + "Project", SessionTestSupport.NewTempFolder());
            SessionState.SetString(Key + "Dataset", datasetName);
            SessionState.SetBool(Key + "AsyncShaders", ShaderUtil.allowAsyncCompilation);
            return sphere;
        }

        static string DatasetsFolder => Path.Combine(SessionState.GetString(Key + "Project", ""), "NeRFDatasets");
        static string DatasetName => SessionState.GetString(Key + "Dataset", "");

        static void StartCapture(GameObject sphere, int trainViews)
        {
            var prepared = DatasetCapture.Prepare(SessionTestSupport.Settings(DatasetName, trainViews), sphere, SessionState.GetString(Key + "Project", ""));
            Assert.That(prepared.Problems.Select(p => p.ToString()), Is.Empty);
            Assert.That(DatasetCapture.StartInBackground(prepared, null), Is.Not.Null);
        }

        /// <summary>The editor as it was before the capture, and nothing of the capture left in memory.</summary>
        static void AssertEditorRestored()
        {
            Assert.That(ActiveCapture.IsRunning, Is.False);
            Assert.That(ShaderUtil.allowAsyncCompilation, Is.EqualTo(SessionState.GetBool(Key + "AsyncShaders", true)),
                "ShaderUtil.allowAsyncCompilation is back to its value before the capture");
            var leftovers = Resources.FindObjectsOfTypeAll<GameObject>()
                .Where(go => go.name == "NeRF Dataset Creator capture" || go.name == "NeRF Dataset Creator camera").ToList();
            Assert.That(leftovers, Is.Empty, "the capture's preview-scene objects are destroyed");
        }

        [UnityTearDown]
        public IEnumerator TearDown()
        {
            ActiveCapture.Session?.Dispose();
            if (EditorApplication.isPlaying) yield return new ExitPlayMode();
            var sphere = GameObject.Find(SphereName);
            if (sphere != null) TestScene.Close(sphere.scene);
            SessionTestSupport.DeleteFolder(SessionState.GetString(Key + "Project", ""));
            foreach (var name in new[] { "Project", "Dataset" }) SessionState.EraseString(Key + name);
            SessionState.EraseBool(Key + "AsyncShaders");
            SessionState.EraseBool(Key + "ExpectReload");
        }

        [UnityTest]
        public IEnumerator EnteringPlayModeMidCaptureEndsItAndTheConfiguredReloadGoesAhead()
        {
            var sphere = StartOfTest("playmode");
            StartCapture(sphere, 400);
            yield return null;
            yield return null;
            Assert.That(ActiveCapture.IsRunning, Is.True, "the capture is under way when Play mode is requested");

            // Enter Play Mode Options may turn the domain reload off; otherwise the capture's reload lock must not block it.
            var reloads = !(EditorSettings.enterPlayModeOptionsEnabled &&
                            (EditorSettings.enterPlayModeOptions & EnterPlayModeOptions.DisableDomainReload) != 0);
            SessionState.SetBool(Key + "ExpectReload", reloads);
            s_sameDomain = true;
            yield return new EnterPlayMode(reloads);

            if (SessionState.GetBool(Key + "ExpectReload", true))
                Assert.That(s_sameDomain, Is.False, "the domain reload happened: the capture released its reload lock in ExitingEditMode");
            AssertEditorRestored();
            Assert.That(Directory.Exists(Path.Combine(DatasetsFolder, DatasetName)), Is.False, "nothing under the final name");
            Assert.That(Directory.GetDirectories(DatasetsFolder, DatasetName + ".partial-*"), Has.Length.EqualTo(1),
                "the partial dataset stays in its working folder");
            yield return new ExitPlayMode();
        }

        [UnityTest]
        public IEnumerator ScriptRecompilationMidCaptureWaitsForTheCaptureToEnd()
        {
            var sphere = StartOfTest("recompile");
            StartCapture(sphere, 150);
            yield return null;
            Assert.That(ActiveCapture.IsRunning, Is.True, "the capture is under way when scripts are recompiled");

            // The capture holds the reload lock: Unity compiles, shows its lock icon, and reloads once the capture ends.
            CompilationPipeline.RequestScriptCompilation();
            yield return new WaitForCaptureThenDomainReload();

            AssertEditorRestored();
            var folder = Path.Combine(DatasetsFolder, DatasetName);
            Assert.That(Directory.Exists(folder), Is.True,
                "the reload waited for the capture, which finished the dataset (partial folders: " +
                string.Join(", ", Directory.GetDirectories(DatasetsFolder, DatasetName + ".partial-*")) + ")");
            Assert.That(DatasetValidator.Validate(folder).Problems.Select(p => p.ToString()), Is.Empty);
        }

        [UnityTest]
        public IEnumerator AWindowClosedAndReopenedMidCaptureAttachesToTheRunningCapture()
        {
            var sphere = StartOfTest("window");
            var window = EditorWindow.GetWindow<NerfDatasetCreatorWindow>("NeRF Dataset Creator");
            StartCapture(sphere, 400);
            var session = ActiveCapture.Session;
            Assert.That(window.IsCapturing, Is.True);

            window.Close();
            yield return null;
            Assert.That(ActiveCapture.Session, Is.SameAs(session), "closing the window neither stopped nor orphaned the run");
            var delivered = session.Delivered;
            for (var i = 0; i < 200 && session.Delivered == delivered && ActiveCapture.IsRunning; i++) yield return null;
            Assert.That(session.Delivered, Is.GreaterThan(delivered), "the run goes on without a window");

            var reopened = EditorWindow.GetWindow<NerfDatasetCreatorWindow>("NeRF Dataset Creator");
            Assert.That(reopened.IsCapturing, Is.True, "the reopened window shows the running capture");
            reopened.Repaint();
            yield return null; // draws progress and Cancel; an exception there would fail the test

            // The reopened window cannot start a second capture: Create goes through the same refusal.
            var second = DatasetCapture.Prepare(SessionTestSupport.Settings("second", 2), sphere, SessionState.GetString(Key + "Project", ""));
            LogAssert.Expect(LogType.Error, new System.Text.RegularExpressions.Regex("Another capture is already running"));
            Assert.That(DatasetCapture.StartInBackground(second, null), Is.Null);
            Assert.That(ActiveCapture.Session, Is.SameAs(session));

            LogAssert.Expect(LogType.Warning, new System.Text.RegularExpressions.Regex("The capture was cancelled after"));
            session.Cancel();
            for (var i = 0; i < 200 && ActiveCapture.IsRunning; i++) yield return null;
            Assert.That(reopened.IsCapturing, Is.False);
            AssertEditorRestored();
            reopened.Close();
        }

        /// <summary>
        /// Waits for the running capture to end and for the domain reload it deferred, like the Test Framework's own
        /// WaitForDomainReload: it lifts the test runner's reload lock first, and fails if no reload comes.
        /// </summary>
        sealed class WaitForCaptureThenDomainReload : IEditModeTestYieldInstruction
        {
            public bool ExpectDomainReload => true;
            public bool ExpectedPlaymodeState => false;

            public IEnumerator Perform()
            {
                EditorApplication.UnlockReloadAssemblies();
                var giveUp = EditorApplication.timeSinceStartup + 600;
                while ((ActiveCapture.IsRunning || EditorApplication.isCompiling) && EditorApplication.timeSinceStartup < giveUp)
                    yield return null;
                // The capture released its lock; the reload comes within a few editor updates and ends this enumerator.
                for (var i = 0; i < 600; i++) yield return null;
                EditorApplication.LockReloadAssemblies();
                throw new Exception("No domain reload came after the capture ended and released its reload lock " +
                    "(capture still running: " + ActiveCapture.IsRunning + ").");
            }
        }
    }
}
