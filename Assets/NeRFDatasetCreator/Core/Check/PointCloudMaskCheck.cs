using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>point cloud vs masks</b>: this plugin's <c>points3d.ply</c> (only when <see cref="PointCloudOwnership"/> says it
    /// is ours: 3DGS writes a random cube under the same name) lies on the target's surface, so every point that projects
    /// into a view lands on the target's mask there — hidden points too, since the mask is the target's whole silhouette.
    /// Catches a cloud in another frame or normalisation than the poses, and masks flipped against the poses.
    /// </summary>
    public sealed class PointCloudMaskCheck : IViewCheck
    {
        /// <summary>
        /// Share of the points projecting into a view that must fall on its mask (within one pixel: the mask's edge is
        /// coverage, a point on the silhouette may land in the next pixel). 2 % allows thin parts the mask pass misses.
        /// </summary>
        public const double MinInside = 0.98;

        /// <summary>Points used at most (evenly spread over the file): enough for a share to 0.1 %.</summary>
        const int MaxPoints = 4096;

        /// <summary>A view is judged only when at least this many points project into it.</summary>
        const int MinPointsInView = 20;

        public string Name => "point cloud vs masks";

        readonly double[] _xyz;
        readonly string _skip;
        int _views, _bad;
        double _worst = 1;

        /// <param name="points">The cloud's positions, or null with <paramref name="skipReason"/>.</param>
        public PointCloudMaskCheck(IReadOnlyList<CloudPoint> points, string skipReason)
        {
            _skip = skipReason;
            if (points == null || points.Count == 0) return;
            var count = System.Math.Min(points.Count, MaxPoints);
            _xyz = new double[count * 3];
            for (var k = 0; k < count; k++)
            {
                var p = points[(int)((long)k * points.Count / count)].Position;
                _xyz[3 * k] = p.X;
                _xyz[3 * k + 1] = p.Y;
                _xyz[3 * k + 2] = p.Z;
            }
        }

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            if (_xyz == null || images.Mask == null || view.Camera == null) return;
            int w = images.Width, h = images.Height, seen = 0, inside = 0;
            var mask = images.Mask;
            for (var k = 0; k < _xyz.Length; k += 3)
            {
                if (!view.Camera.Project(_xyz[k], _xyz[k + 1], _xyz[k + 2], out var u, out var v, out _)) continue;
                var x = (int)System.Math.Floor(u);
                var y = (int)System.Math.Floor(v);
                if (x < 0 || y < 0 || x >= w || y >= h) continue;
                seen++;
                if (OnMask(mask, x, y, w, h)) inside++;
            }
            if (seen < MinPointsInView) return;
            _views++;
            var share = (double)inside / seen;
            if (share < _worst) _worst = share;
            if (share < MinInside)
            {
                _bad++;
                problems.Add(new DatasetProblem(Name, "./" + view.MaskFile, view.Frame, "only " + CheckFigures.Percent(share) + " of the " + seen + " cloud points in view land on the mask, below " +
                    CheckFigures.Percent(MinInside) + ": the cloud, the pose or the mask is in another frame, scale or orientation."));
            }
        }

        static bool OnMask(byte[] mask, int x, int y, int w, int h)
        {
            for (var yy = y - 1; yy <= y + 1; yy++)
                for (var xx = x - 1; xx <= x + 1; xx++)
                    if (xx >= 0 && yy >= 0 && xx < w && yy < h && mask[yy * w + xx] != 0) return true;
            return false;
        }

        public DatasetCheckResult Finish()
        {
            if (_xyz == null) return DatasetCheckResult.Skip(Name, _skip ?? "the dataset has no points3d.ply of this plugin");
            if (_views == 0) return DatasetCheckResult.Skip(Name, "no view with a mask sees " + MinPointsInView + " or more of the cloud's points");
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed,
                _views + " views, " + _xyz.Length / 3 + " points, worst view " + CheckFigures.Percent(_worst) + " on the mask",
                "≥ " + CheckFigures.Percent(MinInside) + " of the points in each view on its mask", _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
