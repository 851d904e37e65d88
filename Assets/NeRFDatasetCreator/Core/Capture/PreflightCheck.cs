using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The calibration capture run before a large capture (issue 21, "Preflight"): a handful of the plan's own views —
    /// a shard of it, so the same poses, splits, passes, background and target, spread round-robin over every split
    /// and formation (<see cref="ShardAssignment"/>) — at low resolution, into a temporary folder, checked with
    /// <see cref="DatasetCheck"/>. A broken pipeline then fails in seconds with the check's words instead of after
    /// thousands of views. What is decided here is engine-free; the Unity layer renders it.
    /// </summary>
    public static class PreflightCheck
    {
        /// <summary>Captures of more views than this are preceded by the calibration capture ("more than a few dozen").</summary>
        public const int MinViews = 48;

        /// <summary>About this many views are rendered (see <see cref="Shard"/>).</summary>
        public const int Views = 12;

        /// <summary>The calibration images' longer side, in pixels (the aspect ratio is kept, so the intrinsics are the plan's scaled).</summary>
        public const int LongSide = 160;

        /// <summary>At most this many points in the calibration's points3d.ply (enough for the point-cloud check).</summary>
        public const int MaxPoints = 20000;

        /// <summary>The folder names the calibration captures are written under, inside the system's temporary folder.</summary>
        public const string FolderPrefix = "nerf-preflight-";

        /// <summary>Whether a capture of <paramref name="plannedViews"/> views with these settings is preceded by a calibration capture.</summary>
        public static bool Needed(DatasetSettings settings, int plannedViews) =>
            settings != null && settings.Preflight && plannedViews > MinViews;

        /// <summary>
        /// The shard of the plan the calibration renders, given the plan's views per split: shard 0 of N, which takes
        /// every N-th view of the plan (train, then val, then test). N = ⌊views / <see cref="Views"/>⌋, or the smallest
        /// non-empty split's size when that costs at most 4 × <see cref="Views"/> views, so that every split — and the
        /// passes it writes — is in the calibration; a split smaller than N may otherwise have no view in it.
        /// </summary>
        public static ShardSpec Shard(params int[] viewsPerSplit)
        {
            var total = 0;
            var smallest = int.MaxValue;
            foreach (var count in viewsPerSplit)
            {
                total += Math.Max(0, count);
                if (count > 0) smallest = Math.Min(smallest, count);
            }
            var n = total / Views;
            if (smallest < n && total / smallest <= 4 * Views) n = smallest;
            return new ShardSpec(0, Math.Max(1, Math.Min(ShardSpec.MaxCount, n)));
        }

        /// <summary>
        /// The calibration's settings: a copy of <paramref name="settings"/> at <see cref="LongSide"/> pixels on the longer
        /// side (same aspect ratio within a pixel, so the same fields of view), at most <see cref="MaxPoints"/> points,
        /// the geometry pack at the start time only (not every step), named <paramref name="name"/> under <paramref name="folder"/>, never overwriting, and without a preflight of its own.
        /// </summary>
        public static DatasetSettings CalibrationSettings(DatasetSettings settings, string folder, string name)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            var s = settings.Clone();
            if (s.Width > 0 && s.Height > 0 && Math.Max(s.Width, s.Height) > LongSide)
            {
                var scale = (double)LongSide / Math.Max(s.Width, s.Height);
                s.Width = Math.Max(8, (int)Math.Round(s.Width * scale));
                s.Height = Math.Max(8, (int)Math.Round(s.Height * scale));
            }
            s.PointCloudPoints = Math.Min(s.PointCloudPoints, MaxPoints);
            // The per-step geometry pack poses and reads the target once per time step: the calibration writes only the
            // start mesh (its check reads no more), and the Unity layer estimates the full pack's time instead (review R4-6).
            s.GeometryPackEveryStep = false;
            s.OutputFolder = folder;
            s.Name = name;
            s.Overwrite = OverwritePolicy.Never;
            s.Preflight = false;
            return s;
        }
    }
}
