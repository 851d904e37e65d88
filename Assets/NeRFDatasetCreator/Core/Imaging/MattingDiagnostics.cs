using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What <see cref="DifferenceMatting.Resolve"/> saw in one view's pair of colour renders that the matting model
    /// cannot produce (pixels.md §2, "Matting diagnostics"). The model is out = F + T·B for the clear colour B, so:
    /// <list type="bullet">
    /// <item><see cref="DarkerOverWhite"/>: samples where some channel of the render over white is darker than over
    /// black by more than <see cref="DarkerTolerance"/> (T &lt; 0). No blend of one surface over two backgrounds does
    /// that; the matting silently clamps such a sample to alpha 1.</item>
    /// <item><see cref="StrayBackground"/>: samples that the mask pass (geometry) leaves empty but whose renders are not
    /// exactly the clear colours (black (0, 0, 0) and white (1, 1, 1), compared bit for bit). Counted only when the
    /// frame carries a mask (<see cref="BackgroundChecked"/>).</item>
    /// </list>
    /// Both are per sample (a k×k block has k² samples), whichever code path (scalar, 64-bit words, vectors) resolved it.
    /// </summary>
    public struct MattingDiagnostics
    {
        /// <summary>
        /// 2⁻⁹: four half-float steps just below 1 (more for darker values), half an 8-bit step. A correct blend is
        /// monotonic in the clear colour, so any W &lt; K is an inconsistency; the tolerance only absorbs blend rounding.
        /// </summary>
        public const float DarkerTolerance = 1f / 512;

        /// <summary>A view is reported on its own when either count exceeds this fraction of its samples (0.1 %).</summary>
        public const double ViewWarningFraction = 0.001;

        /// <summary>Samples resolved (render width × height, summed over views).</summary>
        public long Samples;

        /// <summary>Samples with W − K &lt; −<see cref="DarkerTolerance"/> in R, G or B.</summary>
        public long DarkerOverWhite;

        /// <summary>Samples without geometry in the mask pass whose two renders differ from the clear colours.</summary>
        public long StrayBackground;

        /// <summary>Whether a mask was available, i.e. whether <see cref="StrayBackground"/> was counted at all.</summary>
        public bool BackgroundChecked;

        public double DarkerFraction => Samples > 0 ? (double)DarkerOverWhite / Samples : 0;
        public double StrayFraction => Samples > 0 ? (double)StrayBackground / Samples : 0;

        /// <summary>Either count above <see cref="ViewWarningFraction"/> of the samples.</summary>
        public bool AboveThreshold => DarkerFraction > ViewWarningFraction || StrayFraction > ViewWarningFraction;

        /// <summary>The sum of two views' (or runs') diagnostics.</summary>
        public static MattingDiagnostics operator +(MattingDiagnostics a, MattingDiagnostics b) => new MattingDiagnostics
        {
            Samples = a.Samples + b.Samples,
            DarkerOverWhite = a.DarkerOverWhite + b.DarkerOverWhite,
            StrayBackground = a.StrayBackground + b.StrayBackground,
            BackgroundChecked = a.BackgroundChecked || b.BackgroundChecked,
        };

        /// <summary>"12 of 2 560 000 samples (0.0005 %) darker over white than over black; 0 … stray background".</summary>
        public override string ToString() => string.Format(CultureInfo.InvariantCulture,
            "{0} of {1} samples ({2:0.####} %) darker over white than over black; {3}",
            DarkerOverWhite, Samples, 100 * DarkerFraction,
            BackgroundChecked
                ? string.Format(CultureInfo.InvariantCulture, "{0} ({1:0.####} %) outside the geometry differ from the clear colour", StrayBackground, 100 * StrayFraction)
                : "background not checked (no mask pass)");

        /// <summary>
        /// What usually causes the counts (Documentation~/capture.md, "Matting diagnostics"); empty when both are 0.
        /// </summary>
        public string LikelyCauses()
        {
            var causes = "";
            if (DarkerOverWhite > 0)
                causes += "Darker over white: the two colour renders differ by more than the clear colour — a full-screen " +
                          "renderer feature (URP Full Screen Pass, outline, fog, tint, vignette) or a shader animated by time " +
                          "(wind, scrolling UVs) that moved between the two renders. ";
            if (StrayBackground > 0)
                causes += "Background not clear: something drew where the mask pass saw no geometry — a full-screen renderer " +
                          "feature (vignette, tint, fog, bloom-like glow), or content the data passes do not draw (particles, " +
                          "sprites, lines, trails, terrain; see CaptureSummary's non-mesh renderers), or vertex-animated " +
                          "geometry that the data passes draw undisplaced.";
            return causes.Trim();
        }
    }
}
