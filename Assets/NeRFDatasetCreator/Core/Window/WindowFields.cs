using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The setting paths (as <see cref="ValidationProblem.Field"/> spells them) that the window has a control for,
    /// and the step each belongs to, so that a problem appears next to the control that fixes it.
    /// </summary>
    public static class WindowFields
    {
        public const string Target = "target";
        public const string Scene = "scene";
        public const string Distance = "distance";
        public const string AutoDistanceMargin = "autoDistanceMargin";
        public const string VerticalFov = "camera.verticalFovDegrees";
        public const string NearClip = "camera.nearClip";
        public const string FarClip = "camera.farClip";
        public const string CopyFromCamera = "camera.copyFromCamera";
        public const string Width = "width";
        public const string Height = "height";
        public const string Supersampling = "supersampling";
        public const string Background = "background";
        public const string Seed = "seed";
        public const string Name = "name";
        public const string OutputFolder = "outputFolder";
        public const string Overwrite = "overwrite";
        public const string Loaders = "loaders";
        public const string Normalisation = "normalisation";

        /// <summary>The <c>"labels"</c> section (Core/Labels): shown in step 5, Outputs.</summary>
        public const string Labels = "labels";
        public const string NormalisedTargetRadius = "normalisedTargetRadius";
        public const string PointCloudPoints = "pointCloudPoints";
        public const string PointCloudRadius = "pointCloudRadius";
        public const string TimeModeField = "time.mode";
        public const string TimeSourcesField = "time.sources";
        public const string TimeStart = "time.start";
        public const string TimeEnd = "time.end";
        public const string TimeSteps = "time.steps";
        public const string TimeFps = "time.fps";
        /// <summary>The exposure controls (Editor ExposureSection) show every "exposure.…" problem.</summary>
        public const string Exposure = "exposure";
        /// <summary>The Lens section (Editor LensSection) shows every "lens.…" problem: a coefficient's under its field, the rest below.</summary>
        public const string Lens = LensSettings.Key;
        /// <summary>The Motion blur section (Editor MotionBlurSection) shows every "motionBlur.…" problem.</summary>
        public const string MotionBlur = MotionBlurSettingsJson.Key;
        /// <summary>The HDR section (Editor HdrSection) shows every "hdr.…" problem.</summary>
        public const string Hdr = HdrSettingsJson.Key;

        /// <summary>Step 5's Sparse-view splits field (<see cref="SparseViewsChoices"/>).</summary>
        public const string SparseViews = SparseViewsSettings.Key;

        /// <summary>"splits.train.count" and the like.</summary>
        public static string SplitField(DatasetSplit split, string key) => "splits." + DatasetSplits.Name(split) + "." + key;

        /// <summary>"splits.train.formation.turns" and the like: where formation validation reports a parameter.</summary>
        public static string FormationField(DatasetSplit split, string parameter) => SplitField(split, "formation") + "." + parameter;

        /// <summary>Every field with a control in the window for these settings (formation parameters of the chosen kinds).</summary>
        public static IReadOnlyList<string> All(DatasetSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            var fields = new List<string>
            {
                Target, Scene, Distance, AutoDistanceMargin, VerticalFov, NearClip, FarClip, CopyFromCamera, Width, Height,
                Supersampling, Background, Seed, Name, OutputFolder, Overwrite, Loaders,
                Normalisation, NormalisedTargetRadius, PointCloudPoints, PointCloudRadius,
                TimeModeField, TimeSourcesField, TimeStart, TimeEnd, TimeSteps, TimeFps,
                Exposure, Lens, MotionBlur, SparseViews, Hdr,
            };
            foreach (var split in DatasetSplits.All)
            {
                fields.Add(SplitField(split, "count"));
                fields.Add(SplitField(split, "formation"));
                fields.Add(SplitField(split, "source"));
                var formation = settings.Split(split)?.Formation;
                if (formation != null)
                    foreach (var parameter in FormationSettings.ParameterNames(formation.Kind))
                        fields.Add(FormationField(split, parameter));
                fields.Add(SplitField(split, "depth"));
                fields.Add(SplitField(split, "normal"));
                fields.Add(SplitField(split, "mask"));
            }
            // The Labels controls of step 5 (Editor LabelsSection); each class rule's problems sit under its row.
            if (settings.Labels != null && settings.Labels.Enabled)
                fields.AddRange(new[] { Labels + ".instances", Labels + ".classFrom", Labels + ".classes", Labels + ".otherClass" });
            return fields;
        }

        /// <summary>
        /// True when a problem about <paramref name="problemField"/> belongs next to the control for
        /// <paramref name="controlField"/>: the same path, or a part of it ("background.r" under "background").
        /// </summary>
        public static bool Covers(string controlField, string problemField)
        {
            if (controlField == null || problemField == null) return false;
            if (string.Equals(controlField, problemField, StringComparison.Ordinal)) return true;
            return problemField.Length > controlField.Length &&
                   problemField.StartsWith(controlField, StringComparison.Ordinal) &&
                   (problemField[controlField.Length] == '.' || problemField[controlField.Length] == '[');
        }

        /// <summary>
        /// The step whose controls fix a problem about <paramref name="field"/>; <see cref="WindowStep.Create"/> for
        /// problems no setting fixes (the graphics device, the render pipeline, Play mode).
        /// </summary>
        public static WindowStep StepOf(string field)
        {
            if (string.IsNullOrEmpty(field)) return WindowStep.Create;
            if (Covers(Target, field) || Covers(Scene, field) || Covers(Distance, field) || Covers(AutoDistanceMargin, field))
                return WindowStep.Target;
            if (Covers("camera", field) || Covers(Width, field) || Covers(Height, field) || Covers(Supersampling, field) || Covers(Background, field))
                return WindowStep.Camera;
            if (Covers(Seed, field)) return WindowStep.Rig;
            if (Covers("time", field)) return WindowStep.Time;
            if (Covers(Name, field) || Covers(OutputFolder, field) || Covers(Overwrite, field) || Covers(Loaders, field))
                return WindowStep.OutputFolder;
            if (Covers(Normalisation, field) || Covers(NormalisedTargetRadius, field) || Covers(PointCloudPoints, field) || Covers(PointCloudRadius, field)
                || Covers(Exposure, field) || Covers(Lens, field) || Covers(MotionBlur, field) || Covers(SparseViews, field) || Covers(Hdr, field))
                return WindowStep.Outputs;
            if (Covers(Labels, field)) return WindowStep.Outputs;
            foreach (var split in DatasetSplits.All)
            {
                if (Covers(SplitField(split, "depth"), field) || Covers(SplitField(split, "normal"), field) || Covers(SplitField(split, "mask"), field))
                    return WindowStep.Outputs;
                if (Covers("splits." + DatasetSplits.Name(split), field)) return WindowStep.Rig;
            }
            return WindowStep.Create;
        }
    }
}
