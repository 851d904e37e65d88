using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>One exported image of a Nerfies-family layout: its id (file stem), camera id and integer time id.</summary>
    public sealed class NerfiesView
    {
        public NerfiesView(ExportFrame frame, bool train, int cameraId, int timeId)
        {
            Frame = frame;
            Train = train;
            CameraId = cameraId;
            TimeId = timeId;
            Id = cameraId.ToString(CultureInfo.InvariantCulture) + "_" + timeId.ToString("D5", CultureInfo.InvariantCulture);
        }

        public ExportFrame Frame { get; }

        /// <summary>In <c>train_ids</c> (our train split), else in <c>val_ids</c> (our test split).</summary>
        public bool Train { get; }

        public int CameraId { get; }

        /// <summary>metadata.json's <c>warp_id</c> (and <c>appearance_id</c>): the frame's time on <see cref="NerfiesViews.Grid"/>'s integer grid.</summary>
        public int TimeId { get; }

        /// <summary>"&lt;camera id&gt;_&lt;time id, 5 digits&gt;", as DyCheck's iPhone sequences name their frames (iphone.py:722, 742).</summary>
        public string Id { get; }
    }

    /// <summary>
    /// Which frames a Nerfies-family export writes, with their integer ids. <c>warp_id</c> is an integer embedding
    /// index in Nerfies (nerfies/models.py:125–127, <c>max(warp_ids) + 1</c> embeddings) and 4DGaussians takes the time
    /// as <c>warp_id / max(warp_id)</c> (hyper_loader.py:79–81), so every distinct time gets its own id on the coarsest
    /// integer grid that holds all of them: time id = t·L for the smallest L with every t·L whole (<see cref="Grid"/>).
    /// A multi-view capture of K steps gives L = K − 1 (id = time_step); a monocular one, whose val/test views sit
    /// halfway between train steps, L = 2(N − 1). With the last time at 1, 4DGaussians' warp_id / max is the time itself.
    /// Camera ids: a multi-view capture's train cameras are their <c>camera_id</c>s, the test cameras follow them;
    /// monocular: train 0, test 1.
    /// </summary>
    public static class NerfiesViews
    {
        /// <summary>The largest grid searched: a dataset's times on a finer grid (or none) are refused.</summary>
        public const int MaxGrid = 100000;

        const double Tolerance = 1e-7;

        /// <summary>The smallest L ≤ <see cref="MaxGrid"/> with every time·L within 1e-7 of a whole number; null when there is none.</summary>
        public static int? Grid(IEnumerable<double> times)
        {
            var distinct = times.Distinct().ToList();
            for (var l = 1; l <= MaxGrid; l++)
                if (distinct.All(t => OnGrid(t, l))) return l;
            return null;
        }

        /// <summary>Whether <paramref name="time"/>·<paramref name="grid"/> is a whole number (to 1e-7).</summary>
        public static bool OnGrid(double time, int grid) => Math.Abs(time * grid - Math.Round(time * grid)) <= Tolerance;

        /// <summary>
        /// The train views and then the test views of a dynamic <paramref name="scene"/>. With
        /// <paramref name="testOnTrainTimes"/> (DyCheck: time ids index the train frames) the grid is the train split's and a
        /// test view whose time is between two train times is left out and counted in <paramref name="dropped"/>;
        /// otherwise the grid holds both splits. Refuses a static dataset, a frame without time and two views of one
        /// camera at one time, each in one line naming what is missing.
        /// </summary>
        public static IReadOnlyList<NerfiesView> Of(ExportScene scene, ExportTarget target, bool testOnTrainTimes, out int grid, out int dropped)
        {
            var name = ExportTargets.Name(target);
            var train = scene.Split("train").ToList();
            var test = scene.Split("test").ToList();
            if (!scene.Frames.Any(f => f.Time.HasValue))
                throw Refuse("time", "none (a static dataset)",
                    "--to " + name + " writes a time-varying dataset: every image needs a time (metadata.json's warp_id), and no frame of this dataset has a time key.",
                    "Capture with time.mode \"monocular\" or \"multi-view\" (Documentation~/dynamic-capture.md), or convert to a static format.");
            if (train.Count == 0)
                throw Refuse("splits.train", "0 frames", "--to " + name + " trains on the train split (train_ids), and it is empty.", "Capture a train split.");
            var untimed = train.Concat(test).FirstOrDefault(f => !f.Time.HasValue);
            if (untimed != null)
                throw Refuse("time", untimed.ImagePath, "has no time key, but every image of --to " + name + " needs one (metadata.json's warp_id).",
                    "Re-capture the dataset in one time mode (nerf-dataset validate lists the frames).");
            var gridFrames = testOnTrainTimes ? train : train.Concat(test).ToList();
            var times = gridFrames.Select(f => f.Time.Value).ToList();
            if (times.Distinct().Count() < 2)
                throw Refuse("time", "one time (" + ValidationProblem.Format(times[0]) + ")",
                    "is the only time of the " + (testOnTrainTimes ? "train split" : "train and test splits") + ": --to " + name + " needs content that changes over time (4DGaussians divides by the largest warp_id, hyper_loader.py:80–81).",
                    "Capture with time.steps of at least 2.");
            var found = Grid(times);
            if (!found.HasValue)
                throw Refuse("time", times.Distinct().Count() + " distinct times",
                    "are not on a common grid of at most " + MaxGrid + " steps, so they have no integer warp_id each.",
                    "Capture with this plugin's time settings (evenly spaced steps).");
            grid = found.Value;

            var multiView = train.Concat(test).All(f => f.Timing.Camera.HasValue);
            var trainCameras = multiView ? train.Max(f => f.Timing.Camera.Value) + 1 : 1;
            var views = new List<NerfiesView>();
            dropped = 0;
            foreach (var (frames, isTrain) in new[] { (train, true), (test, false) })
                foreach (var f in frames)
                {
                    var t = f.Time.Value;
                    if (!OnGrid(t, grid))
                    {
                        dropped++;
                        continue;
                    }
                    var camera = multiView ? (isTrain ? 0 : trainCameras) + f.Timing.Camera.Value : (isTrain ? 0 : 1);
                    views.Add(new NerfiesView(f, isTrain, camera, (int)Math.Round(t * grid)));
                }
            var seen = new Dictionary<string, NerfiesView>();
            foreach (var v in views)
            {
                if (seen.TryGetValue(v.Id, out var first))
                    throw Refuse("file_path", v.Frame.ImagePath,
                        "is camera " + v.CameraId + " at time id " + v.TimeId + " again (" + first.Frame.ImagePath + " is too): a camera has one image per time.",
                        "Re-capture the split (nerf-dataset validate lists what is wrong).");
                seen[v.Id] = v;
            }
            return views;
        }

        internal static InvalidParameterException Refuse(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
