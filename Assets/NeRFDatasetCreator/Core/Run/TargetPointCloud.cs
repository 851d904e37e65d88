using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>points3d.ply</c> for a capture: <see cref="DatasetSettings.PointCloudPoints"/> points sampled area-uniformly on
    /// the target's mesh surfaces (Unity world, collected by the editor) with the seed
    /// <c>SeededRandom.Derive(seed, "points3d")</c>, moved into the output world by the plan's normalisation, so the
    /// cloud lines up with the poses. 3DGS starts from it instead of random points in ±1.3.
    /// </summary>
    public static class TargetPointCloud
    {
        public const string FileName = BlenderDatasetLoader.PointCloudFileName;
        public const string SeedLabel = "points3d";

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

        /// <summary>The cloud in the output world (empty when the settings ask for none).</summary>
        public static IReadOnlyList<CloudPoint> Sample(CapturePlan plan, IReadOnlyList<SurfaceMesh> unityWorldMeshes)
        {
            var count = plan.Settings.PointCloudPoints;
            if (count <= 0) return new CloudPoint[0];
            var points = SurfaceSampler.Sample(unityWorldMeshes, count, SeededRandom.Derive(plan.Settings.Seed, SeedLabel));
            var normalisation = plan.Normalisation;
            var moved = new CloudPoint[points.Count];
            for (var i = 0; i < moved.Length; i++) moved[i] = points[i].FromUnityWorld(normalisation);
            return moved;
        }
    }
}
