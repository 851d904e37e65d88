using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Threading;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset check</c> and the capture's self-check (issue 21): decodes a Blender-format dataset's images and
    /// checks that colour alpha, masks, depth, normals, poses, intrinsics and the point cloud agree with each other.
    /// Every check is one class in this folder; Documentation~/check.md describes each, its threshold and what a failure
    /// usually means. Checks whose inputs are missing are skipped with the reason.
    /// </summary>
    public static class DatasetCheck
    {
        public const string ReportFileName = "check_report.json";

        /// <summary>Decoded depth maps kept for the multi-view pass (each 2 bytes a pixel); more are decoded again when needed.</summary>
        const long DepthCacheBytes = 64L << 20;

        /// <summary>
        /// Checks <paramref name="datasetFolder"/>. Never throws for a bad dataset: what cannot be read is a problem in the
        /// report. <paramref name="progress"/> is called from the calling thread with (steps done, steps total): one step
        /// per view, and one more per view in the multi-view pass when there is one.
        /// </summary>
        public static DatasetCheckReport Run(string datasetFolder, DatasetCheckOptions options, Action<int, int> progress = null, CancellationToken cancel = default)
        {
            var started = Stopwatch.GetTimestamp();
            var report = new DatasetCheckReport(datasetFolder);
            options = options ?? new DatasetCheckOptions();
            if (string.IsNullOrEmpty(datasetFolder) || !Directory.Exists(datasetFolder))
            {
                report.Add(new DatasetProblem(CheckDatasetReader.CheckName, datasetFolder ?? "", -1, "is not an existing folder."));
                return report;
            }
            var root = Path.GetFullPath(datasetFolder);
            var read = CheckDatasetReader.Read(root, options);
            foreach (var p in read.Problems) report.Add(p);
            var views = read.Views;
            if (views.Count == 0 && read.Problems.Count == 0)
                report.Add(new DatasetProblem(CheckDatasetReader.CheckName, DatasetLayout.TransformsFileName(options.Split ?? "train"), -1,
                    "has no frames to check (is this a Blender-format dataset with transforms_*.json?)."));

            var dynamic = views.Any(v => v.Time != null);
            var config = DatasetConfig.Read(root);
            var geometryPack = new GeometryPackDepthCheck(root, config, dynamic);
            var checks = new List<IViewCheck>
            {
                // A capture over a solid background (or the sky) has alpha 255 everywhere by design.
                new AlphaMaskCheck(config.Config?.OpaqueBackground == true),
                new DepthMaskCheck(),
                new DepthNormalsCheck(),
                PointCloud(root, config, dynamic),
                new ColourGeometryCheck(),
                new StraightAlphaCheck(),
                InstanceMaskCheck.For(root, views),
                new ExposureCheck(root),
                new HdrCheck(root),
                new MaterialPassCheck(root, config.Config),
                new MotionBlurCheck(),
                new RelightCheck(root, config.Config),
                geometryPack,
            };
            var multiView = new MultiViewGeometryCheck();
            var reprojection = new InstanceReprojectionCheck();
            var cache = new DepthCache(DepthCacheBytes);
            var idCache = new DepthCache(DepthCacheBytes);
            long decodeTicks = 0;
            var intrinsicsReported = new HashSet<string>();
            var total = views.Count * (views.Any(v => v.DepthFile != null) ? 2 : 1);
            var done = 0;
            var decoded = 0;
            foreach (var view in views)
            {
                if (cancel.IsCancellationRequested) { report.Cancelled = true; break; }
                var images = CheckImages.Load(root, view);
                decodeTicks += images.DecodeTicks;
                foreach (var note in images.Notes) report.Add(note);
                if (images.HasColour)
                {
                    decoded++;
                    var problem = CheckDatasetReader.Complete(view, images.Width, images.Height);
                    if (problem != null && intrinsicsReported.Add(view.Split)) report.Add(problem);
                    var found = new List<DatasetProblem>();
                    foreach (var check in checks)
                    {
                        var before = Stopwatch.GetTimestamp();
                        check.View(view, images, found);
                        Time(report, check.Name, before);
                    }
                    foreach (var p in found) report.Add(p);
                    if (images.Depth != null) cache.Put(view.Number, images.Depth);
                    else view.DepthFile = null; // unusable: leave it out of the multi-view pass
                    if (images.Instance != null) idCache.Put(view.Number, images.Instance);
                    else view.InstanceFile = null;
                }
                progress?.Invoke(++done, total);
            }

            string multiSkip = null;
            if (report.Cancelled) multiSkip = "cancelled";
            else if (!views.Any(v => v.DepthFile != null && v.Camera != null)) multiSkip = "no view has a depth PNG (nerf_synthetic has no metric depth)";
            else
            {
                var pairs = MultiViewGeometryCheck.Pairs(views);
                if (pairs.Count == 0 && dynamic) multiSkip = "no two views with depth share a time (a monocular dynamic capture has one view per time)";
                var byView = pairs.GroupBy(p => p.Key).ToList();
                var found = new List<DatasetProblem>();
                foreach (var group in byView)
                {
                    if (cancel.IsCancellationRequested) { report.Cancelled = true; multiSkip = "cancelled"; break; }
                    var a = Depth(root, views[group.Key], cache, idCache, ref decodeTicks);
                    foreach (var pair in group)
                    {
                        var b = Depth(root, views[pair.Value], cache, idCache, ref decodeTicks);
                        var before = Stopwatch.GetTimestamp();
                        if (a != null && b != null) multiView.Pair(views[pair.Key], a, views[pair.Value], b, found);
                        Time(report, MultiViewGeometryCheck.CheckName, before);
                        if (a == null || b == null || views[pair.Key].InstanceFile == null || views[pair.Value].InstanceFile == null) continue;
                        var ia = Ids(root, views[pair.Key], cache, idCache, ref decodeTicks);
                        var ib = Ids(root, views[pair.Value], cache, idCache, ref decodeTicks);
                        before = Stopwatch.GetTimestamp();
                        if (ia != null && ib != null) reprojection.Pair(views[pair.Key], a, ia, views[pair.Value], b, ib, found);
                        Time(report, InstanceReprojectionCheck.CheckName, before);
                    }
                    progress?.Invoke(++done, total);
                }
                foreach (var p in found) report.Add(p);
            }
            // Issue 37's flow/, judged pair by pair against the views' depth and poses (only when the dataset has flow).
            var flow = report.Cancelled ? null : FlowCheck.For(root, config);
            if (flow != null)
            {
                var found = new List<DatasetProblem>();
                var before = Stopwatch.GetTimestamp();
                flow.Run(views, found, cancel);
                Time(report, FlowCheck.CheckName, before);
                foreach (var p in found) report.Add(p);
            }
            progress?.Invoke(total, total);
            foreach (var p in geometryPack.PackProblems) report.Add(p);
            var recordProblems = new List<DatasetProblem>();
            var records = RecordsCheck.Run(root, config, recordProblems);
            foreach (var p in recordProblems) report.Add(p);

            report.Add(new DatasetCheckResult(CheckDatasetReader.CheckName,
                read.Problems.Count > 0 || decoded < views.Count ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed,
                decoded + " of " + views.Count + " views decoded" + (options.Split != null ? " (split " + options.Split + ")" : "") + (dynamic ? ", dynamic (" + views.Select(v => v.Time).Distinct().Count() + " times)" : ""),
                "every frame readable, one camera_angle_x, rigid poses", null));
            foreach (var check in checks.Take(3)) report.Add(check.Finish());
            report.Add(multiView.Finish(multiSkip));
            foreach (var check in checks.Skip(3)) report.Add(check.Finish());
            report.Add(reprojection.Finish(multiSkip ?? (views.Any(v => v.InstanceFile != null) ? null : "no view has an instance map (a capture without labels)")));
            report.Add(records);
            if (flow != null) report.Add(flow.Finish());
            report.ViewsChecked = decoded;
            report.DecodeSeconds = decodeTicks / (double)Stopwatch.Frequency;
            report.TotalSeconds = (Stopwatch.GetTimestamp() - started) / (double)Stopwatch.Frequency;
            return report;
        }

        static void Time(DatasetCheckReport report, string check, long since)
        {
            report.CheckSeconds.TryGetValue(check, out var seconds);
            report.CheckSeconds[check] = seconds + (Stopwatch.GetTimestamp() - since) / (double)Stopwatch.Frequency;
        }

        static ushort[] Depth(string root, CheckView view, DepthCache cache, DepthCache idCache, ref long decodeTicks)
        {
            var depth = cache.Get(view.Number);
            if (depth != null) return depth;
            return Decode(root, view, cache, idCache, ref decodeTicks).Depth;
        }

        /// <summary>The view's instance map, from the cache or decoded again (with its depth).</summary>
        static ushort[] Ids(string root, CheckView view, DepthCache cache, DepthCache idCache, ref long decodeTicks)
        {
            var ids = idCache.Get(view.Number);
            if (ids != null) return ids;
            return Decode(root, view, cache, idCache, ref decodeTicks).Instance;
        }

        static CheckImages Decode(string root, CheckView view, DepthCache cache, DepthCache idCache, ref long decodeTicks)
        {
            var images = CheckImages.Load(root, view, depthOnly: true);
            decodeTicks += images.DecodeTicks;
            if (images.Depth != null) cache.Put(view.Number, images.Depth);
            if (images.Instance != null) idCache.Put(view.Number, images.Instance);
            return images;
        }

        static IViewCheck PointCloud(string root, DatasetConfigFile config, bool dynamic)
        {
            if (!File.Exists(Path.Combine(root, PointCloudOwnership.FileName))) return new PointCloudMaskCheck(null, "the dataset has no " + PointCloudOwnership.FileName);
            var warnings = new List<ValidationProblem>();
            if (!PointCloudOwnership.IsOwn(root, config, warnings))
                return new PointCloudMaskCheck(null, PointCloudOwnership.FileName + " is not this plugin's (no matching record in " + DatasetLayout.ConfigFileName + "): a foreign cloud, e.g. 3DGS's random one, is not the target's surface");
            if (dynamic) return new PointCloudMaskCheck(null, "a dynamic dataset: the cloud is sampled once, and moving content leaves it");
            try
            {
                return new PointCloudMaskCheck(PlyReader.Read(Path.Combine(root, PointCloudOwnership.FileName)), null);
            }
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is InvalidParameterException)
            {
                return new PointCloudMaskCheck(null, PointCloudOwnership.FileName + " cannot be read: " + e.Message);
            }
        }
    }
}
