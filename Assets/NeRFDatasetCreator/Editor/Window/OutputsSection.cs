using System.Linq;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Step 5: per split, the extra passes next to the RGBA image: depth and normals (PNG and/or EXR) and the mask; then
    /// one section per optional output (labels, exposure, lens, motion blur, sparse-view splits), the scene's scale and the geometry pack.
    /// </summary>
    static class OutputsSection
    {
        public static void Draw(WindowContext c)
        {
            if (!SectionHeader.Foldout(c, WindowStep.Outputs, "Outputs per split")) return;
            EditorGUILayout.LabelField("Every view writes its RGBA image; add passes per split.", EditorStyles.wordWrappedMiniLabel);
            foreach (var split in DatasetSplits.All)
            {
                var settings = c.Settings.Split(split);
                EditorGUILayout.BeginHorizontal();
                SectionHeader.Swatch(RigPreview.ColorOf((PreviewSplit)(int)split));
                EditorGUILayout.LabelField(DatasetSplits.Name(split), EditorStyles.boldLabel);
                EditorGUILayout.EndHorizontal();
                using (new EditorGUI.IndentLevelScope())
                {
                    settings.Depth = (ExtraOutput)EditorGUILayout.Popup("Depth", (int)settings.Depth, WindowText.ExtraOutputLabels);
                    ValidationMessages.For(c, WindowFields.SplitField(split, "depth"));
                    settings.Normal = (ExtraOutput)EditorGUILayout.Popup("Normal", (int)settings.Normal, WindowText.ExtraOutputLabels);
                    ValidationMessages.For(c, WindowFields.SplitField(split, "normal"));
                    settings.Mask = EditorGUILayout.Toggle("Mask", settings.Mask);
                    ValidationMessages.For(c, WindowFields.SplitField(split, "mask"));
                }
            }
            LabelsSection.Draw(c);
            ExposureSection.Draw(c);
            HdrSection.Draw(c);
            MaterialsSection.Draw(c);
            RelightingSection.Draw(c);
            LensSection.Draw(c);
            MotionBlurSection.Draw(c);
            SparseViewsSection.Draw(c);
            DrawScene(c);
            // "preflight" in config files (Documentation~/settings.md).
            c.Settings.Preflight = EditorGUILayout.Toggle(new GUIContent("Preflight check",
                "Before a capture of more than " + PreflightCheck.MinViews + " views, capture about " + PreflightCheck.Views +
                " of its views at low resolution into a temporary folder, check them and stop if the check fails."), c.Settings.Preflight);
            // "geometryPack" in config files (Documentation~/settings.md).
            c.Settings.GeometryPack = EditorGUILayout.Toggle(new GUIContent("Geometry pack",
                "Write the target's triangle mesh in the output frame, " + TargetMeshPly.RelativePath +
                " (ground truth for Chamfer / F-score and nerf-dataset evaluate --geometry). A whole dataset (or shard 0) of a target with meshes only; " +
                "a dynamic capture's mesh is the one at its start time unless Every time step is on."), c.Settings.GeometryPack);
            // "geometryPack": "everyStep" (Documentation~/evaluate.md): only a dynamic capture has steps.
            if (c.Settings.GeometryPack && c.Settings.Time != null && c.Settings.Time.Enabled)
            {
                EditorGUI.indentLevel++;
                c.Settings.GeometryPackEveryStep = EditorGUILayout.Toggle(new GUIContent("Every time step",
                    "Write the target's mesh at every time step (" + GeometryPackSteps.RelativePath(0) + " …) instead of the start time's only."), c.Settings.GeometryPackEveryStep);
                EditorGUI.indentLevel--;
            }
        }

        /// <summary>Scale and centring of the output world, and the initial point cloud for Gaussian Splatting.</summary>
        static void DrawScene(WindowContext c)
        {
            var settings = c.Settings;
            EditorGUILayout.LabelField("Scene", EditorStyles.boldLabel);
            using (new EditorGUI.IndentLevelScope())
            {
                settings.Normalisation = (NormalisationMode)EditorGUILayout.Popup("Normalisation", (int)settings.Normalisation, WindowText.NormalisationLabels);
                // Also where the NeRF near 2 / far 6 and ±1.3 warnings appear: the scale that fixes them is chosen here.
                ValidationMessages.For(c, WindowFields.Normalisation);
                if (settings.Normalisation == NormalisationMode.FitTargetRadius)
                {
                    settings.NormalisedTargetRadius = EditorGUILayout.DoubleField("Target radius", settings.NormalisedTargetRadius);
                    ValidationMessages.For(c, WindowFields.NormalisedTargetRadius);
                }
                settings.PointCloudPoints = EditorGUILayout.IntField("points3d.ply points", settings.PointCloudPoints);
                ValidationMessages.For(c, WindowFields.PointCloudPoints);
                if (settings.PointCloudPoints > 0 && DatasetSplits.All.Any(split => settings.Split(split)?.Source?.IsVolume == true))
                {
                    settings.PointCloudRadius = EditorGUILayout.DoubleField(new GUIContent("points3d.ply radius",
                        "Environment capture: only the scene's surface within this many units of the capture volumes' centre is sampled; 0 = " +
                        TargetPointCloud.DefaultRadiusFactor + " × the boxes' half-diagonal."), settings.PointCloudRadius);
                    ValidationMessages.For(c, WindowFields.PointCloudRadius);
                }
            }
        }
    }
}
