using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>One view's figures as a trainer's result file gives them (null where it gives none).</summary>
    public sealed class TrainerViewFigures
    {
        public string Name;
        public double? Psnr, Ssim, Lpips;
    }

    /// <summary>
    /// The figures a trainer wrote about its own renders (<see cref="TrainerResults"/>): the means, the per-view values
    /// matched to the split's frames when the file has them, and what each figure is (its SSIM and LPIPS variants).
    /// </summary>
    public sealed class TrainerFigures
    {
        /// <summary>"3dgs metrics.py" or "nerfstudio ns-eval".</summary>
        public string Source;

        public string File;

        /// <summary>3DGS: the ours_&lt;iter&gt; key; nerfstudio: method_name.</summary>
        public string Method;

        public double? Psnr, Ssim, Lpips;

        /// <summary>What the trainer's SSIM and LPIPS are, and whether its SSIM is this tool's variant (compared) or another (shown only).</summary>
        public string SsimVariant, LpipsVariant;
        public bool SsimComparable;

        /// <summary>PSNR tolerance in dB for the means (and views): 3DGS scores the same 8-bit PNGs; ns-eval scores float renders.</summary>
        public double PsnrTolerance;

        /// <summary>Indexed like the split's frames when the file lists every view in order (<see cref="TrainerResults"/>); null otherwise.</summary>
        public TrainerViewFigures[] Views;

        public List<string> Notes = new List<string>();
    }
}
