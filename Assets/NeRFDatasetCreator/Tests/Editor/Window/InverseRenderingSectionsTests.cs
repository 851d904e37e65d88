using System.Collections;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using NUnit.Framework;
using UnityEditor;
using UnityEngine.TestTools;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Step 5's Material passes and Relighting sections (issue 38) draw with every part open (all passes; an environment
    /// without a map, a point light, a spot with and without a direction) without an error, and drawing them is not an
    /// edit: every value they show is the same afterwards (compared field by field, doubles round-trip exact).
    /// </summary>
    [TestFixture]
    public class InverseRenderingSectionsTests
    {
        static DatasetSettings EveryPartOpen()
        {
            var settings = new DatasetSettings { Name = "inverse rendering sections" };
            settings.Materials.On = true;
            settings.Materials.Specular = settings.Materials.Emission = true;
            settings.Relighting.On = true;
            settings.Relighting.Conditions = new List<LightingCondition>
            {
                new LightingCondition { Name = "sunset", Kind = LightingKind.Environment, File = "", Rotations = new[] { 0, 90.5, 0.1 }, Intensity = 1.3 },
                new LightingCondition { Name = "olat-00", Kind = LightingKind.Point, Position = new[] { 0.1, -3, 3 }, Intensity = 20, Colour = new[] { 1, 0.9, 0.3 } },
                new LightingCondition { Name = "key", Kind = LightingKind.Spot, Position = new double[] { 2, 2, 3 }, Direction = new[] { -2, -2, -3.3 }, SpotAngle = 30 },
                new LightingCondition { Name = "rim", Kind = LightingKind.Spot, Direction = null },
            };
            return settings;
        }

        static string Shown(DatasetSettings s)
        {
            var b = new StringBuilder();
            var m = s.Materials;
            b.Append(m.On).Append(m.Albedo).Append(m.Metallic).Append(m.Roughness).Append(m.Specular).Append(m.Emission).Append('|').Append(s.Relighting.On);
            foreach (var c in s.Relighting.Conditions)
            {
                b.Append('|').Append(c.Name).Append(',').Append(c.Kind).Append(',').Append(c.File).Append(',').Append(R(c.Intensity)).Append(',')
                    .Append(R(c.SpotAngle)).Append(',').Append(c.Shadows);
                foreach (var array in new[] { c.Rotations, c.Position, c.Direction, c.Colour })
                {
                    b.Append('[');
                    if (array != null) foreach (var v in array) b.Append(R(v)).Append(' ');
                    b.Append(']');
                }
            }
            return b.ToString();
        }

        static string R(double v) => v.ToString("R", CultureInfo.InvariantCulture);

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
                store.Apply(EveryPartOpen(), "NeRF inverse-rendering sections test");
                var before = Shown(store.Settings);
                window = EditorWindow.GetWindow<NerfDatasetCreatorWindow>("NeRF Dataset Creator");
                var until = EditorApplication.timeSinceStartup + 1.0;
                while (EditorApplication.timeSinceStartup < until)
                {
                    window.Repaint();
                    yield return null;
                }
                Assert.That(Shown(store.Settings), Is.EqualTo(before));
            }
            finally
            {
                if (window != null) window.Close();
                WindowStepFoldouts.SetOpen(WindowStep.Outputs, wasOpen);
                store.Apply(saved, "NeRF inverse-rendering sections test");
            }
        }
    }
}
