using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The plan-time warnings of reference §2.4 for the loaders the settings list: <see cref="LoaderRangeCheck"/>'s
    /// near/far checks only matter to NeRF (bmild/nerf, nerf-pytorch); its initial-cloud check matters to 3DGS when no
    /// points3d.ply is written, and to nerfstudio when the target leaves its ±1.5 box; instant-ngp warns when no
    /// aabb_scale holds the target; nerfstudio when the splits differ in depth or masks (<see cref="SplitExtrasCheck"/>);
    /// D-NeRF and 4DGaussians (a dynamic capture's nerf and 3dgs) where their code cannot take the capture (<see cref="DynamicLoaderLimits"/>).
    /// With unknown bounds the target counts as a point at its centre.
    /// </summary>
    static class PlanWarnings
    {
        /// <summary>nerfstudio blender-data's scene box is ±1.5.</summary>
        public const double NerfstudioBoxHalfSize = 1.5;

        public static IReadOnlyList<ValidationProblem> For(DatasetSettings settings, PlanTarget target, SceneNormalisation normalisation,
            IEnumerable<UnityPose> poses)
        {
            var loaders = settings.Loaders;
            var reach = TargetReach(target, normalisation);
            var warnings = new List<ValidationProblem>();
            // Inside-out views: near/far from the target mean nothing; one plain warning replaces them.
            var volume = VolumePlanning.InsideOutWarning(settings);
            if (volume != null && (loaders & TargetLoaders.Nerf) != 0) warnings.Add(volume);
            foreach (var (range, problem) in LoaderRangeCheck.ClassifiedForCapture(poses, normalisation, target.Centre, Radius(target),
                         NormalisationModes.Name(settings.Normalisation)))
            {
                var isRange = range != LoaderRangeCheck.Range.InitialCloud;
                if (isRange && volume != null) continue;
                var keep = isRange
                    ? (loaders & TargetLoaders.Nerf) != 0
                    : ((loaders & TargetLoaders.GaussianSplatting) != 0 && settings.PointCloudPoints == 0)
                      || ((loaders & TargetLoaders.Nerfstudio) != 0 && reach > NerfstudioBoxHalfSize);
                if (keep) warnings.Add(problem);
            }
            if ((loaders & TargetLoaders.InstantNgp) != 0) AabbScale.ForRadius(reach, warnings);
            if ((loaders & TargetLoaders.Nerfstudio) != 0) warnings.AddRange(SplitExtrasCheck.For(settings));
            warnings.AddRange(DynamicLoaderLimits.For(settings));
            warnings.AddRange(LensSettingsValidator.Warnings(settings));
            return warnings;
        }

        public static double TargetReach(PlanTarget target, SceneNormalisation normalisation) =>
            normalisation.ApplyToUnityPoint(target.Centre).Length + Radius(target) * normalisation.Scale;

        static double Radius(PlanTarget target) => target.HasBounds ? target.BoundingRadius : 0;
    }
}
