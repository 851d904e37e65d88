using System.Collections;
using System.Linq;
using NUnit.Framework;
using UnityEditor;
using UnityEngine.TestTools;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>Steps 1–6 fold, each remembered on its own for the editor session (SessionState).</summary>
    [TestFixture]
    public class WindowStepFoldoutTests
    {
        static readonly WindowStep[] Folding =
            { WindowStep.Target, WindowStep.Camera, WindowStep.Rig, WindowStep.Time, WindowStep.Outputs, WindowStep.OutputFolder };

        bool[] _saved;

        [SetUp]
        public void SetUp() => _saved = Folding.Select(WindowStepFoldouts.IsOpen).ToArray();

        [TearDown]
        public void TearDown()
        {
            for (var i = 0; i < Folding.Length; i++) WindowStepFoldouts.SetOpen(Folding[i], _saved[i]);
        }

        [Test]
        public void EachStepKeepsItsOwnState()
        {
            Assert.That(Folding.Select(WindowStepFoldouts.Key).Distinct().Count(), Is.EqualTo(Folding.Length));
            foreach (var step in Folding) WindowStepFoldouts.SetOpen(step, true);
            WindowStepFoldouts.SetOpen(WindowStep.Rig, false);
            Assert.That(Folding.Select(WindowStepFoldouts.IsOpen), Is.EqualTo(new[] { true, true, false, true, true, true }));
            Assert.That(SessionState.GetBool(WindowStepFoldouts.Key(WindowStep.Rig), true), Is.False, "kept in SessionState");
        }

        [UnityTest]
        public IEnumerator TheWindowDrawsWithEveryStepClosedAndOpen()
        {
            // An exception or an unbalanced layout group in OnGUI is logged as an error, which fails the test; the
            // yielded editor frames let the window paint.
            foreach (var open in new[] { false, true })
            {
                foreach (var step in Folding) WindowStepFoldouts.SetOpen(step, open);
                var window = EditorWindow.GetWindow<NerfDatasetCreatorWindow>("NeRF Dataset Creator");
                window.Repaint();
                yield return null;
                yield return null;
                window.Close();
            }
        }
    }
}
