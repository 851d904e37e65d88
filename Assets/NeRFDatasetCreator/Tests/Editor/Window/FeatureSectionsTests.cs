using System.Collections;
using System.Collections.Generic;
using NUnit.Framework;
using UnityEditor;
using UnityEngine.TestTools;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Step 5's sections for the optional outputs (lens, motion blur, exposure list values, sparse-view splits, hdr) draw with every part they
    /// have open, and drawing them is not an edit: the stored settings are the same afterwards (a section that
    /// "corrected" a value while drawing would make an undo step of its own).
    /// </summary>
    [TestFixture]
    public class FeatureSectionsTests
    {
        static IEnumerable<DatasetSettings> EveryPartOpen()
        {
            var opencv = new DatasetSettings { Name = "sections" };
            opencv.Lens.Model = "opencv";
            opencv.Lens.K1 = -0.12;
            opencv.Lens.K4 = 0.01; // another model's coefficient, as a config may give it: drawn with its error under it
            opencv.MotionBlur.Enabled = true;
            opencv.MotionBlur.Camera = ShutterCameraMotion.Shake;
            opencv.MotionBlur.ShakeDegrees = 3;
            opencv.Exposure.Mode = ExposureMode.List;
            opencv.Exposure.Values = new List<ViewExposure> { new ViewExposure(-1, 1, 1, 1), new ViewExposure(1, 1.3, 1, 0.75), new ViewExposure(20, 1, 1, 1) };
            opencv.SparseViews = new[] { 3, 8 }; // the Sparse-view splits field shows "3, 8"
            opencv.Hdr.On = true;
            yield return opencv;

            var fisheye = new DatasetSettings { Name = "sections" };
            fisheye.Lens.Model = "opencv_fisheye";
            fisheye.Lens.K1 = 0.05;
            fisheye.MotionBlur.Enabled = true;
            fisheye.MotionBlur.Readout = 0.5;
            fisheye.Exposure.Mode = ExposureMode.List; // empty: the list's own error below the rows
            fisheye.SparseViews = new[] { 100 }; // as many as the train views: its error under the field
            fisheye.Hdr.On = true;
            fisheye.Hdr.Train = fisheye.Hdr.Val = fisheye.Hdr.Test = false; // hdr.splits' error under the section
            yield return fisheye;
        }

        [UnityTest]
        public IEnumerator TheSectionsDrawWithoutEditingTheSettings()
        {
            var store = NerfDatasetCreatorSettings.instance;
            var saved = store.Settings.Clone();
            var wasOpen = WindowStepFoldouts.IsOpen(WindowStep.Outputs);
            NerfDatasetCreatorWindow window = null;
            try
            {
                WindowStepFoldouts.SetOpen(WindowStep.Outputs, true);
                foreach (var settings in EveryPartOpen())
                {
                    store.Apply(settings, "NeRF sections test");
                    var before = DatasetSettingsJson.Write(store.Settings);
                    // An exception or an unbalanced layout group in OnGUI is logged as an error, which fails the test; the
                    // yielded editor frames let the window paint (and re-check, which puts the errors under the fields).
                    window = EditorWindow.GetWindow<NerfDatasetCreatorWindow>("NeRF Dataset Creator");
                    var until = EditorApplication.timeSinceStartup + 1.0;
                    while (EditorApplication.timeSinceStartup < until)
                    {
                        window.Repaint();
                        yield return null;
                    }
                    Assert.That(DatasetSettingsJson.Write(store.Settings), Is.EqualTo(before), "drawing changed the settings of " + settings.Lens.Model);
                    window.Close();
                    window = null;
                }
            }
            finally
            {
                if (window != null) window.Close();
                WindowStepFoldouts.SetOpen(WindowStep.Outputs, wasOpen);
                store.Apply(saved, "NeRF sections test");
            }
        }
    }
}
