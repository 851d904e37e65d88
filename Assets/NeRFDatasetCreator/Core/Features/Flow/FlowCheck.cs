using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>flow</b>: a dataset's <c>flow/</c> (issue 37) agrees with its depth, poses and itself, pair by pair —
    /// (a) the flow is where frame a's depth, the two poses and the scene flow put each point (on static parts, the
    /// camera-induced flow); (b) forward ∘ backward = identity where a pixel is visible both ways; (c) the occluded mask
    /// agrees with frame b's depth; (d) every file is there, of the image's size, masks 0/255, NaN flow exactly where there
    /// is no surface. Each problem names the pair's file and the pair. Runs only when the dataset has <c>flow/flow.json</c>
    /// or records one in <c>dataset_config.json</c>; thresholds and why: Documentation~/maintainers/check.md, "flow".
    /// </summary>
    public sealed class FlowCheck
    {
        public const string CheckName = "flow";

        /// <summary>Share of a pair's judged pixels allowed to disagree in (a), (b), (c): silhouette pixels whose depth sample and mesh ray meet different surfaces.</summary>
        public const double MaxBadShare = 0.01;

        /// <summary>
        /// The share of a pair's pixels allowed to miss forward ∘ backward = identity: 5 %. The bilinear bound
        /// (<see cref="FlowPairCheck.InverseSpreadShare"/>) holds on one smooth surface; where the cell straddles a facet kink
        /// or a silhouette of a curved mesh it does not, and on the flow demo (52 views of 200 px, a faceted sphere) up to
        /// 3.1 % of a clean pair's pixels (4 of 130) and 1.2 % of a large one's missed it. A flipped sign, swapped axes or a
        /// pair one step off miss on nearly every pixel, and the depth-and-poses test catches them on its own.
        /// </summary>
        public const double MaxInverseBadShare = 0.05;

        /// <summary>Share of a pair's surface pixels where the flow's "surface" and frame a's depth may disagree: the silhouette, as in depth vs mask.</summary>
        public const double MaxSurfaceMismatch = 0.005;

        /// <summary>Pixels sampled per pair for (a)–(c) (a stride over larger images); (d) reads every pixel.</summary>
        public const int SamplesPerPair = 40000;

        /// <summary>Fewer judged pixels than this and a measurement is not judged for the pair.</summary>
        public const int MinJudged = 20;

        readonly string _root;
        readonly string _recordedButMissing;
        int _pairs, _skippedPairs, _badPairs, _structureProblems;
        int _judgedCamera, _judgedInverse, _judgedOcclusion, _judgedSurface;
        double _worstCamera, _worstInverse, _worstOcclusion, _worstSurface;
        string _skip;

        FlowCheck(string root, string recordedButMissing)
        {
            _root = root;
            _recordedButMissing = recordedButMissing;
        }

        /// <summary>The check for a dataset with <c>flow/flow.json</c> (or a <c>flow</c> record in dataset_config.json), else null: datasets without flow do not list it.</summary>
        public static FlowCheck For(string root, DatasetConfigFile config)
        {
            if (File.Exists(Path.Combine(root, FlowLayout.RecordFile.Replace('/', Path.DirectorySeparatorChar)))) return new FlowCheck(root, null);
            if (config?.Config?.Json?["flow"] != null) return new FlowCheck(root, DatasetLayout.ConfigFileName + " records flow (\"flow\"), but " + FlowLayout.RecordFile + " is missing.");
            return null;
        }

        public void Run(IReadOnlyList<CheckView> views, List<DatasetProblem> problems, CancellationToken cancel = default)
        {
            if (_recordedButMissing != null)
            {
                problems.Add(new DatasetProblem(CheckName, "./" + FlowLayout.RecordFile, -1, _recordedButMissing + " Restore flow/ or run nerf-dataset flow on the dataset again."));
                _structureProblems++;
                return;
            }
            FlowRecord record;
            try { record = FlowRecord.Read(_root); }
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException || e is FormatException || e is InvalidCastException || e is ArgumentException)
            {
                problems.Add(new DatasetProblem(CheckName, "./" + FlowLayout.RecordFile, -1, "cannot be read: " + e.Message));
                _structureProblems++;
                return;
            }
            foreach (var t in record.Tracks)
            {
                var full = PathSafety.Inside(_root, t.File, out _);
                if (full == null || !File.Exists(full))
                {
                    problems.Add(new DatasetProblem(CheckName, "./" + t.File, -1, "is listed in " + FlowLayout.RecordFile + " (tracks of " + t.Video + ", query frame " + t.QueryFrame + ") but is missing."));
                    _structureProblems++;
                }
            }
            var byImage = new Dictionary<string, CheckView>(StringComparer.Ordinal);
            foreach (var v in views) byImage[Normal(v.ColourFile)] = v;
            var depths = new DepthCache(_root);
            var pairs = new HashSet<(string, int, int)>(record.Pairs.Select(p => (p.Video, p.From, p.To)));
            foreach (var pair in record.Pairs)
            {
                if (cancel.IsCancellationRequested) return;
                _pairs++;
                var video = record.Video(pair.Video);
                var fa = video.Frames[pair.From];
                var fb = video.Frames[pair.To];
                byImage.TryGetValue(Normal(fa.Image), out var va);
                byImage.TryGetValue(Normal(fb.Image), out var vb);
                if (va?.Camera == null || vb?.Camera == null) { _skippedPairs++; continue; }
                var found = CheckPair(record, pair, fa.Image, va, fb.Image, vb, pairs.Contains((pair.Video, pair.To, pair.From)), depths);
                if (found.Count == 0) continue;
                _badPairs++;
                var name = "pair " + pair.Video + " " + pair.From + " → " + pair.To + " (" + fa.Image + " → " + fb.Image + "): ";
                foreach (var (file, message) in found) problems.Add(new DatasetProblem(CheckName, "./" + file, -1, name + message));
            }
            if (_pairs == 0) _skip = FlowLayout.RecordFile + " lists no frame pairs";
            else if (_skippedPairs == _pairs) _skip = "no pair's two views were checked (--split or --max-views left them out, or their images could not be read)";
        }

        List<(string file, string message)> CheckPair(FlowRecord record, FlowPair pair, string imageA, CheckView va, string imageB, CheckView vb, bool hasReverse, DepthCache depths)
        {
            var found = new List<(string, string)>();
            int w = va.Camera.Width, h = va.Camera.Height;
            var files = FlowPairFiles.Read(_root, pair, record.SceneFlow, w, h);
            if (!files.Complete)
            {
                _structureProblems += files.Problems.Count;
                foreach (var p in files.Problems) found.Add((pair.FlowFile, p));
                return found;
            }
            foreach (var p in FlowPairCheck.Structure(files, pair, w, h))
            {
                _structureProblems++;
                found.Add(p);
            }
            var stride = Math.Max(1, (int)Math.Sqrt((double)w * h / SamplesPerPair));
            FlowCheckDepth da = null, db = null;
            try
            {
                da = depths.Get(imageA, va);
                db = depths.Get(imageB, vb);
            }
            // PngGray16Reader refuses a depth PNG of another layout with an InvalidParameterException naming it.
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException || e is InvalidParameterException)
            {
                found.Add((pair.FlowFile, "the depth of its frames cannot be read (" + e.Message + "), so the flow is not compared with it."));
                return found;
            }
            if (da != null && (da.Width != w || da.Height != h)) da = null;
            if (db != null && (db.Width != w || db.Height != h)) db = null;

            if (da != null)
            {
                var s = FlowPairCheck.SurfaceVsDepth(files, da);
                if (s.Judged >= MinJudged)
                {
                    _judgedSurface++;
                    _worstSurface = Math.Max(_worstSurface, s.Share);
                    if (s.Share > MaxSurfaceMismatch)
                        found.Add((pair.FlowFile, CheckFigures.Percent(s.Share) + " of the " + s.Judged + " pixels with a surface in the flow or in " + da.File + " have it in only one (NaN flow must be exactly where there is no surface), above " + CheckFigures.Percent(MaxSurfaceMismatch) + ": the flow is of another frame or flipped."));
                }
            }
            if (da != null && files.SceneFlow != null)
            {
                var cam = FlowPairCheck.CameraFlow(files, da, va.Camera, vb.Camera, stride, out var statics);
                if (cam.Judged >= MinJudged)
                {
                    _judgedCamera++;
                    _worstCamera = Math.Max(_worstCamera, cam.Share);
                    if (cam.Share > MaxBadShare)
                        found.Add((pair.FlowFile, CheckFigures.Percent(cam.Share) + " of " + cam.Judged + " pixels (" + statics + " static) are not where " + da.File + ", the two poses and " + Path.GetFileName(pair.SceneFlowFile) +
                            " put them in frame b (worst " + DatasetCheckResult.Number(cam.Worst, "0.##") + " px off; allowed: the depth's tolerance + " + DatasetCheckResult.Number(FlowPairCheck.FlowSlackPixels) + " px), above " + CheckFigures.Percent(MaxBadShare) +
                            ": the flow's sign or axes (dx, dy) are wrong, or it is of another pair or time step."));
                }
                if (db != null)
                {
                    var occ = FlowPairCheck.Occlusion(files, da, db, va.Camera, vb.Camera, stride, out var visibleBad, out var hiddenBad);
                    if (occ.Judged >= MinJudged)
                    {
                        _judgedOcclusion++;
                        _worstOcclusion = Math.Max(_worstOcclusion, occ.Share);
                        if (occ.Share > MaxBadShare)
                            found.Add((pair.OccludedFile, CheckFigures.Percent(occ.Share) + " of " + occ.Judged + " pixels disagree with " + db.File + ": " + visibleBad + " marked visible where frame b's depth is not the point's, " + hiddenBad +
                                " marked occluded where nothing nearer is in front of it; above " + CheckFigures.Percent(MaxBadShare) + ": the mask is inverted or of another pair."));
                    }
                }
            }
            if (hasReverse)
            {
                var reverse = new FlowPair(pair.Video, pair.To, pair.From);
                var back = FlowPairFiles.Read(_root, reverse, false, w, h);
                if (back.Complete)
                {
                    var residuals = new List<double>();
                    var inv = FlowPairCheck.Inverse(files, back, db, w, h, stride, residuals);
                    if (inv.Judged >= MinJudged)
                    {
                        _judgedInverse++;
                        _worstInverse = Math.Max(_worstInverse, inv.Share);
                        if (inv.Share > MaxInverseBadShare)
                            found.Add((pair.FlowFile, CheckFigures.Percent(inv.Share) + " of " + inv.Judged + " pixels visible both ways do not come back through " + reverse.FlowFile + " (|forward + backward| > " +
                                DatasetCheckResult.Number(FlowPairCheck.InversePixels) + " px + ¼ of the backward flow's spread over the 4 pixels it is read from; median " + DatasetCheckResult.Number(CheckFigures.Median(residuals), "0.###") + " px), above " + CheckFigures.Percent(MaxInverseBadShare) +
                                ": one of the two has its sign or axes wrong, or is of another pair."));
                    }
                }
            }
            return found;
        }

        static string Normal(string relative) => relative?.Replace('\\', '/').TrimStart('.', '/');

        public DatasetCheckResult Finish()
        {
            if (_recordedButMissing != null)
                return new DatasetCheckResult(CheckName, DatasetCheckStatus.Failed, "no " + FlowLayout.RecordFile, "every recorded flow file present", "1 problem(s)");
            if (_skip != null && _structureProblems == 0) return DatasetCheckResult.Skip(CheckName, _skip);
            var figure = (_pairs - _skippedPairs) + " pairs; worst pair: " + CheckFigures.Percent(_worstCamera) + " off depth and poses (" + _judgedCamera + " judged), " +
                         CheckFigures.Percent(_worstInverse) + " off forward ∘ backward (" + _judgedInverse + "), " + CheckFigures.Percent(_worstOcclusion) + " against b's depth (" + _judgedOcclusion + "), " +
                         CheckFigures.Percent(_worstSurface) + " NaN vs depth";
            var threshold = "≤ " + CheckFigures.Percent(MaxBadShare) + " of each pair's pixels off (depth ± tolerance + " + DatasetCheckResult.Number(FlowPairCheck.FlowSlackPixels) + " px; 1 % depth), ≤ " +
                            CheckFigures.Percent(MaxInverseBadShare) + " off forward ∘ backward (" + DatasetCheckResult.Number(FlowPairCheck.InversePixels) + " px + ¼ local spread), ≤ " + CheckFigures.Percent(MaxSurfaceMismatch) + " NaN vs depth, files complete, masks 0/255";
            var failed = _badPairs > 0 || _structureProblems > 0;
            return new DatasetCheckResult(CheckName, failed ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed, figure, threshold,
                failed ? _badPairs + " pair(s) with problems" : _skippedPairs > 0 ? _skippedPairs + " pairs not checked (their views were not)" : null);
        }

        /// <summary>The last few frames' depths: a video's pairs run through its frames in order, so each is read about once.</summary>
        sealed class DepthCache
        {
            const int Keep = 4;
            readonly string _root;
            readonly List<KeyValuePair<string, FlowCheckDepth>> _entries = new List<KeyValuePair<string, FlowCheckDepth>>();

            public DepthCache(string root) { _root = root; }

            public FlowCheckDepth Get(string image, CheckView view)
            {
                foreach (var e in _entries) if (e.Key == image) return e.Value;
                var depth = FlowCheckDepth.Read(_root, image, view);
                _entries.Add(new KeyValuePair<string, FlowCheckDepth>(image, depth));
                if (_entries.Count > Keep) _entries.RemoveAt(0);
                return depth;
            }
        }
    }
}
