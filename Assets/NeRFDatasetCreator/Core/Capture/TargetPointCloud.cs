using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>points3d.ply</c> for a capture: <see cref="DatasetSettings.PointCloudPoints"/> points sampled area-uniformly on
    /// the target's mesh surfaces (Unity world, collected by the editor) with the seed
    /// <c>SeededRandom.Derive(seed, "points3d")</c>, moved into the output world by the plan's normalisation, so the
    /// cloud lines up with the poses. 3DGS starts from it instead of random points in ±1.3. An environment capture
    /// (a split samples an inside-out volume) samples only the surface within <see cref="Region"/>'s sphere
    /// (<see cref="SphereSurfaceSampler"/>), so a large scene's far geometry does not take the points from where the
    /// cameras are.
    /// </summary>
    public static class TargetPointCloud
    {
        public const string FileName = BlenderDatasetLoader.PointCloudFileName;
        public const string SeedLabel = "points3d";

        /// <summary>
        /// The default radius of an environment's cloud in half-diagonals of the volume boxes: the cameras stand inside
        /// the boxes (one half-diagonal), and 4 also covers the near surroundings they see in detail, while a
        /// landscape's far geometry does not take the points from where the cameras are. A default, not a law:
        /// <see cref="DatasetSettings.PointCloudRadius"/> sets it.
        /// </summary>
        public const double DefaultRadiusFactor = 4;

        /// <summary>
        /// An environment capture's sphere in the Unity world: centred on the box around every volume split's box
        /// corners, radius <see cref="DatasetSettings.PointCloudRadius"/> or, when 0, <see cref="DefaultRadiusFactor"/> ×
        /// that box's half-diagonal; null when no split samples a volume.
        /// </summary>
        public static CloudRegion Region(CapturePlan plan)
        {
            var corners = new List<Vector3d>();
            foreach (var split in DatasetSplits.All)
            {
                var source = plan.Settings.Split(split)?.Source;
                if (source == null || !source.IsVolume || source.Volume == null) continue;
                for (var i = 0; i < 8; i++)
                    corners.Add(source.Volume.Box.PointAt(new Vector3d((i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5)));
            }
            if (corners.Count == 0) return null;
            var min = new Vector3d(corners.Min(c => c.X), corners.Min(c => c.Y), corners.Min(c => c.Z));
            var max = new Vector3d(corners.Max(c => c.X), corners.Max(c => c.Y), corners.Max(c => c.Z));
            var halfDiagonal = (max - min).Length / 2;
            var radius = plan.Settings.PointCloudRadius > 0 ? plan.Settings.PointCloudRadius : DefaultRadiusFactor * halfDiagonal;
            return new CloudRegion(0.5 * (min + max), radius, plan.Settings.PointCloudRadius <= 0);
        }

        /// <summary>Why <paramref name="unityWorldMeshes"/> cannot give the settings' point cloud; empty when they can (or none is asked for).</summary>
        public static IReadOnlyList<ValidationProblem> Check(DatasetSettings settings, IReadOnlyList<SurfaceMesh> unityWorldMeshes)
        {
            var problems = new List<ValidationProblem>();
            if (settings.PointCloudPoints <= 0) return problems;
            var hasArea = unityWorldMeshes != null && unityWorldMeshes.Any(m => Enumerable.Range(0, m.TriangleCount).Any(t => m.TriangleArea(t) > 0));
            if (!hasArea)
                problems.Add(new ValidationProblem("pointCloudPoints", settings.PointCloudPoints.ToString(System.Globalization.CultureInfo.InvariantCulture),
                    "asks for a point cloud, but the target has no readable mesh surface to sample" +
                    (unityWorldMeshes == null || unityWorldMeshes.Count == 0 ? "." : " (every triangle has zero area)."),
                    "Pick a target with MeshRenderer/MeshFilter or SkinnedMeshRenderer children, or set pointCloudPoints to 0."));
            return problems;
        }

        /// <summary>
        /// What <see cref="Check"/> says, and for an environment capture whether any surface comes within its sphere
        /// (the problem names pointCloudRadius and the sphere).
        /// </summary>
        public static IReadOnlyList<ValidationProblem> Check(CapturePlan plan, IReadOnlyList<SurfaceMesh> unityWorldMeshes)
        {
            var problems = new List<ValidationProblem>(Check(plan.Settings, unityWorldMeshes));
            var region = Region(plan);
            if (problems.Count > 0 || region == null || plan.Settings.PointCloudPoints <= 0) return problems;
            if (SphereSurfaceSampler.Pieces(unityWorldMeshes, region.Centre, region.Radius).Count == 0)
                problems.Add(new ValidationProblem("pointCloudRadius", ValidationProblem.Format(plan.Settings.PointCloudRadius),
                    "leaves no scene surface for points3d.ply: no mesh comes within " + ValidationProblem.Format(region.Radius) +
                    " units of the capture volumes' centre " + region.Centre + (region.Automatic ? " (" + DefaultRadiusFactor + " × the boxes' half-diagonal)." : "."),
                    "Raise pointCloudRadius, or set pointCloudPoints to 0."));
            return problems;
        }

        /// <summary>The cloud in the output world (empty when the settings ask for none).</summary>
        public static IReadOnlyList<CloudPoint> Sample(CapturePlan plan, IReadOnlyList<SurfaceMesh> unityWorldMeshes)
        {
            var count = plan.Settings.PointCloudPoints;
            if (count <= 0) return new CloudPoint[0];
            var seed = SeededRandom.Derive(plan.Settings.Seed, SeedLabel);
            var region = Region(plan);
            var points = region == null
                ? SurfaceSampler.Sample(unityWorldMeshes, count, seed)
                : SphereSurfaceSampler.Sample(unityWorldMeshes, count, seed, region.Centre, region.Radius).Points;
            var normalisation = plan.Normalisation;
            var moved = new CloudPoint[points.Count];
            for (var i = 0; i < moved.Length; i++) moved[i] = points[i].FromUnityWorld(normalisation);
            return moved;
        }
    }

    /// <summary>The sphere (Unity world) an environment's point cloud is sampled in.</summary>
    public sealed class CloudRegion
    {
        public CloudRegion(Vector3d centre, double radius, bool automatic)
        {
            Centre = centre;
            Radius = radius;
            Automatic = automatic;
        }

        public Vector3d Centre { get; }
        public double Radius { get; }

        /// <summary>Whether the radius came from the boxes (pointCloudRadius 0).</summary>
        public bool Automatic { get; }
    }
}
