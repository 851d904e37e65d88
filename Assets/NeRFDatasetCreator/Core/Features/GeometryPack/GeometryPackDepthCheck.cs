using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>geometry pack vs depth</b>: the geometry pack is the target's surface in the output frame, and a depth map holds
    /// the nearest surface of the target, so no point of the mesh may lie in front of a view's depth, nor project where
    /// the view saw nothing — both judged against the 3×3 neighbourhood (its nearest surface, or all nine pixels empty), as
    /// a depth pixel holds the surface at its centre and silhouettes and steep slopes change within a pixel. Each view is compared with the mesh
    /// of its own time: a static dataset's one mesh, a per-step pack's mesh whose <c>time</c> equals the frame's, a
    /// start-only pack's mesh for the frames at time 0 (monocular val/test views between two steps have no mesh and are
    /// skipped). Catches a mesh in another frame, scale or normalisation than the poses, and a step's mesh written at
    /// another step's time. At most <see cref="MaxMeshes"/> meshes are read, spread over the steps, each sampled to
    /// <see cref="Points"/> points.
    /// </summary>
    public sealed class GeometryPackDepthCheck : IViewCheck
    {
        public const string CheckName = "geometry pack vs depth";

        /// <summary>Share of a view's in-frame mesh points allowed in front of its depth or on empty pixels: 2 %, as for the point cloud.</summary>
        public const double MaxBadShare = 0.02;

        /// <summary>Output units a point may lie in front of the depth besides the pixel-footprint slack (5 depth-PNG steps).</summary>
        public const double Tolerance = 0.005;

        /// <summary>Pixel footprints of depth allowed for sloped surfaces (ObservedPoints' rule).</summary>
        const double PixelSlack = 1.5;

        public const int Points = 4096;
        public const int MaxMeshes = 16;
        const int MinPointsInView = 20;

        readonly string _root;
        readonly List<GeometryPackEntry> _entries;
        readonly bool _dynamic;
        readonly string _skip;
        GeometryPackEntry _loaded;
        double[] _xyz;
        int _views, _bad;
        double _worst;

        public string Name => CheckName;

        /// <param name="config">The dataset's <c>dataset_config.json</c>, read once by the check runner.</param>
        public GeometryPackDepthCheck(string root, DatasetConfigFile config, bool dynamic)
        {
            _root = root;
            _dynamic = dynamic;
            if (config.State == DatasetConfigState.Unreadable || config.State == DatasetConfigState.NotJson)
            {
                _skip = DatasetLayout.ConfigFileName + " cannot be read";
                return;
            }
            var entries = (config.Config?.GeometryEntries ?? Array.Empty<GeometryPackEntry>()).ToList();
            if (entries.Count == 0)
            {
                _skip = "the dataset has no geometry pack";
                return;
            }
            // Every recorded mesh, not only the ones compared below: a pack recorded but lost or damaged is a failure,
            // never a skip (evaluate would score against it).
            foreach (var entry in entries)
            {
                var why = Damage(root, entry);
                if (why != null) Damaged(entry, why);
            }
            if (entries.Count > MaxMeshes)
                entries = Enumerable.Range(0, MaxMeshes).Select(i => entries[(int)((long)i * (entries.Count - 1) / (MaxMeshes - 1))]).Distinct().ToList();
            _entries = entries;
        }

        /// <summary>
        /// The recorded meshes that are outside the dataset, missing, changed since the capture or unreadable, each naming
        /// the file and the fix: <see cref="DatasetCheck"/> reports them as problems of this check.
        /// </summary>
        public IReadOnlyList<DatasetProblem> PackProblems => _damaged;

        readonly List<DatasetProblem> _damaged = new List<DatasetProblem>();
        readonly HashSet<GeometryPackEntry> _damagedEntries = new HashSet<GeometryPackEntry>();

        void Damaged(GeometryPackEntry entry, string why)
        {
            if (!_damagedEntries.Add(entry)) return;
            _damaged.Add(new DatasetProblem(CheckName, entry.File, -1, "is recorded in " + DatasetLayout.ConfigFileName + " as the geometry pack" +
                (entry.Step.HasValue ? " of time step " + entry.Step.Value : "") + " but " + why +
                ". Capture the dataset again with the geometry pack on (or remove the geometry record from " + DatasetLayout.ConfigFileName + " if the dataset should have none)."));
        }

        /// <summary>Why a recorded mesh cannot be the target's surface (outside, missing, not the recorded bytes), or null.</summary>
        static string Damage(string root, GeometryPackEntry entry)
        {
            var path = PathSafety.Inside(root, entry.File, out var outside);
            if (path == null) return "its path " + outside;
            if (!File.Exists(path)) return "does not exist";
            if (entry.Sha256 == null) return null;
            try
            {
                return string.Equals(PointCloudRecord.HashOf(path), entry.Sha256, StringComparison.OrdinalIgnoreCase) ? null
                    : "does not have the SHA-256 recorded for it (truncated, replaced or edited after the capture)";
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                return "cannot be read (" + e.Message + ")";
            }
        }

        /// <summary>The mesh of the view's time, or null.</summary>
        GeometryPackEntry MeshOf(CheckView view)
        {
            if (!_dynamic) return _entries.FirstOrDefault(e => e.Step == null) ?? _entries[0];
            if (!view.Time.HasValue) return null;
            // A start-only pack recorded before its time was written is at time 0.
            return _entries.FirstOrDefault(e => Math.Abs((e.Time ?? 0) - view.Time.Value) < 1e-9);
        }

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            if (_entries == null || images.Depth == null || view.Camera == null) return;
            var entry = MeshOf(view);
            if (entry == null || !Load(entry)) return;
            int w = images.Width, h = images.Height, seen = 0, bad = 0;
            var depth = images.Depth;
            for (var k = 0; k < _xyz.Length; k += 3)
            {
                if (!view.Camera.Project(_xyz[k], _xyz[k + 1], _xyz[k + 2], out var u, out var v, out var z)) continue;
                var x = (int)Math.Floor(u);
                var y = (int)Math.Floor(v);
                if (x < 0 || y < 0 || x >= w || y >= h) continue;
                seen++;
                // The nearest surface over the 3×3 neighbourhood: a point near a silhouette or on a steep slope may
                // project into a pixel whose centre ray meets a farther surface; 0 when all nine pixels are empty.
                var nearest = Nearest(depth, x, y, w, h);
                if (nearest == 0 || z < nearest * view.DepthScale - Tolerance - PixelSlack * z / view.Camera.Focal) bad++;
            }
            if (seen < MinPointsInView) return;
            _views++;
            var share = (double)bad / seen;
            if (share > _worst) _worst = share;
            if (share > MaxBadShare)
            {
                _bad++;
                problems.Add(new DatasetProblem(Name, "./" + view.DepthFile, view.Frame, CheckFigures.Percent(share) + " of the " + seen + " points of " + entry.File +
                    (entry.Step.HasValue ? " (time step " + entry.Step.Value + ")" : "") + " in view lie in front of the depth or where it saw nothing, above " + CheckFigures.Percent(MaxBadShare) +
                    ": the mesh, the pose or the depth is in another frame, scale or time."));
            }
        }

        bool Load(GeometryPackEntry entry)
        {
            if (ReferenceEquals(entry, _loaded)) return _xyz != null;
            _loaded = entry;
            _xyz = null;
            if (_damagedEntries.Contains(entry)) return false; // reported once, as a problem
            var path = PathSafety.Inside(_root, entry.File, out _);
            if (path == null || !File.Exists(path)) return false;
            try
            {
                var mesh = GeometryFile.Read(path);
                if (mesh.TriangleCount == 0)
                {
                    Damaged(entry, "has no triangles");
                    return false;
                }
                var points = SurfaceSampler.Sample(new[] { mesh }, Points, 0x636865636b);
                _xyz = new double[points.Count * 3];
                for (var i = 0; i < points.Count; i++)
                {
                    _xyz[3 * i] = points[i].Position.X;
                    _xyz[3 * i + 1] = points[i].Position.Y;
                    _xyz[3 * i + 2] = points[i].Position.Z;
                }
                return true;
            }
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is InvalidParameterException)
            {
                Damaged(entry, "cannot be read: " + e.Message);
                return false;
            }
        }

        static int Nearest(ushort[] depth, int x, int y, int w, int h)
        {
            var nearest = 0;
            for (var yy = y - 1; yy <= y + 1; yy++)
                for (var xx = x - 1; xx <= x + 1; xx++)
                    if (xx >= 0 && yy >= 0 && xx < w && yy < h && depth[yy * w + xx] != 0 && (nearest == 0 || depth[yy * w + xx] < nearest)) nearest = depth[yy * w + xx];
            return nearest;
        }

        public DatasetCheckResult Finish()
        {
            if (_entries == null) return DatasetCheckResult.Skip(Name, _skip);
            if (_damaged.Count > 0)
                return new DatasetCheckResult(Name, DatasetCheckStatus.Failed, _damaged.Count + (_damaged.Count == 1 ? " recorded mesh" : " recorded meshes") + " lost or damaged",
                    "every recorded mesh inside the dataset, present, unchanged and readable", _damaged.Count + " problem(s)");
            if (_views == 0) return DatasetCheckResult.Skip(Name, "no view with depth at a time the geometry pack holds sees " + MinPointsInView + " or more of its points");
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed,
                _views + " views, " + _entries.Count + (_entries.Count == 1 ? " mesh" : " meshes") + ", worst view " + CheckFigures.Percent(_worst) + " in front of the depth or off it",
                "≤ " + CheckFigures.Percent(MaxBadShare) + " of the mesh points in each view in front of its depth or on empty pixels", _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
