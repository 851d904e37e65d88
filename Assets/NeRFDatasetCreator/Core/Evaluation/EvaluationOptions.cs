using System;

namespace NerfDatasetCreator
{
    /// <summary>What <c>nerf-dataset evaluate</c> (and the Editor's "Evaluate renders…") asks for.</summary>
    public sealed class EvaluationOptions
    {
        public string DatasetFolder;
        public string RendersFolder;
        public string Split = "test";

        /// <summary><c>--split sparse_&lt;n&gt;</c>: a split file's name (<see cref="SplitFileSelection"/>); <see cref="Split"/> is then test. Null: none.</summary>
        public string SplitFile;

        /// <summary>Null: <c>&lt;renders&gt;/evaluation-&lt;split&gt;</c>.</summary>
        public string OutFolder;

        /// <summary>Null: detected.</summary>
        public RenderLayout? Layout;

        public string Background = "white";

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

        public string ResolvedOutFolder(string rendersRoot) => OutFolder ?? System.IO.Path.Combine(rendersRoot, "evaluation-" + (SplitFile ?? Split));
    }
}
