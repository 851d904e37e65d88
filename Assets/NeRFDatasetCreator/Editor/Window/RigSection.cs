using System.Linq;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Step 3: per split, how many views on which formation; the semi-sphere's tuning folded away.</summary>
    static class RigSection
    {
        static readonly string[] FormationLabels = WindowText.FormationLabels();

        public static void Draw(WindowContext c)
        {
            if (!SectionHeader.Foldout(c, WindowStep.Rig, "Rig per split")) return;
            var s = c.Settings;
            s.Seed = EditorGUILayout.LongField("Seed (random formations)", s.Seed);
            ValidationMessages.For(c, WindowFields.Seed);
            foreach (var split in DatasetSplits.All) DrawSplit(c, split);
        }

        static void DrawSplit(WindowContext c, DatasetSplit split)
        {
            var settings = c.Settings.Split(split);
            var formation = settings.Formation ?? (settings.Formation = new FormationSettings());

            EditorGUILayout.BeginHorizontal();
            SectionHeader.Swatch(RigPreview.ColorOf((PreviewSplit)(int)split));
            EditorGUILayout.LabelField(DatasetSplits.Name(split), EditorStyles.boldLabel);
            EditorGUILayout.EndHorizontal();

            using (new EditorGUI.IndentLevelScope())
            {
                if (CameraSourceSection.Draw(c, split)) return; // another source (file, scene, animated camera) sets the views
                settings.Count = EditorGUILayout.IntField("Views", settings.Count);
                ValidationMessages.For(c, WindowFields.SplitField(split, "count"));
                var kind = EditorGUILayout.Popup("Formation", (int)formation.Kind, FormationLabels);
                formation.Kind = FormationKinds.All[Mathf.Clamp(kind, 0, FormationKinds.All.Count - 1)];
                // Only the formation itself: its parameters' problems appear under each parameter.
                Show(c, WindowFields.SplitField(split, "formation"), exactOnly: true);

                switch (formation.Kind)
                {
                    case FormationKind.Halo:
                        Parameter(c, split, "elevationDegrees", "Elevation (°)", ref formation.ElevationDegrees);
                        Parameter(c, split, "startAzimuthDegrees", "Start azimuth (°)", ref formation.StartAzimuthDegrees);
                        break;
                    case FormationKind.SemiSphere:
                        DrawSemiSphere(c, split, formation);
                        break;
                    case FormationKind.Random:
                        formation.UpperHemisphereOnly = EditorGUILayout.Toggle("Upper hemisphere only", formation.UpperHemisphereOnly);
                        ValidationMessages.For(c, WindowFields.FormationField(split, "upperHemisphereOnly"));
                        break;
                    case FormationKind.Orbit:
                        Parameter(c, split, "turns", "Turns", ref formation.Turns);
                        Parameter(c, split, "lowElevationDegrees", "Lowest elevation (°)", ref formation.LowElevationDegrees);
                        Parameter(c, split, "highElevationDegrees", "Highest elevation (°)", ref formation.HighElevationDegrees);
                        Parameter(c, split, "startAzimuthDegrees", "Start azimuth (°)", ref formation.StartAzimuthDegrees);
                        break;
                }
            }
        }

        /// <summary>
        /// The semi-sphere works well as it is (nerf_synthetic's upper hemisphere), so its tuning is folded away;
        /// a problem inside the closed foldout is still shown, under the foldout.
        /// </summary>
        static void DrawSemiSphere(WindowContext c, DatasetSplit split, FormationSettings formation)
        {
            var open = EditorGUILayout.Foldout(c.Foldouts.Advanced(split), "Advanced", true);
            c.Foldouts.SetAdvanced(split, open);
            if (!open)
            {
                var fields = FormationSettings.ParameterNames(FormationKind.SemiSphere).Select(p => WindowFields.FormationField(split, p));
                ValidationMessages.Show(c.Problems.ErrorsForAny(fields), MessageType.Error, withField: true);
                return;
            }
            using (new EditorGUI.IndentLevelScope())
            {
                Parameter(c, split, "topElevationDegrees", "Top elevation (°)", ref formation.TopElevationDegrees);
                Parameter(c, split, "bottomElevationDegrees", "Bottom elevation (°)", ref formation.BottomElevationDegrees);
                Parameter(c, split, "spiralRatio", "Spiral ratio (0 = golden)", ref formation.SpiralRatio);
            }
        }

        static void Parameter(WindowContext c, DatasetSplit split, string name, string label, ref double value)
        {
            value = EditorGUILayout.DoubleField(label, value);
            ValidationMessages.For(c, WindowFields.FormationField(split, name));
        }

        static void Show(WindowContext c, string field, bool exactOnly)
        {
            if (!exactOnly)
            {
                ValidationMessages.For(c, field);
                return;
            }
            ValidationMessages.Show(c.Problems.Errors.Where(p => p.Field == field).ToList(), MessageType.Error);
            ValidationMessages.Show(c.Problems.Warnings.Where(p => p.Field == field).ToList(), MessageType.Warning);
        }
    }
}
