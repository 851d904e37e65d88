using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Checks settings and returns every problem at once, each naming the config field, its value, why it is
    /// wrong and how to fix it. <see cref="Validate(DatasetSettings)"/> looks at the values only;
    /// <see cref="Validate(DatasetSettings, string)"/> also checks the output folder on disk.
    /// </summary>
    public static class SettingsValidator
    {
        public static IReadOnlyList<ValidationProblem> Validate(DatasetSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            var problems = new List<ValidationProblem>();
            void Add(ValidationProblem p)
            {
                if (p != null) problems.Add(p);
            }

            Add(DatasetNameRules.Check("name", settings.Name));

            var camera = settings.Camera ?? new CameraSettings();
            var fov = camera.VerticalFovDegrees;
            if (!(fov > 0 && fov < 180))
                Add(new ValidationProblem("camera.verticalFovDegrees", ValidationProblem.Format(fov),
                    IsFinite(fov) ? "must be more than 0 and less than 180 degrees." : "is not a finite number.",
                    "Use Unity's vertical field of view, e.g. 39.6 (nerf_synthetic) or 60."));
            var nearOk = IsFinite(camera.NearClip) && camera.NearClip > 0;
            if (!nearOk)
                Add(new ValidationProblem("camera.nearClip", ValidationProblem.Format(camera.NearClip),
                    IsFinite(camera.NearClip) ? "must be above 0." : "is not a finite number.", "Use a small positive distance such as 0.1."));
            var farOk = IsFinite(camera.FarClip) && camera.FarClip > 0;
            if (!farOk)
                Add(new ValidationProblem("camera.farClip", ValidationProblem.Format(camera.FarClip),
                    IsFinite(camera.FarClip) ? "must be above 0." : "is not a finite number.", "Use a distance beyond the far side of the target, e.g. 100."));
            else if (nearOk && camera.NearClip >= camera.FarClip)
                Add(new ValidationProblem("camera.farClip", ValidationProblem.Format(camera.FarClip),
                    "is not beyond camera.nearClip (" + ValidationProblem.Format(camera.NearClip) + ").", "Make the far clip larger than the near clip."));

            if (settings.AutoDistance)
                Add(ValidationProblem.OutsideRange("autoDistanceMargin", settings.AutoDistanceMargin, AutoDistanceRule.MinMargin, AutoDistanceRule.MaxMargin));
            else if (!IsFinite(settings.Distance) || !(settings.Distance > 0))
                Add(new ValidationProblem("distance", ValidationProblem.Format(settings.Distance),
                    IsFinite(settings.Distance) ? "must be above 0." : "is not a finite number.",
                    "Use the distance from the target to the cameras in Unity units (nerf_synthetic: 4), or \"auto\"."));
            else if (nearOk && settings.Distance <= camera.NearClip)
                Add(new ValidationProblem("distance", ValidationProblem.Format(settings.Distance),
                    "is not beyond camera.nearClip (" + ValidationProblem.Format(camera.NearClip) + "), so the target's centre would be clipped away.",
                    "Increase the distance or lower the near clip."));
            else if (farOk && settings.Distance >= camera.FarClip)
                Add(new ValidationProblem("distance", ValidationProblem.Format(settings.Distance),
                    "is not inside camera.farClip (" + ValidationProblem.Format(camera.FarClip) + "), so the target would be clipped away.",
                    "Decrease the distance or raise the far clip."));

            Add(ValidationProblem.OutsideRange("width", settings.Width, DatasetSettings.MinSize, DatasetSettings.MaxSize));
            Add(ValidationProblem.OutsideRange("height", settings.Height, DatasetSettings.MinSize, DatasetSettings.MaxSize));
            var supersampling = ValidationProblem.OutsideRange("supersampling", settings.Supersampling, DatasetSettings.MinSupersampling, DatasetSettings.MaxSupersampling);
            Add(supersampling);
            var rendered = Math.Max(settings.Width, settings.Height) * (long)settings.Supersampling;
            if (supersampling == null && rendered > DatasetSettings.MaxRenderSize && settings.Width <= DatasetSettings.MaxSize && settings.Height <= DatasetSettings.MaxSize)
                Add(new ValidationProblem("supersampling", settings.Supersampling.ToString(System.Globalization.CultureInfo.InvariantCulture),
                    "renders " + rendered + " pixels across, beyond the " + DatasetSettings.MaxRenderSize + " a render texture can have on common GPUs.",
                    "Lower the supersampling or the size so that size × supersampling ≤ " + DatasetSettings.MaxRenderSize + "."));

            var background = settings.Background ?? new BackgroundSettings();
            if (!background.Transparent && !background.Sky)
            {
                Add(ValidationProblem.OutsideRange("background.r", background.R, 0, 1));
                Add(ValidationProblem.OutsideRange("background.g", background.G, 0, 1));
                Add(ValidationProblem.OutsideRange("background.b", background.B, 0, 1));
            }

            if (!NormalisationModes.IsDefined(settings.Normalisation))
                Add(new ValidationProblem("normalisation", ((int)settings.Normalisation).ToString(System.Globalization.CultureInfo.InvariantCulture),
                    "is not a normalisation mode.", "Use one of " + NormalisationModes.NameList() + "."));
            var radius = ValidationProblem.OutsideRange("normalisedTargetRadius", settings.NormalisedTargetRadius,
                DatasetSettings.MinNormalisedTargetRadius, DatasetSettings.MaxNormalisedTargetRadius, "output units");
            if (radius != null)
                Add(new ValidationProblem(radius.Field, radius.Value, radius.Reason,
                    radius.Fix + " 1.3 or less keeps the target inside every loader's box (3DGS ±1.3, nerfstudio ±1.5)."));
            Add(ValidationProblem.OutsideRange("pointCloudPoints", settings.PointCloudPoints, 0, DatasetSettings.MaxPointCloudPoints));
            if (double.IsNaN(settings.PointCloudRadius) || double.IsInfinity(settings.PointCloudRadius) || settings.PointCloudRadius < 0)
                Add(new ValidationProblem("pointCloudRadius", ValidationProblem.Format(settings.PointCloudRadius),
                    "must be 0 (pick it from the volume boxes) or a distance above 0 in Unity units.",
                    "Use 0, or the distance from the capture volume's centre within which points3d.ply samples the scene."));

            foreach (var split in DatasetSplits.All)
                ValidateSplit(settings, split, problems);
            var protocol = EvalProtocol.Problem(settings.Background, settings.EvaluationBackground);
            if (protocol != null) problems.Add(protocol);
            problems.AddRange(TimeSettingsValidator.Validate(settings));
            problems.AddRange(LabelSettingsValidator.Validate(settings));
            problems.AddRange(LensSettingsValidator.Validate(settings));
            problems.AddRange(ExposureSettingsValidator.Validate(settings));
            problems.AddRange(HdrSettingsValidator.Validate(settings));
            problems.AddRange(MaterialPassSettingsValidator.Validate(settings));
            problems.AddRange(RelightingSettingsValidator.Validate(settings));
            problems.AddRange(MotionBlurSettingsValidator.Validate(settings));
            problems.AddRange(SparseViewsSettings.Validate(settings));
            problems.AddRange(FlowSettingsValidator.Validate(settings));

            if (settings.Loaders == TargetLoaders.None)
                Add(new ValidationProblem("loaders", "[]", "is empty, so nothing checks that the splits suit any loader.",
                    "List the loaders you will use, from " + TargetLoaderNames.NameList() + "."));
            return problems;
        }

        /// <summary>
        /// Every problem of <see cref="Validate(DatasetSettings)"/>, plus the output folder's: inside Assets,
        /// inside another dataset, not writable, or an existing dataset that the overwrite policy protects.
        /// </summary>
        public static IReadOnlyList<ValidationProblem> Validate(DatasetSettings settings, string projectRoot)
        {
            var problems = new List<ValidationProblem>(Validate(settings));
            if (DatasetNameRules.Check("name", settings.Name) == null)
                problems.AddRange(SafeOutput.CheckOutputFolder(SafeOutput.ResolveOutputFolder(settings, projectRoot), projectRoot, settings.Overwrite));
            return problems;
        }

        static void ValidateSplit(DatasetSettings settings, DatasetSplit split, List<ValidationProblem> problems)
        {
            var name = DatasetSplits.Name(split);
            var prefix = "splits." + name;
            var s = settings.Split(split);
            if (s == null)
            {
                problems.Add(new ValidationProblem(prefix, "null", "is missing.", "Give every split a count and a formation."));
                return;
            }
            if (s.Source != null && !s.Source.IsFormation)
            {
                problems.AddRange(s.Source.Validate(prefix + ".source")); // the source sets the count; no formation is used
                return;
            }
            var count = ValidationProblem.OutsideRange(prefix + ".count", s.Count, 0, DatasetSettings.MaxViews);
            if (count != null) problems.Add(count);
            if (s.Formation == null)
                problems.Add(new ValidationProblem(prefix + ".formation", "null", "is missing.", "Choose one of " + FormationKinds.NameList() + "."));
            else
                problems.AddRange(s.Formation.ToFormation(settings.Seed, name).Validate(prefix + ".formation"));

            if (s.Count == 0)
            {
                var needing = new List<string>();
                foreach (TargetLoaders loader in new[] { TargetLoaders.Nerf, TargetLoaders.InstantNgp, TargetLoaders.Nerfstudio, TargetLoaders.GaussianSplatting })
                    if ((settings.Loaders & loader) != 0 && new List<DatasetSplit>(TargetLoaderNames.RequiredSplits(loader)).Contains(split))
                        needing.Add(TargetLoaderNames.DisplayName(loader));
                if (needing.Count > 0)
                    problems.Add(new ValidationProblem(prefix + ".count", "0",
                        "leaves the " + name + " split empty, but " + string.Join(", ", needing) + (needing.Count == 1 ? " needs" : " need") + " it.",
                        "Give the split at least one view, or remove " + string.Join(", ", needing) + " from loaders."));
            }
        }

        static bool IsFinite(double v) => !double.IsNaN(v) && !double.IsInfinity(v);
    }
}
