using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset validate</c>'s checks of a dynamic dataset's time keys. With dataset_config.json's
    /// <c>time</c> record: every frame has <c>time</c> in [0, 1] and a <c>time_seconds</c> that the record's mapping
    /// gives; monocular splits start at time 0 (D-NeRF's load_blender.py line 99 asserts it) and never go back in
    /// time; multi-view splits hold every camera at every step, each camera's times rising. Without the record (any
    /// other tool's dataset), frames that carry <c>time</c> are checked for its range, for a first frame at 0, and for
    /// frames that lack it (4DGaussians and nerfstudio's dnerf parser index <c>frame["time"]</c> and would fail).
    /// </summary>
    public static class TimeDatasetChecks
    {
        /// <summary>How far time_seconds may be from the mapping, relative to the range (JSON keeps 17 digits).</summary>
        const double SecondsTolerance = 1e-9;

        /// <summary>
        /// Checks the frames' time keys against dataset_config.json's time record (or, for another tool's dataset, on
        /// their own). <paramref name="frames"/> holds per split what <see cref="Keep"/> kept of each frame, in order
        /// (DatasetValidator streams the transforms files and keeps only these); a split that is missing or
        /// unreadable is absent, as DatasetValidator has said so.
        /// </summary>
        /// <param name="config">The dataset's <c>dataset_config.json</c>, or null when it has none or it cannot be read.</param>
        public static void Check(DatasetConfig config, DatasetValidationReport report, IReadOnlyDictionary<DatasetSplit, IReadOnlyList<Kept>> frames)
        {
            var record = ReadRecord(config, report);
            foreach (var split in DatasetSplits.All)
            {
                if (!frames.TryGetValue(split, out var list)) continue;
                var file = DatasetLayout.TransformsFileName(split);
                if (record == null) CheckForeign(file, list, report);
                else CheckOwn(file, list, record, report, split);
            }
        }

        /// <summary>What the checks keep of one frame: its file_path and its time keys (<see cref="TimeKeys.Read"/>).</summary>
        public sealed class Kept
        {
            public readonly string FilePath;
            public readonly FrameTime Time;

            public Kept(string filePath, FrameTime time)
            {
                FilePath = filePath;
                Time = time;
            }
        }

        /// <summary>What <see cref="Keep"/> returns for a frame without time keys: one shared object.</summary>
        internal static readonly Kept NoTime = new Kept(null, FrameTime.None);

        /// <summary>
        /// What the checks need of one frame: its file_path and time keys — for every frame when the dataset has a time
        /// record (<paramref name="every"/>), otherwise only for frames with a time key; all others share one object,
        /// so a static dataset of 300 000 frames costs a reference each.
        /// </summary>
        public static Kept Keep(DatasetFrame frame, bool every)
        {
            if (frame == null || !frame.IsObject) return NoTime;
            if (!every && !frame.Time.Any) return NoTime;
            return new Kept(frame.FilePath, frame.Time);
        }

        /// <summary>A warning for <c>convert</c>: the formats it writes have no time, so a dynamic dataset loses it.</summary>
        public static ValidationProblem ConversionWarning(IEnumerable<FrameTime> train)
        {
            if (train == null || !train.Any(t => t.HasTime)) return null;
            return new ValidationProblem("time", "per-frame time keys",
                "are dropped: nerfstudio's, instant-ngp's and COLMAP's formats hold no time, so the export is a static dataset of moving content.",
                "Train dynamic methods on the Blender layout itself (D-NeRF, 4DGaussians, ns-train … dnerf-data), or convert a multi-view capture with --to dynamic3dgs; see Documentation~/dynamic-capture.md.");
        }

        sealed class Record
        {
            public TimeMode Mode;
            public double Start, End;
            public int Steps;
        }

        /// <summary>The config's time record when it is valid; null without one (an unreadable config is reported by validate's own read).</summary>
        static Record ReadRecord(DatasetConfig config, DatasetValidationReport report)
        {
            var time = config?.Time;
            if (time == null) return null;
            var record = new Record { Start = time.StartSeconds ?? 0, End = time.EndSeconds ?? 0, Steps = time.Steps ?? 0 };
            var ok = TimeModes.TryParse(time.Mode, out record.Mode) && record.Mode != TimeMode.Static;
            ok &= time.StartSeconds.HasValue && time.EndSeconds.HasValue;
            ok &= time.Steps.HasValue && record.Steps >= 2 && record.End > record.Start;
            if (!ok)
            {
                report.Problems.Add(DatasetProblem.Structure(DatasetLayout.ConfigFileName, -1, null,
                    "has a \"time\" record without a valid mode, startSeconds < endSeconds and steps ≥ 2; the frames' times cannot be checked against it."));
                return null;
            }
            return record;
        }

        static void CheckForeign(string file, IReadOnlyList<Kept> frames, DatasetValidationReport report)
        {
            var withTime = frames.Count(f => f.Time.HasTime);
            if (withTime == 0) return;
            if (withTime < frames.Count)
                report.Problems.Add(DatasetProblem.Structure(file, -1, null, (frames.Count - withTime) + " of " + frames.Count +
                    " frames have no \"time\" while the others do; 4DGaussians and nerfstudio's dnerf parser read frame[\"time\"] from every frame."));
            for (var i = 0; i < frames.Count; i++)
            {
                if (!frames[i].Time.HasTime) continue;
                if (!(frames[i].Time.Time is double t)) Problem(report, file, i, frames[i], "time is not a number.");
                else if (!(t >= 0 && t <= 1)) Problem(report, file, i, frames[i], "time = " + ValidationProblem.Format(t) + " is outside [0, 1].");
            }
            CheckStartsAtZero(file, frames, report);
        }

        static void CheckOwn(string file, IReadOnlyList<Kept> frames, Record record, DatasetValidationReport report, DatasetSplit split)
        {
            var times = new double?[frames.Count];
            for (var i = 0; i < frames.Count; i++)
            {
                var f = frames[i];
                if (!(f.Time.Time is double t))
                {
                    Problem(report, file, i, f, !f.Time.HasTime ? "has no \"time\", which every frame of a dynamic dataset needs." : "time is not a number.");
                    continue;
                }
                if (!(t >= 0 && t <= 1))
                {
                    Problem(report, file, i, f, "time = " + ValidationProblem.Format(t) + " is outside [0, 1].");
                    continue;
                }
                times[i] = t;
                var expected = record.Start + t * (record.End - record.Start);
                if (!(f.Time.Seconds is double seconds))
                    Problem(report, file, i, f, "has no number time_seconds (the content time this plugin records beside time).");
                else if (Math.Abs(seconds - expected) > SecondsTolerance * Math.Max(1, Math.Abs(record.End)))
                    Problem(report, file, i, f, "time_seconds = " + ValidationProblem.Format(seconds) + " but time " + ValidationProblem.Format(t) +
                        " maps to " + ValidationProblem.Format(expected) + " s (dataset_config.json's time record: " +
                        ValidationProblem.Format(record.Start) + "–" + ValidationProblem.Format(record.End) + " s).");
            }
            if (record.Mode == TimeMode.Monocular)
            {
                CheckStartsAtZero(file, frames, report);
                for (var i = 1; i < frames.Count; i++)
                    if (times[i].HasValue && times[i - 1].HasValue && times[i] < times[i - 1])
                        Problem(report, file, i, frames[i], "time = " + ValidationProblem.Format(times[i].Value) + " is before the previous frame's " +
                            ValidationProblem.Format(times[i - 1].Value) + "; a monocular capture's frames follow time.");
                if (split == DatasetSplit.Train && frames.Count > 0 && frames.Count != record.Steps)
                    report.Problems.Add(DatasetProblem.Structure(file, -1, null, "has " + frames.Count + " frames but dataset_config.json records " +
                        record.Steps + " time steps, one train view each."));
                return;
            }
            CheckMultiView(file, frames, times, record, report);
        }

        static void CheckMultiView(string file, IReadOnlyList<Kept> frames, double?[] times, Record record, DatasetValidationReport report)
        {
            var seen = new Dictionary<int, SortedSet<int>>();
            var last = new Dictionary<int, double>();
            for (var i = 0; i < frames.Count; i++)
            {
                var f = frames[i];
                if (!(f.Time.Camera is int camera) || !(f.Time.Step is int step))
                {
                    Problem(report, file, i, f, "has no whole-number camera_id and time_step, which a multi-view frame needs.");
                    continue;
                }
                if (camera < 0 || step < 0 || step >= record.Steps)
                {
                    Problem(report, file, i, f, "camera_id " + camera + " / time_step " + step + " is outside the " + record.Steps + " recorded steps.");
                    continue;
                }
                if (!seen.TryGetValue(camera, out var steps)) seen[camera] = steps = new SortedSet<int>();
                if (!steps.Add(step)) Problem(report, file, i, f, "repeats camera " + camera + " at step " + step + ".");
                if (!times[i].HasValue) continue;
                var stepTime = step / (double)(record.Steps - 1);
                if (Math.Abs(times[i].Value - stepTime) > 1e-12)
                    Problem(report, file, i, f, "time = " + ValidationProblem.Format(times[i].Value) + " is not step " + step + "'s time " + ValidationProblem.Format(stepTime) + ".");
                if (last.TryGetValue(camera, out var previous) && times[i].Value <= previous)
                    Problem(report, file, i, f, "camera " + camera + "'s time " + ValidationProblem.Format(times[i].Value) + " does not follow its previous frame's " +
                        ValidationProblem.Format(previous) + "; each camera's frames must rise in time.");
                last[camera] = times[i].Value;
            }
            var cameras = seen.Count == 0 ? 0 : seen.Keys.Max() + 1;
            var missing = new List<string>();
            var missingCount = 0;
            for (var c = 0; c < cameras; c++)
                for (var k = 0; k < record.Steps; k++)
                    if (!seen.TryGetValue(c, out var s) || !s.Contains(k))
                    {
                        missingCount++;
                        if (missing.Count < 5) missing.Add("camera " + c + " step " + k);
                    }
            if (missingCount > 0)
                report.Problems.Add(DatasetProblem.Structure(file, -1, null, missingCount + " (camera, step) pairs of " + cameras + " cameras × " + record.Steps +
                    " steps are missing (" + string.Join(", ", missing) + (missingCount > missing.Count ? ", …" : "") + "); multi-view methods need every camera at every step."));
        }

        static void CheckStartsAtZero(string file, IReadOnlyList<Kept> frames, DatasetValidationReport report)
        {
            if (frames.Count == 0 || !(frames[0].Time.Time is double first) || first == 0) return;
            Problem(report, file, 0, frames[0], "time = " + ValidationProblem.Format(first) + ", but D-NeRF's load_blender.py asserts that each split's first frame is at time 0.");
        }

        static void Problem(DatasetValidationReport report, string file, int index, Kept frame, string message) =>
            report.Problems.Add(DatasetProblem.Structure(file, index, frame.FilePath, message));

        static bool TryNumber(JToken token, out double value)
        {
            value = 0;
            if (token == null || (token.Type != JTokenType.Integer && token.Type != JTokenType.Float)) return false;
            value = Convert.ToDouble(((JValue)token).Value, CultureInfo.InvariantCulture);
            return true;
        }
    }
}
