using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes the geometry pack into a capture's working folder and returns its dataset_config.json record: the target's
    /// mesh at the start (a static capture's only pose; a dynamic capture's step 0), or, for a dynamic capture with
    /// <c>"geometryPack": "everyStep"</c>, one mesh per time step (<see cref="GeometryPackSteps"/>). Meshes come in the
    /// Unity world and are moved to the output frame with the plan's normalisation (<see cref="TargetMeshPly.FromUnityWorld"/>).
    /// </summary>
    public static class GeometryPackWriter
    {
        /// <summary>Whether the plan asks for a mesh per time step (a dynamic capture with <c>"geometryPack": "everyStep"</c>).</summary>
        public static bool WritesEveryStep(CapturePlan plan) =>
            plan != null && plan.Settings.GeometryPack && plan.Settings.GeometryPackEveryStep && plan.Time != null;

        /// <param name="startMeshes">The target at the start time (Unity world); used unless every step is written.</param>
        /// <param name="meshesAtStep">The target posed at step k (Unity world), called once per step in order, so only one
        /// step's meshes are held at a time; null when the caller cannot pose the target (then only the start is written).</param>
        /// <returns>The record, or null when nothing was written (no triangles at any step).</returns>
        public static JObject Write(DatasetWriteSession session, CapturePlan plan, IReadOnlyList<SurfaceMesh> startMeshes,
            Func<int, IReadOnlyList<SurfaceMesh>> meshesAtStep)
        {
            if (WritesEveryStep(plan) && meshesAtStep != null)
            {
                var steps = new List<JObject>();
                for (var k = 0; k < plan.Time.Steps; k++)
                {
                    // A step where nothing is drawn (an object that appears later) still gets its file: an empty PLY
                    // says "no surface at this time" where a gap would say "not written".
                    var meshes = (meshesAtStep(k) ?? Array.Empty<SurfaceMesh>()).Where(m => m.TriangleCount > 0).ToList();
                    var output = TargetMeshPly.FromUnityWorld(meshes, plan.Normalisation);
                    var path = session.PathOf(GeometryPackSteps.RelativePath(k));
                    FileOps.CreateDirectory(System.IO.Path.GetDirectoryName(path));
                    TargetMeshPly.Write(path, output);
                    steps.Add(GeometryPackStepRecord.StepJson(plan.Time.AtStep(k, -1), output, PointCloudRecord.HashOf(path)));
                }
                return steps.Any(s => (long)s["triangles"] > 0) ? GeometryPackStepRecord.ToJson(steps) : Discard(session, plan.Time.Steps);
            }
            var start = startMeshes?.Where(m => m.TriangleCount > 0).ToList();
            if (start == null || start.Count == 0) return null;
            var outputMeshes = TargetMeshPly.FromUnityWorld(start, plan.Normalisation);
            var single = session.PathOf(TargetMeshPly.RelativePath);
            FileOps.CreateDirectory(System.IO.Path.GetDirectoryName(single));
            TargetMeshPly.Write(single, outputMeshes);
            var hash = PointCloudRecord.HashOf(single);
            return plan.Time != null ? GeometryPackRecord.ToJson(outputMeshes, hash, plan.Time.AtStep(0, -1)) : GeometryPackRecord.ToJson(outputMeshes, hash);
        }

        /// <summary>No step had a triangle: the empty files go again, as a target without meshes has no pack.</summary>
        static JObject Discard(DatasetWriteSession session, int steps)
        {
            for (var k = 0; k < steps; k++) FileOps.DeleteFile(session.PathOf(GeometryPackSteps.RelativePath(k)));
            var folder = session.PathOf(TargetMeshPly.Folder);
            if (!System.IO.Directory.EnumerateFileSystemEntries(folder).Any()) FileOps.DeleteDirectory(folder);
            return null;
        }
    }
}
