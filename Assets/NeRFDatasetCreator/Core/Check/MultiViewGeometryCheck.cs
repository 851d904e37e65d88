using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>multi-view geometry</b>: each view's depth, back-projected with its pose and intrinsics, lands on the depth of
    /// its neighbouring views (the two whose viewing directions are nearest, 2°–60° apart; in a dynamic dataset only
    /// views of the same time). For sampled pixels of view i: the world point X, its projection into view j and z-depth
    /// there, and j's depth at that spot (bilinear). Points hidden behind j's surface are occlusions and not counted; the
    /// others give a depth error |d_j − z_j| and a pixel error (j's surface point projected back into i, against the pixel
    /// it came from). Catches pose, handedness and flips, field of view, depth scale and depth along the ray.
    /// </summary>
    public sealed class MultiViewGeometryCheck
    {
        public const string CheckName = "multi-view geometry";

        /// <summary>Share of the points j does not see hidden behind a nearer surface that must agree within the depth tolerance: exact data leaves only stray silhouette points out; a wrong pose, field of view or scale moves most points off j's surface.</summary>
        public const double MinConsistent = 0.8;

        /// <summary>Share of the points that may lie behind j's surface (occlusion between views 2°–60° apart hid two thirds of one view's points in a test scene): a depth scale too large puts nearly every point behind it.</summary>
        public const double MaxHidden = 0.9;

        /// <summary>Share of a view's sampled points that must land inside a neighbour's image (views 2°–60° apart around one target share most of it).</summary>
        public const double MinInFrame = 0.25;

        /// <summary>Neighbouring depths within this share of the depth (and 3 steps) are one smooth surface.</summary>
        const double SmoothTolerance = 0.02;

        /// <summary>Median pixel error per pair: exact data gives ~0.1 px (depth steps, bilinear lookup); a wrong field of view or pose moves points by pixels.</summary>
        public const double MaxMedianPixels = 0.5;

        /// <summary>95th-percentile pixel error per pair: silhouettes and grazing surfaces, where a depth step moves a point far, make the tail.</summary>
        public const double MaxP95Pixels = 3;

        /// <summary>Median depth error per pair relative to the depth: 16-bit steps are ≤ 0.03 % at 4 units, and depth at supersampling 2 is the harmonic mean of the block's central samples, the depth at the pixel centre (a clean 128×96 lens capture: median 0.03 %, worst pair 0.04 %; when it was one sample a quarter pixel off, 0.2 % and 0.79 %); a depth scale or ray-vs-z error is a bias of a percent or more.</summary>
        public const double MaxMedianRelativeDepth = 0.005;

        /// <summary>Depth tolerance for "agrees": 1 % of the depth (and at least 3 steps), wide enough for grazing surfaces and the bilinear lookup.</summary>
        const double RelativeTolerance = 0.01;

        const double MinAngleDegrees = 2, MaxAngleDegrees = 60;
        const int Neighbours = 2;
        const int SamplesPerPair = 6000;
        const int MinPoints = 50;

        int _pairs, _judged, _bad;
        readonly List<double> _medianPx = new List<double>(), _p95Px = new List<double>(), _medianDepth = new List<double>(), _p95Depth = new List<double>(), _consistent = new List<double>();

        /// <summary>(i, j) pairs of indices into <paramref name="views"/>: each view with depth and its nearest neighbours by viewing direction, at the same time.</summary>
        public static List<KeyValuePair<int, int>> Pairs(IReadOnlyList<CheckView> views)
        {
            var pairs = new List<KeyValuePair<int, int>>();
            var cosMin = Math.Cos(MaxAngleDegrees * Math.PI / 180);
            var cosMax = Math.Cos(MinAngleDegrees * Math.PI / 180);
            for (var i = 0; i < views.Count; i++)
            {
                var a = views[i];
                if (a.DepthFile == null || a.Camera == null) continue;
                var fa = a.Camera.Forward;
                var best = new List<KeyValuePair<double, int>>();
                for (var j = 0; j < views.Count; j++)
                {
                    var b = views[j];
                    if (j == i || b.DepthFile == null || b.Camera == null || a.Time != b.Time) continue;
                    var cos = Vector3d.Dot(fa, b.Camera.Forward);
                    if (cos < cosMin || cos > cosMax) continue;
                    best.Add(new KeyValuePair<double, int>(-cos, j));
                }
                best.Sort((x, y) => x.Key != y.Key ? x.Key.CompareTo(y.Key) : x.Value.CompareTo(y.Value));
                for (var k = 0; k < Math.Min(Neighbours, best.Count); k++) pairs.Add(new KeyValuePair<int, int>(i, best[k].Value));
            }
            return pairs;
        }

        public void Pair(CheckView vi, ushort[] di, CheckView vj, ushort[] dj, List<DatasetProblem> problems)
        {
            _pairs++;
            CheckCamera ci = vi.Camera, cj = vj.Camera;
            int wi = ci.Width, hi = ci.Height, wj = cj.Width, hj = cj.Height;
            var stride = Math.Max(1, (int)Math.Sqrt((double)wi * hi / (4.0 * SamplesPerPair)));
            var pixels = new List<double>();
            var depths = new List<double>();
            int sampled = 0, inView = 0, consistent = 0, background = 0, hidden = 0, ambiguous = 0;
            for (var v = 1; v < hi - 1; v += stride)
                for (var u = 1; u < wi - 1; u += stride)
                {
                    var p = v * wi + u;
                    int z0 = di[p];
                    if (z0 == 0) continue;
                    // Smooth interior samples only: at a depth edge the point-sampled depth may belong to either side
                    // (pixels.md §4: the sample nearest the pixel centre, up to half a pixel off it).
                    var edge = Math.Max(3, (int)(SmoothTolerance * z0));
                    if (Math.Abs(di[p - 1] - z0) > edge || Math.Abs(di[p + 1] - z0) > edge || Math.Abs(di[p - wi] - z0) > edge || Math.Abs(di[p + wi] - z0) > edge) continue;
                    ci.BackProject(u + 0.5, v + 0.5, z0 * vi.DepthScale, out var x, out var y, out var w);
                    sampled++;
                    if (!cj.Project(x, y, w, out var uj, out var vjj, out var zj)) continue;
                    double fx = uj - 0.5, fy = vjj - 0.5;
                    var x0 = (int)Math.Floor(fx);
                    var y0 = (int)Math.Floor(fy);
                    if (x0 < 0 || y0 < 0 || x0 + 1 >= wj || y0 + 1 >= hj) continue;
                    inView++;
                    var q = y0 * wj + x0;
                    int s00 = dj[q], s10 = dj[q + 1], s01 = dj[q + wj], s11 = dj[q + wj + 1];
                    var tolerance = Math.Max(3 * vj.DepthScale, RelativeTolerance * zj);
                    if ((s00 | s10 | s01 | s11) == 0) { background++; continue; } // j sees empty space through the point
                    int lo = Math.Min(Math.Min(s00, s10), Math.Min(s01, s11)), top = Math.Max(Math.Max(s00, s10), Math.Max(s01, s11));
                    if (lo == 0 || top - lo > Math.Max(3, (int)(SmoothTolerance * top))) { ambiguous++; continue; } // j's silhouette or a depth edge
                    double ax = fx - x0, ay = fy - y0;
                    var d = ((s00 * (1 - ax) + s10 * ax) * (1 - ay) + (s01 * (1 - ax) + s11 * ax) * ay) * vj.DepthScale;
                    var r = d - zj;
                    if (r < -tolerance) { hidden++; continue; } // behind j's nearer surface
                    if (r <= tolerance) consistent++;
                    depths.Add(Math.Abs(r) / zj);
                    cj.BackProject(uj, vjj, d, out var x2, out var y2, out var w2);
                    if (ci.Project(x2, y2, w2, out var ui2, out var vi2, out _))
                        pixels.Add(Math.Sqrt((ui2 - u - 0.5) * (ui2 - u - 0.5) + (vi2 - v - 0.5) * (vi2 - v - 0.5)));
                    else pixels.Add(double.PositiveInfinity);
                }
            var judged = inView - ambiguous;
            if (sampled >= MinPoints && inView < MinInFrame * sampled)
            {
                // Neighbours 2°–60° apart around one target share most of it; a depth or pose far off throws the points out of j's frame.
                _judged++;
                _bad++;
                _consistent.Add(0);
                problems.Add(new DatasetProblem(CheckName, "./" + vi.DepthFile, vi.Frame, "reprojected into " + vj.Name + " (" + vj.Split + " frame " + vj.Frame + "): only " + inView + " of " + sampled +
                    " points land in its image, below " + CheckFigures.Percent(MinInFrame) + ". A wrong pose, field of view or depth scale."));
                return;
            }
            if (judged < MinPoints) return;
            _judged++;
            var visible = judged - hidden;
            var share = visible == 0 ? 0 : (double)consistent / visible;
            var hiddenShare = (double)hidden / judged;
            var medianPx = pixels.Count == 0 ? double.PositiveInfinity : CheckFigures.Median(pixels);
            var p95Px = pixels.Count == 0 ? double.PositiveInfinity : CheckFigures.Percentile(pixels, 0.95);
            var medianDepth = depths.Count == 0 ? double.PositiveInfinity : CheckFigures.Median(depths);
            var p95Depth = depths.Count == 0 ? double.PositiveInfinity : CheckFigures.Percentile(depths, 0.95);
            _consistent.Add(share);
            _medianPx.Add(medianPx);
            _p95Px.Add(p95Px);
            _medianDepth.Add(medianDepth);
            _p95Depth.Add(p95Depth);
            var why = new List<string>();
            if (hiddenShare > MaxHidden) why.Add(CheckFigures.Percent(hiddenShare) + " of its " + judged + " points lie behind the surface j sees (depth too large?)");
            else if (share < MinConsistent) why.Add("only " + CheckFigures.Percent(share) + " of its " + visible + " unhidden points agree within " + CheckFigures.Percent(RelativeTolerance) + " (" + background + " land on background)");
            if (medianPx > MaxMedianPixels) why.Add("median error " + Px(medianPx));
            if (p95Px > MaxP95Pixels) why.Add("95th percentile " + Px(p95Px));
            if (medianDepth > MaxMedianRelativeDepth) why.Add("median depth error " + CheckFigures.Percent(medianDepth) + " of the depth");
            if (why.Count == 0) return;
            _bad++;
            problems.Add(new DatasetProblem(CheckName, "./" + vi.DepthFile, vi.Frame, "reprojected into " + vj.Name + " (" + vj.Split + " frame " + vj.Frame + "): " + string.Join(", ", why) +
                ". A wrong pose (handedness, axis sign, Y/Z swap), field of view, depth scale or depth along the ray instead of z."));
        }

        static string Px(double value) => double.IsNaN(value) ? "n/a" : double.IsInfinity(value) ? "∞ px" : DatasetCheckResult.Number(value, "0.###") + " px";

        public DatasetCheckResult Finish(string skipReason)
        {
            if (skipReason != null) return DatasetCheckResult.Skip(CheckName, skipReason);
            if (_pairs == 0) return DatasetCheckResult.Skip(CheckName, "no two views with depth at the same time look at the scene within " + MaxAngleDegrees + "° of each other");
            if (_judged == 0) return DatasetCheckResult.Skip(CheckName, "no pair of neighbouring views shares " + MinPoints + " depth samples");
            var figure = _judged + " view pairs; pixel error median " + Px(CheckFigures.Median(_medianPx)) + " (worst pair " + Px(Max(_medianPx)) + "), 95th percentile " +
                         Px(CheckFigures.Median(_p95Px)) + " (worst " + Px(Max(_p95Px)) + "); depth error median " + CheckFigures.Percent(CheckFigures.Median(_medianDepth)) +
                         " of the depth (worst " + CheckFigures.Percent(Max(_medianDepth)) + "), 95th percentile " + CheckFigures.Percent(CheckFigures.Median(_p95Depth)) +
                         "; points agreeing " + CheckFigures.Percent(CheckFigures.Median(_consistent)) + " (worst " + CheckFigures.Percent(Min(_consistent)) + ")";
            var threshold = "per pair: median ≤ " + DatasetCheckResult.Number(MaxMedianPixels) + " px, 95th percentile ≤ " + DatasetCheckResult.Number(MaxP95Pixels) +
                            " px, median depth error ≤ " + CheckFigures.Percent(MaxMedianRelativeDepth) + ", ≥ " + CheckFigures.Percent(MinConsistent) + " of unhidden points agreeing, ≤ " + CheckFigures.Percent(MaxHidden) + " hidden";
            return new DatasetCheckResult(CheckName, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed, figure, threshold, _bad > 0 ? _bad + " problem(s)" : null);
        }

        static double Max(List<double> values) { var m = values.Count == 0 ? double.NaN : double.NegativeInfinity; foreach (var v in values) m = Math.Max(m, v); return m; }
        static double Min(List<double> values) { var m = values.Count == 0 ? double.NaN : double.PositiveInfinity; foreach (var v in values) m = Math.Min(m, v); return m; }
    }
}
