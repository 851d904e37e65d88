using System.IO;
using System.Linq;
using NUnit.Framework;
using UnityEditor;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>The window against the real capture entry point: it opens cleanly, and what Prepare reports lands next to a field.</summary>
    [TestFixture]
    public class WindowTests
    {
        [Test]
        public void TheWindowOpensAndClosesWithoutErrors()
        {
            // An exception in OnEnable, OnGUI or OnDisable is logged as an error, which fails the test.
            var window = EditorWindow.GetWindow<NerfDatasetCreatorWindow>("NeRF Dataset Creator");
            Assert.That(window, Is.Not.Null);
            window.Close();
        }

        [Test]
        public void AMissingTargetIsReportedUnderTheTargetField()
        {
            var root = Path.Combine(Path.GetTempPath(), "nerf-window-test-" + System.Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(root);
            try
            {
                var prepared = DatasetCapture.Prepare(new DatasetSettings(), null, root);
                Assert.That(prepared.IsValid, Is.False);
                var problems = new FieldProblems(prepared.Problems, prepared.Warnings);
                Assert.That(problems.ErrorsFor(WindowFields.Target), Is.Not.Empty,
                    "Prepare's problem for a missing target should use the field \"target\"; it said: " +
                    string.Join("; ", prepared.Problems.Select(p => p.Field)));
                Assert.That(problems.StepHasErrors(WindowStep.Target), Is.True);
            }
            finally
            {
                Directory.Delete(root, true);
            }
        }

        [Test]
        public void AnEndAtTheClipLengthOfATargetWithoutClipsIsReportedUnderTheTimeStep()
        {
            var root = Path.Combine(Path.GetTempPath(), "nerf-window-test-" + System.Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(root);
            var still = UnityEngine.GameObject.CreatePrimitive(UnityEngine.PrimitiveType.Cube); // no Animator, Animation, Timeline or particles
            try
            {
                var settings = new DatasetSettings();
                settings.Time.Mode = TimeMode.MultiView;
                settings.Time.Steps = 3;
                settings.Time.EndAtClipLength = true;
                var prepared = DatasetCapture.Prepare(settings, still, root);
                var problems = new FieldProblems(prepared.Problems, prepared.Warnings);
                Assert.That(problems.ErrorsFor(WindowFields.TimeEnd), Is.Not.Empty,
                    "fields reported: " + string.Join("; ", prepared.Problems.Select(p => p.Field)));
                Assert.That(problems.StepHasErrors(WindowStep.Time), Is.True);
            }
            finally
            {
                UnityEngine.Object.DestroyImmediate(still);
                Directory.Delete(root, true);
            }
        }
    }
}
