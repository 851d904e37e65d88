using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>instance reprojection</b>: an object's id is the same in neighbouring views. For sampled pixels of view i inside
    /// an object (the id and depth the same in the 3×3 block), the point back-projected with i's depth, pose and
    /// intrinsics is projected into each neighbouring view j (<see cref="MultiViewGeometryCheck.Pairs"/>); where j sees
    /// that surface (its depth there agrees) and the spot is inside one object, j's id must be i's. Catches ids swapped
    /// between objects in some views, ids numbered per view or per shard instead of per capture, and id maps of
    /// another view or time.
    /// </summary>
    public sealed class InstanceReprojectionCheck
    {
        public const string CheckName = "instance reprojection";

        /// <summary>
        /// Share of an object's visible points (per pair) that must keep its id. Exact data keeps all but stray points where
        /// j's depth agrees with a neighbouring object's at a contact edge; a swapped or renumbered id keeps none.
        /// </summary>
        public const double MinAgreement = 0.9;

        /// <summary>Points an object needs in a pair to be judged.</summary>
        public const int MinPoints = 12;

        const int SamplesPerPair = 6000;
        const double RelativeTolerance = 0.01;

        int _pairs, _judged, _bad, _objects;
        double _worst = 1;

        public void Pair(CheckView vi, ushort[] di, ushort[] ii, CheckView vj, ushort[] dj, ushort[] ij, List<DatasetProblem> problems)
        {
            _pairs++;
            CheckCamera ci = vi.Camera, cj = vj.Camera;
            int wi = ci.Width, hi = ci.Height, wj = cj.Width, hj = cj.Height;
            var stride = Math.Max(1, (int)Math.Sqrt((double)wi * hi / (4.0 * SamplesPerPair)));
            var seen = new Dictionary<int, int>();
            var kept = new Dictionary<int, int>();
            var becameOther = new Dictionary<int, Dictionary<int, int>>();
            for (var v = 1; v < hi - 1; v += stride)
                for (var u = 1; u < wi - 1; u += stride)
                {
                    var p = v * wi + u;
                    int id = ii[p], z0 = di[p];
                    if (id == 0 || z0 == 0 || !Uniform(ii, p, wi)) continue;
                    var edge = Math.Max(3, (int)(0.02 * z0));
                    if (Math.Abs(di[p - 1] - z0) > edge || Math.Abs(di[p + 1] - z0) > edge || Math.Abs(di[p - wi] - z0) > edge || Math.Abs(di[p + wi] - z0) > edge) continue;
                    ci.BackProject(u + 0.5, v + 0.5, z0 * vi.DepthScale, out var x, out var y, out var w);
                    if (!cj.Project(x, y, w, out var uj, out var vjj, out var zj)) continue;
                    int xj = (int)Math.Floor(uj), yj = (int)Math.Floor(vjj);
                    if (xj < 1 || yj < 1 || xj >= wj - 1 || yj >= hj - 1) continue;
                    var q = yj * wj + xj;
                    if (dj[q] == 0 || !Uniform(ij, q, wj)) continue; // j's silhouette or an edge between objects
                    var tolerance = Math.Max(3 * vj.DepthScale, RelativeTolerance * zj);
                    if (Math.Abs(dj[q] * vj.DepthScale - zj) > tolerance) continue; // hidden in j, or j's depth disagrees (multi-view geometry's to judge)
                    seen.TryGetValue(id, out var n);
                    seen[id] = n + 1;
                    if (ij[q] == id)
                    {
                        kept.TryGetValue(id, out var k);
                        kept[id] = k + 1;
                    }
                    else
                    {
                        if (!becameOther.TryGetValue(id, out var others)) becameOther[id] = others = new Dictionary<int, int>();
                        others.TryGetValue(ij[q], out var o);
                        others[ij[q]] = o + 1;
                    }
                }
            var judgedObjects = seen.Where(s => s.Value >= MinPoints).OrderBy(s => s.Key).ToList();
            if (judgedObjects.Count == 0) return;
            _judged++;
            var why = new List<string>();
            foreach (var entry in judgedObjects)
            {
                _objects++;
                kept.TryGetValue(entry.Key, out var k);
                var share = (double)k / entry.Value;
                if (share < _worst) _worst = share;
                if (share >= MinAgreement) continue;
                var instead = becameOther.TryGetValue(entry.Key, out var others) ? others.OrderByDescending(o => o.Value).ThenBy(o => o.Key).First().Key : 0;
                why.Add("id " + entry.Key + " keeps its id at only " + CheckFigures.Percent(share) + " of " + entry.Value + " points (mostly " + instead + " there)");
            }
            if (why.Count == 0) return;
            _bad++;
            problems.Add(new DatasetProblem(CheckName, "./" + vi.InstanceFile, vi.Frame, "reprojected into " + vj.Name + " (" + vj.Split + " frame " + vj.Frame + "): " + string.Join(", ", why) +
                ". The same object must have the same id in every view: ids swapped or numbered per view, or a map of another view."));
        }

        static bool Uniform(ushort[] ids, int p, int w)
        {
            var id = ids[p];
            return ids[p - 1] == id && ids[p + 1] == id && ids[p - w] == id && ids[p + w] == id &&
                   ids[p - w - 1] == id && ids[p - w + 1] == id && ids[p + w - 1] == id && ids[p + w + 1] == id;
        }

        public DatasetCheckResult Finish(string skipReason)
        {
            if (skipReason != null) return DatasetCheckResult.Skip(CheckName, skipReason);
            if (_pairs == 0) return DatasetCheckResult.Skip(CheckName, "no two neighbouring views both have depth and an instance map");
            if (_judged == 0) return DatasetCheckResult.Skip(CheckName, "no object shows " + MinPoints + " points to a neighbouring view");
            return new DatasetCheckResult(CheckName, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed,
                _judged + " view pairs, " + _objects + " object sightings; worst share keeping its id " + CheckFigures.Percent(_worst),
                "≥ " + CheckFigures.Percent(MinAgreement) + " of each object's visible points per pair", _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
