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
        /// <summary>
        /// The key a plan's warnings name: the setting that fixes them. (They used to name "normalisation.near",
        /// ".far" and ".targetRadius", keys no config has.)
        /// </summary>
        public const string Field = "normalisation";

        /// <summary>What a dataset's warnings name when no settings are known (validate, convert): the poses themselves.</summary>
        public const string DatasetField = "transform_matrix";

        /// <summary>Which of the loaders' ranges a warning is about.</summary>
        public enum Range
        {
            /// <summary>NeRF's near 2 (bmild/nerf, nerf-pytorch).</summary>
            Near,
            /// <summary>NeRF's far 6.</summary>
            Far,
            /// <summary>3DGS's random initial cloud in ±1.3 (and nerfstudio's ±1.5 box).</summary>
            InitialCloud,
        }

        /// <summary>
        /// The warnings for a dataset's cameras, named <see cref="DatasetField"/> with the measured distance as the value.
        /// </summary>
        public static IReadOnlyList<ValidationProblem> Check(IEnumerable<Vector3d> cameraCentres, double targetRadius, Vector3d? targetCentre = null) =>
            Classified(cameraCentres, targetRadius, targetCentre, null).Select(r => r.Problem).ToList();

        /// <summary>
        /// Each warning with its <see cref="Range"/>. With <paramref name="normalisationMode"/> (a plan's), they name the
        /// <c>normalisation</c> setting and its value, which is what fixes them; without, the dataset's poses.
        /// </summary>
        public static List<(Range Range, ValidationProblem Problem)> Classified(IEnumerable<Vector3d> cameraCentres, double targetRadius,
            Vector3d? targetCentre, string normalisationMode)
        {
            // One pass without lists: a plan checks up to 300 000 cameras here.
            var tally = new Tally(targetRadius, targetCentre);
            foreach (var c in cameraCentres) tally.Add(c);
            return tally.Classified(normalisationMode);
        }

        /// <summary>
        /// The figures the checks need of a stream of camera centres, gathered one centre at a time (validate reads the
        /// transforms files frame by frame and keeps no centres). A value: a copy is a checkpoint to go back to.
        /// </summary>
        public struct Tally
        {
            readonly Vector3d _centre;
            readonly double _b;
            int _count, _nearCount, _farCount;
            double _sum, _nearest, _farthest;

            public Tally(double targetRadius, Vector3d? targetCentre = null)
            {
                _centre = targetCentre ?? Vector3d.Zero;
                _b = Math.Max(0, targetRadius);
                _count = _nearCount = _farCount = 0;
                _sum = 0;
                _nearest = double.PositiveInfinity;
                _farthest = double.NegativeInfinity;
            }

            public void Add(Vector3d c)
            {
                var d = Vector3d.Distance(c, _centre);
                _count++;
                _sum += d;
                if (d - _b < SceneNormalisation.NerfNear)
                {
                    _nearCount++;
                    _nearest = Math.Min(_nearest, d);
                }
                if (d + _b > SceneNormalisation.NerfFar)
                {
                    _farCount++;
                    _farthest = Math.Max(_farthest, d);
                }
            }

            /// <summary>The warnings of <see cref="Check"/> for the centres added.</summary>
            public IReadOnlyList<ValidationProblem> Check() => Classified(null).Select(r => r.Problem).ToList();

            /// <summary>The warnings with their <see cref="Range"/>s (<see cref="LoaderRangeCheck.Classified"/>).</summary>
            public List<(Range Range, ValidationProblem Problem)> Classified(string normalisationMode) =>
                LoaderRangeCheck.Classified(_count, _nearCount, _farCount, _sum, _nearest, _farthest, _centre, _b, normalisationMode);
        }

        static List<(Range Range, ValidationProblem Problem)> Classified(int count, int nearCount, int farCount, double sum, double nearest, double farthest,
            Vector3d centre, double b, string normalisationMode)
        {
            var problems = new List<(Range, ValidationProblem)>();
            var field = normalisationMode == null ? DatasetField : Field;
            string Shown(double measured) => normalisationMode == null ? F(measured) : "\"" + normalisationMode + "\"";
            if (count == 0) return problems;
            var suggestion = SuggestedScaleText(sum / count, b);

            if (nearCount > 0)
                problems.Add((Range.Near, new ValidationProblem(field, Shown(nearest - b),
                    $"{nearCount} of {count} cameras are closer to the target's surface than NeRF's fixed near distance {F(SceneNormalisation.NerfNear)} (closest: {F(nearest - b)} output units); bmild/nerf and nerf-pytorch will not see that part.",
                    suggestion)));

            if (farCount > 0)
                problems.Add((Range.Far, new ValidationProblem(field, Shown(farthest + b),
                    $"{farCount} of {count} cameras see target surface beyond NeRF's fixed far distance {F(SceneNormalisation.NerfFar)} (farthest: {F(farthest + b)} output units); bmild/nerf and nerf-pytorch will cut it off.",
                    suggestion)));

            var reach = centre.Length + b;
            if (reach > SceneNormalisation.GaussianSplattingInitHalfSize)
                problems.Add((Range.InitialCloud, new ValidationProblem(field, Shown(reach),
                    $"the target reaches beyond 3DGS's random initial cloud [−1.3, 1.3]³ (and, above 1.5, nerfstudio blender-data's ±1.5 box).",
                    "Recentre on the target and export points3d.ply (pointCloudPoints; 3DGS then starts from it), or scale the target to radius 1.3 (normalisation \"fit-radius\" with normalisedTargetRadius 1.3).")));
            return problems;
        }

        /// <summary>
        /// The check for a planned capture: Unity camera poses and the target's bounding sphere (Unity units) as
        /// they will be after <paramref name="normalisation"/>.
        /// </summary>
        public static IReadOnlyList<ValidationProblem> ForCapture(IEnumerable<UnityPose> poses, SceneNormalisation normalisation,
            Vector3d targetCentreUnity, double targetRadiusUnity, string normalisationMode = null) =>
            ClassifiedForCapture(poses, normalisation, targetCentreUnity, targetRadiusUnity, normalisationMode).Select(r => r.Problem).ToList();

        /// <summary><see cref="ForCapture"/> with each warning's <see cref="Range"/>.</summary>
        public static List<(Range Range, ValidationProblem Problem)> ClassifiedForCapture(IEnumerable<UnityPose> poses, SceneNormalisation normalisation,
            Vector3d targetCentreUnity, double targetRadiusUnity, string normalisationMode) =>
            Classified(poses.Select(p => normalisation.ApplyToUnityPoint(p.Position)), targetRadiusUnity * normalisation.Scale,
                normalisation.ApplyToUnityPoint(targetCentreUnity), normalisationMode);

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
