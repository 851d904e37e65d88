using System;
using System.Collections.Generic;
using System.Linq;
using System.Threading.Tasks;
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
        /// <param name="meshesAtStep">The target posed at step k (Unity world), called once per step in order on the calling
        /// thread (the Unity layer's main thread, where meshes can be read); null when the caller cannot pose the target
        /// (then only the start is written).</param>
        /// <param name="progress">Called on the calling thread with (steps done, steps) as every step's meshes have been read
        /// and once more when the last file is written; may be null.</param>
        /// <returns>The record, or null when nothing was written (no triangles at any step).</returns>
        /// <remarks>
        /// Every step: the calling thread reads step k while a worker moves step k − 1 to the output frame, writes its PLY
        /// and hashes it (review R4-6: the reading must stay on Unity's main thread, the packing and writing need not). At
        /// most one step is in flight, so at most two steps' meshes are held. A worker's exception is rethrown here as it was.
        /// </remarks>
        public static JObject Write(DatasetWriteSession session, CapturePlan plan, IReadOnlyList<SurfaceMesh> startMeshes,
            Func<int, IReadOnlyList<SurfaceMesh>> meshesAtStep, Action<int, int> progress = null)
        {
            if (WritesEveryStep(plan) && meshesAtStep != null)
            {
                var count = plan.Time.Steps;
                var steps = new JObject[count];
                Task pending = null;
                try
                {
                    for (var k = 0; k < count; k++)
                    {
                        // A step where nothing is drawn (an object that appears later) still gets its file: an empty PLY
                        // says "no surface at this time" where a gap would say "not written".
                        var meshes = (meshesAtStep(k) ?? Array.Empty<SurfaceMesh>()).Where(m => m.TriangleCount > 0).ToList();
                        pending?.GetAwaiter().GetResult();
                        var step = k;
                        pending = Task.Run(() => steps[step] = WriteStep(session, plan, step, meshes));
                        progress?.Invoke(k, count);
                    }
                }
                finally
                {
                    // Never leave a worker writing into the session after this returns or throws.
                    if (pending != null && !pending.IsCompleted) ((IAsyncResult)pending).AsyncWaitHandle.WaitOne();
                }
                pending?.GetAwaiter().GetResult();
                progress?.Invoke(count, count);
                return steps.Any(s => (long)s["triangles"] > 0) ? GeometryPackStepRecord.ToJson(steps.ToList()) : Discard(session, count);
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

        /// <summary>Step k's PLY in the output frame and its record (a worker thread: Core only).</summary>
        static JObject WriteStep(DatasetWriteSession session, CapturePlan plan, int k, List<SurfaceMesh> meshes)
        {
            var output = TargetMeshPly.FromUnityWorld(meshes, plan.Normalisation);
            var path = session.PathOf(GeometryPackSteps.RelativePath(k));
            FileOps.CreateDirectory(System.IO.Path.GetDirectoryName(path));
            TargetMeshPly.Write(path, output);
            return GeometryPackStepRecord.StepJson(plan.Time.AtStep(k, -1), output, PointCloudRecord.HashOf(path));
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
