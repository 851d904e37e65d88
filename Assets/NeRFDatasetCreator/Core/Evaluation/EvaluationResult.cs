using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>The figures of one view.</summary>
    public sealed class ViewResult
    {
        public int FrameIndex { get; internal set; }
        public string FilePath { get; internal set; }
        public string RenderPath { get; internal set; }
        public int Width { get; internal set; }
        public int Height { get; internal set; }
        public double Psnr { get; internal set; }
        public double Ssim { get; internal set; }

        /// <summary>NaN without masks.</summary>
        public double MaskedPsnr { get; internal set; } = double.NaN;

        public long MaskPixels { get; internal set; }
        public DepthErrors Depth { get; internal set; }
        public NormalErrors Normals { get; internal set; }

        /// <summary>Relative to the out folder.</summary>
        public string ErrorMapFile { get; internal set; }

        /// <summary>PNG bytes of the report's pictures: ground truth (composited), render, error.</summary>
        public byte[] TruthThumbnail { get; internal set; }
        public byte[] RenderThumbnail { get; internal set; }
        public byte[] ErrorThumbnail { get; internal set; }
    }

    /// <summary>Everything an evaluation measured, with the choices it made; <see cref="MetricsJson"/> and <see cref="ReportHtml"/> write it.</summary>
    public sealed class EvaluationResult
    {
        public string DatasetFolder { get; internal set; }
        public string Split { get; internal set; }

        /// <summary>The split file whose test views were scored (<c>--split sparse_&lt;n&gt;</c>), or null.</summary>
        public SparseSplit SplitFile { get; internal set; }
        public RenderSet Renders { get; internal set; }
        public EvaluationBackground Background { get; internal set; }
        public bool DepthAlongRay { get; internal set; }
        public bool HasMasks { get; internal set; }
        public List<ViewResult> Views { get; } = new List<ViewResult>();
        public GeometryResult Geometry { get; internal set; }

        /// <summary><c>--geometry &lt;folder&gt;</c>: one result per time step (<see cref="GeometryStepsEvaluation"/>); empty otherwise.</summary>
        public List<GeometryResult> GeometrySteps { get; } = new List<GeometryResult>();
        public List<string> Notes { get; } = new List<string>();

        /// <summary>What was accepted against the protocol or the renders' own background (<c>--override-protocol</c>), or a trainer figure that disagrees: said loudly.</summary>
        public List<string> Warnings { get; } = new List<string>();

        /// <summary>The dataset's eval_protocol.json, or null when it has none (<see cref="EvalProtocolFile"/>).</summary>
        public EvalProtocol Protocol { get; internal set; }

        /// <summary>The renders' mean colour where the ground truth is transparent (<see cref="RenderBackgroundCheck"/>); null when not measured.</summary>
        public RenderBackgroundCheck.Measurement RenderBackground { get; internal set; }

        /// <summary>The trainer's own figures for these renders (<see cref="TrainerResults"/>), or null.</summary>
        public TrainerFigures Trainer { get; internal set; }
        public List<TrainerMetricComparison> TrainerMeans { get; } = new List<TrainerMetricComparison>();
        public List<int> TrainerFlaggedViews { get; } = new List<int>();

        public string OutFolder { get; internal set; }
        public string CreatedUtc { get; internal set; }
    }
}
