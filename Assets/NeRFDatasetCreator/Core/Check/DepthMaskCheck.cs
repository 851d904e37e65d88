using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>depth vs mask</b>: depth is present exactly where the mask has geometry. A fully covered mask pixel (255) needs
    /// depth, a background pixel (0) must have none; edge pixels (1…254) may go either way, since depth is point-sampled
    /// and the mask is coverage (pixels.md §3–4).
    /// </summary>
    public sealed class DepthMaskCheck : IViewCheck
    {
        /// <summary>
        /// Share of a view's geometry pixels (mask or depth) allowed to disagree: a few stray pixels where the two passes
        /// rasterise a thin feature differently. A flipped, shifted or wrongly culled pass disagrees on far more.
        /// </summary>
        public const double MaxMismatch = 0.005;

        public string Name => "depth vs mask";

        int _views, _bad;
        double _worst;

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            var mask = images.Mask;
            var depth = images.Depth;
            if (mask == null || depth == null) return;
            _views++;
            int missing = 0, extra = 0, geometry = 0;
            for (var i = 0; i < mask.Length; i++)
            {
                var m = mask[i];
                var d = depth[i] != 0;
                if (m != 0 || d) geometry++;
                if (m == 255 && !d) missing++;
                else if (m == 0 && d) extra++;
            }
            var fraction = geometry == 0 ? 0 : (double)(missing + extra) / geometry;
            if (fraction > _worst) _worst = fraction;
            if (fraction > MaxMismatch)
            {
                _bad++;
                problems.Add(new DatasetProblem(Name, "./" + view.DepthFile, view.Frame, CheckFigures.Percent(fraction) + " of the geometry disagrees with " + view.MaskFile +
                    " (" + missing + " covered pixels without depth, " + extra + " background pixels with depth), above " + CheckFigures.Percent(MaxMismatch) +
                    ": one of the two passes is flipped, offset or draws other objects."));
            }
        }

        public DatasetCheckResult Finish()
        {
            if (_views == 0) return DatasetCheckResult.Skip(Name, "no view has both a depth PNG and a mask");
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed,
                _views + " views, worst mismatch " + CheckFigures.Percent(_worst), "≤ " + CheckFigures.Percent(MaxMismatch) + " of each view's geometry", _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
