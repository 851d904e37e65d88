using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>alpha vs mask</b>: the colour image's alpha covers the target's geometry (the mask), allowing what pixels.md §3
    /// documents — glass is in the mask at any alpha above 0, particles, sprites and lines have alpha outside the mask —
    /// and no view's alpha is empty or opaque everywhere. Where the edges lie is <see cref="ColourGeometryCheck"/>'s.
    /// </summary>
    public sealed class AlphaMaskCheck : IViewCheck
    {
        /// <summary>
        /// Share of a view's fully covered mask pixels (255) that must have alpha above 0. Glass is partly transparent but
        /// never fully (alpha 0 would mean it is invisible); 1 % leaves room for a clear material or a hole the colour pass
        /// draws differently. A mask flipped or shifted against the colour loses far more.
        /// </summary>
        public const double MinMaskUnderAlpha = 0.99;

        /// <summary>
        /// Share of a view's background (mask 0) that may have alpha above 0: particles, sprites, lines and trails live
        /// there (pixels.md §3), but not over half the background; a renderer feature that veils the whole frame
        /// (unity-layer-review.md S3-1) puts alpha on all of it.
        /// </summary>
        public const double MaxBackgroundWithAlpha = 0.5;

        public string Name => "alpha vs mask";

        readonly bool _opaqueBackground;
        int _views, _compared, _noAlpha;
        double _worstUnder = 1, _worstBackground;
        readonly List<double> _iou = new List<double>();
        int _bad;

        /// <param name="opaqueBackground">The dataset was captured over a solid colour (dataset_config.json): alpha is 255 everywhere by design.</param>
        public AlphaMaskCheck(bool opaqueBackground) { _opaqueBackground = opaqueBackground; }

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            if (!images.HasColour) return;
            _views++;
            var alpha = images.Alpha;
            if (alpha == null) { _noAlpha++; return; }
            var file = "./" + view.ColourFile;
            int any = 0, opaque = 0, n = alpha.Length;
            for (var i = 0; i < n; i++)
            {
                if (alpha[i] != 0) any++;
                if (alpha[i] == 255) opaque++;
            }
            if (any == 0)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, "alpha is 0 everywhere: the view shows nothing (the target is outside the view, or the matting lost it)."));
                _bad++;
            }
            else if (any == n && !_opaqueBackground)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, (opaque == n ? "alpha is 255" : "alpha is above 0") +
                    " everywhere although the background is transparent: something drew over the whole frame (a full-screen renderer feature or post-processing)."));
                _bad++;
            }
            var mask = images.Mask;
            if (mask == null) return;
            int full = 0, fullUnder = 0, background = 0, backgroundWith = 0, both = 0, either = 0;
            for (var i = 0; i < n; i++)
            {
                var m = mask[i];
                var a = alpha[i] != 0;
                if (m == 255) { full++; if (a) fullUnder++; }
                else if (m == 0) { background++; if (a) backgroundWith++; }
                if (m != 0 && a) both++;
                if (m != 0 || a) either++;
            }
            _compared++;
            if (either > 0) _iou.Add((double)both / either);
            var under = full == 0 ? 1 : (double)fullUnder / full;
            var withAlpha = background == 0 ? 0 : (double)backgroundWith / background;
            if (under < _worstUnder) _worstUnder = under;
            if (withAlpha > _worstBackground) _worstBackground = withAlpha;
            if (under < MinMaskUnderAlpha)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, CheckFigures.Percent(under) + " of the mask's covered pixels (" + view.MaskFile +
                    ") have alpha, below " + CheckFigures.Percent(MinMaskUnderAlpha) + ": the mask and the colour do not show the same thing (a pass flipped or offset, or alpha lost)."));
                _bad++;
            }
            if (withAlpha > MaxBackgroundWithAlpha && !_opaqueBackground)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, CheckFigures.Percent(withAlpha) + " of the mask's background has alpha, above " +
                    CheckFigures.Percent(MaxBackgroundWithAlpha) + ": the alpha is veiled (a renderer feature drawing over the frame) or the mask is wrong."));
                _bad++;
            }
        }

        public DatasetCheckResult Finish()
        {
            if (_views == 0) return DatasetCheckResult.Skip(Name, "no colour image could be decoded");
            if (_noAlpha == _views) return DatasetCheckResult.Skip(Name, "the colour images have no alpha channel");
            var threshold = "alpha neither empty nor" + (_opaqueBackground ? "" : " opaque everywhere") +
                            (_compared > 0 ? "; ≥ " + CheckFigures.Percent(MinMaskUnderAlpha) + " of each mask under alpha, ≤ " + CheckFigures.Percent(MaxBackgroundWithAlpha) + " of its background with alpha" : "");
            var figure = (_views - _noAlpha) + " views" + (_compared == 0
                ? " (no masks: coverage not compared)"
                : "; worst mask under alpha " + CheckFigures.Percent(_worstUnder) + ", worst background with alpha " + CheckFigures.Percent(_worstBackground) +
                  ", median IoU of alpha > 0 and mask > 0 " + DatasetCheckResult.Number(CheckFigures.Median(_iou), "0.0000") + " (glass, particles and sprites lower it)");
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed, figure, threshold,
                _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
