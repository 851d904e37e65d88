using System;
using System.Collections.Generic;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The target's surface at each time step, for <c>"geometryPack": "everyStep"</c>: one temporary copy of the target
    /// (SceneCopy, scripts off, in a preview scene) posed by <see cref="ContentClock"/> at step k's content time
    /// (<c>TimeRange.SecondsOf(k)</c>, the time the capture poses the views of that step at) and read by
    /// <see cref="TargetSurface.Collect"/> — MeshFilter meshes by their world matrix, skinned meshes by
    /// <c>SkinnedMeshRenderer.BakeMesh(mesh, useScale: true)</c> in the pose the clock just set (UnityCsReference
    /// Runtime/Export/Graphics/GraphicsRenderers.bindings.cs; "Creates a snapshot of SkinnedMeshRenderer", Scripting API
    /// SkinnedMeshRenderer.BakeMesh — the snapshot is of the current pose, which ContentClock set). The clock evaluates
    /// every call from scratch, so the steps may be read in any order; the user's objects are only read.
    /// <para>
    /// A capture makes it when the run starts, beside the capture's own copy (review R4-6): the steps are then the target
    /// as captured, not as it stands after a background run during which it may have been edited. Reading stays on the
    /// main thread — <c>Mesh.vertices</c> and the other channel getters go through
    /// <c>GetAllocArrayFromChannelImpl</c>, a binding not marked thread-safe (UCR Runtime/Export/Graphics/Mesh.cs:143,
    /// Mesh.bindings.cs:125 on 2022.3.76f1 and 6000.0.78f1), as is <c>BakeMesh</c>
    /// (GraphicsRenderers.bindings.cs:244) — while Core's <see cref="GeometryPackWriter"/> packs and writes each step on a worker.
    /// </para>
    /// </summary>
    public sealed class TargetSurfaceOverTime : IDisposable
    {
        readonly SceneCopy _copy;
        readonly ContentClock _clock;
        readonly TimeRange _range;
        readonly List<ValidationProblem> _warnings;

        public TargetSurfaceOverTime(GameObject target, TimeRange range, long seed, List<ValidationProblem> warnings)
        {
            _range = range ?? throw new ArgumentNullException(nameof(range));
            _warnings = warnings ?? new List<ValidationProblem>();
            _copy = SceneCopy.OfObject(target, "geometry pack copy");
            _clock = new ContentClock(range.Sources, seed);
        }

        /// <summary>The target's meshes (Unity world) at step <paramref name="step"/>.</summary>
        public IReadOnlyList<SurfaceMesh> At(int step)
        {
            _clock.Show(_copy.Root, _range.SecondsOf(step));
            return TargetSurface.Collect(_copy.Root, _warnings);
        }

        /// <summary>What the readers found but left out (meshes that cannot be read), for the Console.</summary>
        public IReadOnlyList<ValidationProblem> Warnings => _warnings;

        public void Dispose() => _copy.Dispose();
    }
}
