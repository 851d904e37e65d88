using System;
using System.IO;
using System.Text.RegularExpressions;
using NUnit.Framework;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;
using UnityEngine.TestTools;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// The editor's one capture (<see cref="ActiveCapture"/>): a second one is refused, and the path that Play mode,
    /// domain reloads and quitting take (<see cref="ActiveCapture.Interrupt"/>) ends a run completely before it
    /// returns. Those three events themselves are exercised by <see cref="EditorEventTests"/>; quitting cannot be
    /// (it would end the test run), so its handler shares this path, which is tested here.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class ActiveCaptureTests
    {
        Scene _scene;
        GameObject _sphere;
        string _project;
        bool _asyncShadersBefore;
        int _previewScenesBefore;

        [SetUp]
        public void SetUp()
        {
            TestScene.RequireRendering();
            _scene = TestScene.Open();
            _sphere = TestScene.LitSphere("Session test sphere");
            _project = SessionTestSupport.NewTempFolder();
            _asyncShadersBefore = ShaderUtil.allowAsyncCompilation;
            _previewScenesBefore = EditorSceneManager.previewSceneCount;
        }

        [TearDown]
        public void TearDown()
        {
            ActiveCapture.Session?.Dispose();
            TestScene.Close(_scene);
            SessionTestSupport.DeleteFolder(_project);
        }

        void AssertEditorRestored()
        {
            Assert.That(ActiveCapture.IsRunning, Is.False, "the capture slot is free");
            Assert.That(ShaderUtil.allowAsyncCompilation, Is.EqualTo(_asyncShadersBefore), "asynchronous shader compilation is as it was");
            Assert.That(EditorSceneManager.previewSceneCount, Is.EqualTo(_previewScenesBefore), "the capture's preview scene is closed");
        }

        [Test]
        public void ASecondCaptureIsRefusedWhileOneRuns()
        {
            var session = CaptureRunner.RunInBackground(_sphere, SessionTestSupport.Poses(50), SessionTestSupport.Options(), new RecordingConsumer(), null);
            try
            {
                Assert.That(ActiveCapture.Session, Is.SameAs(session));
                Assert.That(ShaderUtil.allowAsyncCompilation, Is.False, "the running capture compiles shaders synchronously");
                var e = Assert.Throws<CaptureException>(() =>
                    CaptureRunner.RunBlocking(_sphere, SessionTestSupport.Poses(2), SessionTestSupport.Options(), new RecordingConsumer(), new ScriptedProgress()));
                Assert.That(e.Message, Does.Contain("Another capture is already running"));
                Assert.That(ActiveCapture.Session, Is.SameAs(session), "the refused capture did not disturb the running one");
                Assert.That(ShaderUtil.allowAsyncCompilation, Is.False, "nor restore the editor state under it");
            }
            finally
            {
                session.Dispose();
            }
            AssertEditorRestored();
        }

        [Test]
        public void ASecondDatasetCaptureIsRefusedBeforeItWritesAnything()
        {
            var first = DatasetCapture.Prepare(SessionTestSupport.Settings("first", 50), _sphere, _project);
            var session = DatasetCapture.StartInBackground(first, null);
            Assert.That(session, Is.Not.Null);
            var entries = Directory.GetFileSystemEntries(_project, "*", SearchOption.AllDirectories).Length;
            var second = DatasetCapture.Prepare(SessionTestSupport.Settings("second", 2), _sphere, _project);
            DatasetCaptureResult refused = null;
            LogAssert.Expect(LogType.Error, new Regex("nothing was captured — Another capture is already running"));
            Assert.That(DatasetCapture.StartInBackground(second, r => refused = r), Is.Null);
            Assert.That(refused.Succeeded, Is.False);
            Assert.That(Directory.GetFileSystemEntries(_project, "*", SearchOption.AllDirectories).Length, Is.EqualTo(entries), "no working folder for the refused run");

            LogAssert.Expect(LogType.Warning, new Regex("stopped after \\d+ written views because a test ended it"));
            ActiveCapture.Interrupt("a test ended it");
            AssertEditorRestored();
        }

        [Test]
        public void AnEditorEventBetweenStepsEndsTheCaptureBeforeItReturns()
        {
            var consumer = new RecordingConsumer();
            var ends = 0;
            Exception error = null;
            var session = CaptureRunner.RunInBackground(_sphere, SessionTestSupport.Poses(50), SessionTestSupport.Options(), consumer, (summary, e) =>
            {
                ends++;
                error = e;
            });
            Assert.That(EditorSceneManager.previewSceneCount, Is.EqualTo(_previewScenesBefore + 1));

            // What playModeStateChanged (ExitingEditMode), beforeAssemblyReload and quitting call.
            ActiveCapture.Interrupt("Unity is entering Play mode");

            Assert.That(ends, Is.EqualTo(1), "the run reported its end inside the call");
            Assert.That(error, Is.TypeOf<CaptureCancelledException>());
            Assert.That(((CaptureCancelledException)error).Interruption, Is.EqualTo("Unity is entering Play mode"));
            Assert.That(consumer.Aborted, Is.True);
            Assert.That(() => session.Step(1), Throws.TypeOf<CaptureCancelledException>(), "a late step says why the run is over");
            AssertEditorRestored();

            ActiveCapture.Interrupt("Unity is quitting");
            Assert.That(ends, Is.EqualTo(1), "a second event finds nothing to end");
        }

        [Test]
        public void AnEditorEventRaisedInsideAStepStopsTheRunAtItsNextCheck()
        {
            // E.g. an event raised while the blocking run draws its progress bar: the session is mid-step, so it is only
            // marked, and RunBlocking disposes it as soon as the step throws.
            var consumer = new RecordingConsumer();
            var progress = new ScriptedProgress { OnReport = meter => ActiveCapture.Interrupt("Unity is reloading scripts") };
            var e = Assert.Throws<CaptureCancelledException>(() =>
                CaptureRunner.RunBlocking(_sphere, SessionTestSupport.Poses(20), SessionTestSupport.Options(), consumer, progress));
            Assert.That(e.Interruption, Is.EqualTo("Unity is reloading scripts"));
            Assert.That(progress.Reports, Is.EqualTo(1), "the run stopped at the check after the first report");
            Assert.That(consumer.Aborted, Is.True);
            AssertEditorRestored();
        }

        [Test]
        public void AnInterruptedDatasetCaptureKeepsItsPartialFilesAndNamesThemInTheConsole()
        {
            var prepared = DatasetCapture.Prepare(SessionTestSupport.Settings("interrupted", 50), _sphere, _project);
            DatasetCaptureResult result = null;
            Assert.That(DatasetCapture.StartInBackground(prepared, r => result = r), Is.Not.Null);
            LogAssert.Expect(LogType.Warning, new Regex("stopped after 0 written views because Unity is quitting.*Partial files are in "));
            ActiveCapture.Interrupt("Unity is quitting");

            Assert.That(result, Is.Not.Null);
            Assert.That(result.Cancelled, Is.True);
            Assert.That(result.PartialFolder, Is.Not.Null.And.Not.Empty);
            Assert.That(Directory.Exists(result.PartialFolder), Is.True, "the working folder stays for the user");
            Assert.That(result.Message, Does.Contain(result.PartialFolder));
            Assert.That(Directory.Exists(prepared.DatasetFolder), Is.False, "nothing under the final name");
            AssertEditorRestored();
        }
    }
}
