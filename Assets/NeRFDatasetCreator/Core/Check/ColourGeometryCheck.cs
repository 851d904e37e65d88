using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>colour vs geometry</b>: the colour image's alpha edges lie on the mask's and the depth's edges, to the pixel.
    /// For every view the whole-pixel shift that best lines alpha &gt; 0 up with mask &gt; 0 (and with depth &gt; 0) is
    /// measured (<see cref="EdgeShift"/>); any shift other than (0, 0) that clearly explains the edges better is a problem.
    /// </summary>
    public sealed class ColourGeometryCheck : IViewCheck
    {
        /// <summary>
        /// A shift counts when it leaves at most half the edge mismatches of no shift: a one-pixel offset of a whole pass
        /// removes nearly all of them, while anti-aliasing differences between passes leave no shift better than another.
        /// </summary>
        public const double ShiftGain = 0.5;

        /// <summary>Mismatches at no shift below this share of the edge band are alignment noise, not an offset.</summary>
        public const double MinMismatchShare = 0.05;

        public string Name => "colour vs geometry";

        int _views, _bad;
        double _worstShare;
        readonly EdgeShift _shift = new EdgeShift();
        bool[] _alpha = new bool[0], _geometry = new bool[0];

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            if (images.Alpha == null || (images.Mask == null && images.Depth == null)) return;
            _views++;
            int w = images.Width, h = images.Height, n = w * h;
            if (_alpha.Length != n)
            {
                _alpha = new bool[n];
                _geometry = new bool[n];
            }
            var alpha = images.Alpha;
            for (var i = 0; i < n; i++) _alpha[i] = alpha[i] != 0;
            if (images.Mask != null)
            {
                var mask = images.Mask;
                for (var i = 0; i < n; i++) _geometry[i] = mask[i] != 0;
                Compare(view, _alpha, _geometry, w, h, view.MaskFile, problems);
            }
            if (images.Depth != null)
            {
                var depth = images.Depth;
                for (var i = 0; i < n; i++) _geometry[i] = depth[i] != 0;
                Compare(view, _alpha, _geometry, w, h, view.DepthFile, problems);
            }
        }

        void Compare(CheckView view, bool[] a, bool[] g, int w, int h, string against, List<DatasetProblem> problems)
        {
            var r = _shift.Measure(a, g, w, h);
            if (r.BandPixels == 0) return;
            var share = (double)r.MismatchAtZero / r.BandPixels;
            if (share > _worstShare) _worstShare = share;
            if ((r.BestDx != 0 || r.BestDy != 0) && share >= MinMismatchShare && r.BestMismatch <= ShiftGain * r.MismatchAtZero)
            {
                _bad++;
                problems.Add(new DatasetProblem(Name, "./" + view.ColourFile, view.Frame, "the alpha's edges lie " + Describe(r.BestDx, r.BestDy) + " of " + against +
                    "'s (" + r.MismatchAtZero + " of " + r.BandPixels + " edge pixels disagree as written, " + r.BestMismatch + " after the shift): a pass is offset by a pixel (a half-pixel or supersampling error, or a flipped row order)."));
            }
        }

        static string Describe(int dx, int dy)
        {
            var parts = new List<string>();
            if (dx != 0) parts.Add(System.Math.Abs(dx) + " px " + (dx > 0 ? "right" : "left"));
            if (dy != 0) parts.Add(System.Math.Abs(dy) + " px " + (dy > 0 ? "down" : "up"));
            return string.Join(" and ", parts);
        }

        public DatasetCheckResult Finish()
        {
            if (_views == 0) return DatasetCheckResult.Skip(Name, "no view has alpha and a mask or depth PNG");
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed,
                _views + " views, worst edge mismatch without shift " + CheckFigures.Percent(_worstShare) + " of the edge band",
                "no whole-pixel shift (up to " + EdgeShift.Reach + " px) halves the edge mismatch", _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
