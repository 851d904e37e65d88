using System;

namespace NerfDatasetCreator
{
    /// <summary>What <c>nerf-dataset evaluate</c> (and the Editor's "Evaluate renders…") asks for.</summary>
    public sealed class EvaluationOptions
    {
        public string DatasetFolder;
        public string RendersFolder;

        /// <summary><c>--inverse</c>: a relightable model's albedo/, normal/, roughness/, relit/&lt;key&gt;/ outputs (<see cref="InverseRenderingEvaluator"/>); null: none.</summary>
        public string InverseFolder;
        /// <summary><c>--flow</c>: a model's rendered flow and tracks (<see cref="FlowPredictions"/>), scored on their own by <see cref="FlowEvaluation"/>; null: images.</summary>
        public string FlowFolder;
        /// <summary>Null: the protocol's evaluation split (eval_protocol.json), else test.</summary>
        public string Split;

        /// <summary><c>--split sparse_&lt;n&gt;</c>: a split file's name (<see cref="SplitFileSelection"/>); <see cref="Split"/> is then test. Null: none.</summary>
        public string SplitFile;

        /// <summary>Null: <c>&lt;renders&gt;/evaluation-&lt;split&gt;</c>.</summary>
        public string OutFolder;

        /// <summary>Null: detected.</summary>
        public RenderLayout? Layout;

        /// <summary>white, black or dataset; null: the protocol's (eval_protocol.json), else white.</summary>
        public string Background;

        /// <summary>
        /// <c>--override-protocol</c>: accept a <see cref="Background"/> that contradicts the dataset's protocol, and renders
        /// whose background is another colour (<see cref="RenderBackgroundCheck"/>), with a warning in place of the refusal.
        /// </summary>
        public bool OverrideProtocol;

        /// <summary><c>--trainer-metrics</c>: a 3DGS results.json or an ns-eval JSON to put beside the figures; null: found by layout (<see cref="TrainerResults"/>).</summary>
        public string TrainerMetricsPath;

        /// <summary>nerfstudio depth is the distance along each ray (nerfacto) rather than z-depth (splatfacto).</summary>
        public bool DepthAlongRay;

        public string GeometryPath;
        public string TruthMeshPath;
        public double? Threshold;

        /// <summary>A dynamic dataset's time step for <see cref="GeometryPath"/> (<c>--step</c>); see <see cref="GeometryTruth"/>.</summary>
        public int? Step;
        public int TruthPoints = GeometryEvaluation.DefaultTruthPoints;

        /// <summary>Longer side of the report's pictures, in pixels.</summary>
        public int ThumbnailSize = 240;

        public int Threads = Math.Max(1, Environment.ProcessorCount);

        /// <param name="split">The split evaluated (<see cref="Split"/> or the protocol's).</param>
        public string ResolvedOutFolder(string rendersRoot, string split) => OutFolder ?? System.IO.Path.Combine(rendersRoot, "evaluation-" + (SplitFile ?? split));
    }
}
