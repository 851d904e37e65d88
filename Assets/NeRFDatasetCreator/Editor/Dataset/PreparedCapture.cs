using System.Collections.Generic;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>A checked capture, ready to run: <see cref="DatasetCapture.Prepare"/> makes it; read <see cref="Problems"/> first.</summary>
    public sealed class PreparedCapture
    {
        internal PreparedCapture(DatasetRun run, GameObject target, CaptureOptions options,
            IReadOnlyList<ValidationProblem> problems, IReadOnlyList<ValidationProblem> warnings)
        {
            Run = run;
            Target = target;
            Options = options;
            Problems = problems;
            Warnings = warnings;
        }

        internal DatasetRun Run { get; }
        internal GameObject Target { get; }
        internal CaptureOptions Options { get; }

        /// <summary>What <see cref="DatasetCapture.Prepare"/> was given (a copy): the preflight prepares its calibration from them.</summary>
        internal DatasetSettings Settings { get; set; }
        internal string ProjectRoot { get; set; }

        /// <summary>
        /// The target's mesh surfaces (Unity world) for points3d.ply, read when the run starts; null when this run writes
        /// none or has not started.
        /// </summary>
        internal IReadOnlyList<SurfaceMesh> Surface { get; set; }

        /// <summary>
        /// <c>"geometryPack": "everyStep"</c>: the copy of the target made when the run starts, posed at each step when the
        /// dataset is finished (review R4-6); null otherwise. Disposed when the run ends.
        /// </summary>
        internal TargetSurfaceOverTime GeometrySteps { get; set; }

        /// <summary>The target's scene path, GlobalObjectId, local-to-world and the colour space when the run starts, for
        /// <c>unity_frame</c> (<see cref="UnityFrameCapture"/>); null before.</summary>
        internal UnityFrameFacts UnityFrame { get; set; }

        /// <summary>The capture's label table (labels.json), made when the run starts (<see cref="SceneLabels"/>); null without labels.</summary>
        internal LabelTable Labels { get; set; }

        /// <summary>Every reason the capture cannot start; empty when <see cref="IsValid"/>.</summary>
        public IReadOnlyList<ValidationProblem> Problems { get; }

        /// <summary>
        /// What works but will not suit a chosen loader (the plan's <see cref="CapturePlan.Warnings"/>: NeRF's near/far,
        /// 3DGS's and nerfstudio's boxes, instant-ngp's cube) and meshes the point cloud leaves out. Never stops a capture.
        /// </summary>
        public IReadOnlyList<ValidationProblem> Warnings { get; }

        public bool IsValid => Problems.Count == 0;

        /// <summary>The views this capture renders (a shard's share of the dataset); null when not valid.</summary>
        public CapturePlan Plan => IsValid ? Run.Plan : null;

        /// <summary>The absolute folder the finished dataset is moved to.</summary>
        public string DatasetFolder => Run?.DatasetFolder;

        public int ViewCount => IsValid ? Run.Plan.Views.Count : 0;
    }
}
