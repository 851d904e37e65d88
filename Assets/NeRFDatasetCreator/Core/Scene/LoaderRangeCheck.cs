using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Warnings (not errors: the data is still valid) when a normalised scene violates a loader's fixed
    /// assumption (reference §2.4): NeRF's Blender loaders sample only between near 2 and far 6 from each camera;
    /// 3DGS without a point cloud initialises inside [−1.3, 1.3]³; nerfstudio's blender-data box is ±1.5.
    /// The target is a sphere of radius <c>targetRadius</c> (output units) around <c>targetCentre</c> (default the
    /// origin, where normalisation puts it): near/far are measured from each camera to the sphere, the init-cube test
    /// uses the sphere's reach from the origin, |centre| + radius.
    /// </summary>
    public static class LoaderRangeCheck
    {
        public const string Field = "normalisation";

        public static IReadOnlyList<ValidationProblem> Check(IEnumerable<Vector3d> cameraCentres, double targetRadius, Vector3d? targetCentre = null)
        {
            var centre = targetCentre ?? Vector3d.Zero;
            var problems = new List<ValidationProblem>();
            var b = Math.Max(0, targetRadius);
            // One pass without lists: a plan checks up to 300 000 cameras here.
            int count = 0, nearCount = 0, farCount = 0;
            double sum = 0, nearest = double.PositiveInfinity, farthest = double.NegativeInfinity;
            foreach (var c in cameraCentres)
            {
                var d = Vector3d.Distance(c, centre);
                count++;
                sum += d;
                if (d - b < SceneNormalisation.NerfNear)
                {
                    nearCount++;
                    nearest = Math.Min(nearest, d);
                }
                if (d + b > SceneNormalisation.NerfFar)
                {
                    farCount++;
                    farthest = Math.Max(farthest, d);
                }
            }
            if (count == 0) return problems;
            var suggestion = SuggestedScaleText(sum / count, b);

            if (nearCount > 0)
                problems.Add(new ValidationProblem(Field + ".near", F(nearest - b),
                    $"{nearCount} of {count} cameras are closer to the target's surface than NeRF's fixed near distance {F(SceneNormalisation.NerfNear)} (closest: {F(nearest - b)} output units); bmild/nerf and nerf-pytorch will not see that part.",
                    suggestion));

            if (farCount > 0)
                problems.Add(new ValidationProblem(Field + ".far", F(farthest + b),
                    $"{farCount} of {count} cameras see target surface beyond NeRF's fixed far distance {F(SceneNormalisation.NerfFar)} (farthest: {F(farthest + b)} output units); bmild/nerf and nerf-pytorch will cut it off.",
                    suggestion));

            var reach = centre.Length + b;
            if (reach > SceneNormalisation.GaussianSplattingInitHalfSize)
                problems.Add(new ValidationProblem(Field + ".targetRadius", F(reach),
                    $"the target reaches beyond 3DGS's random initial cloud [−1.3, 1.3]³ (and, above 1.5, nerfstudio blender-data's ±1.5 box).",
                    "Recentre on the target and export points3d.ply (3DGS then starts from it), or scale the target to radius 1.3 (FitTargetRadius)."));
            return problems;
        }

        /// <summary>
        /// The check for a planned capture: Unity camera poses and the target's bounding sphere (Unity units) as
        /// they will be after <paramref name="normalisation"/>.
        /// </summary>
        public static IReadOnlyList<ValidationProblem> ForCapture(IEnumerable<UnityPose> poses, SceneNormalisation normalisation,
            Vector3d targetCentreUnity, double targetRadiusUnity) =>
            Check(poses.Select(p => normalisation.ApplyToUnityPoint(p.Position)), targetRadiusUnity * normalisation.Scale,
                normalisation.ApplyToUnityPoint(targetCentreUnity));

        static string SuggestedScaleText(double meanDistance, double b)
        {
            if (!(meanDistance > 0)) return "Move the cameras away from the target.";
            var s = SceneNormalisation.NerfSyntheticCameraRadius / meanDistance;
            var fits = b <= SceneNormalisation.PresetMaxTargetRadiusFraction * meanDistance;
            return fits
                ? $"Use the nerf_synthetic scale preset (cameras at radius 4: scale × {F(s)})."
                : $"Use the nerf_synthetic scale preset (scale × {F(s)}) and move the cameras out to at least {F(b / SceneNormalisation.PresetMaxTargetRadiusFraction)} (≈3.1× the target radius), or accept that bmild/nerf will not fit this scene.";
        }

        static string F(double v) => v.ToString("0.###", CultureInfo.InvariantCulture);
    }
}
