using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The time of every view of a dynamic capture.
    /// <list type="bullet">
    /// <item>Monocular (N train views): train view i is step i of N, at normalised time i/(N − 1). Val and test view 0
    /// is at time 0 (D-NeRF's load_blender.py asserts that every split starts at time 0); view j ≥ 1 of M is halfway
    /// between two train steps: k = ⌊(j − ½)(N − 1)/(M − 1)⌋, time (k + ½)/(N − 1), so test times are never train times.</item>
    /// <item>Multi-view (T steps, C cameras in a split): view k·C + c is camera c of the split's formation at step k.</item>
    /// </list>
    /// Frames are written in view order, so times never decrease within a split (per camera in multi-view).
    /// </summary>
    public static class TimePlanning
    {
        /// <summary>One planned view: its index in the split (the file's <c>r_i</c>), the formation camera it uses and its time.</summary>
        public readonly struct Slot
        {
            public Slot(int index, int camera, ViewTime? time)
            {
                Index = index;
                Camera = camera;
                Time = time;
            }

            public int Index { get; }
            public int Camera { get; }
            public ViewTime? Time { get; }
        }

        /// <summary>
        /// Problems only a known clip length shows (the settings' own are <see cref="TimeSettingsValidator"/>'s):
        /// an end at the clip's length where it is unknown, a frame rate that gives fewer than 2 steps or a count that
        /// disagrees with a monocular train split, and multi-view splits with more views than a split may hold.
        /// </summary>
        /// <param name="clipLengthSeconds">The target's longest clip or Timeline in seconds (0 when unknown, as in the headless tool).</param>
        public static IReadOnlyList<ValidationProblem> Check(DatasetSettings settings, double clipLengthSeconds)
        {
            var problems = new List<ValidationProblem>();
            Resolve(settings, clipLengthSeconds, problems);
            return problems;
        }

        /// <summary>The resolved range, or null for a static capture; throws <see cref="InvalidParameterException"/> when <see cref="Check"/> finds problems.</summary>
        public static TimeRange Resolve(DatasetSettings settings, double clipLengthSeconds)
        {
            var problems = new List<ValidationProblem>();
            var range = Resolve(settings, clipLengthSeconds, problems);
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            return range;
        }

        static TimeRange Resolve(DatasetSettings settings, double clipLength, List<ValidationProblem> problems)
        {
            var time = settings.Time;
            if (time == null || !time.Enabled) return null;
            var start = time.StartSeconds;
            var end = time.EndSeconds;
            if (time.EndAtClipLength)
            {
                if (!(clipLength > 0) || double.IsInfinity(clipLength))
                {
                    problems.Add(new ValidationProblem("time.end", "\"clip\"",
                        "needs the length of the target's clips or Timeline, which is unknown: the target has no clip, Timeline or particle system with a length among time.sources, or this is the headless tool, which does not open the scene.",
                        "Give the end time in seconds, or animate the target (in Unity)."));
                    return null;
                }
                end = clipLength;
                if (end <= start)
                {
                    problems.Add(new ValidationProblem("time.start", ValidationProblem.Format(start),
                        "is not before the clip's end (" + ValidationProblem.Format(end) + " s), so there is no time range to capture.",
                        "Use a start below " + ValidationProblem.Format(end) + " seconds."));
                    return null;
                }
            }
            if (!(end > start)) return null; // the settings' own problem, reported by TimeSettingsValidator

            int steps;
            if (time.Fps > 0)
            {
                // The frames at start + k/fps that lie in [start, end]; the tolerance keeps 2·(1/30) from losing its last frame to rounding.
                var frames = Math.Floor((end - start) * time.Fps + 1e-9);
                if (frames > TimeSettings.MaxSteps)
                {
                    problems.Add(new ValidationProblem("time.fps", ValidationProblem.Format(time.Fps),
                        "gives " + ValidationProblem.Format(frames + 1) + " time steps over " + ValidationProblem.Format(end - start) + " s, more than " + TimeSettings.MaxSteps + ".",
                        "Lower the frame rate or shorten the range."));
                    return null;
                }
                steps = (int)frames + 1;
                if (steps < 2)
                {
                    problems.Add(new ValidationProblem("time.fps", ValidationProblem.Format(time.Fps),
                        "gives a single frame between time.start and the end (" + ValidationProblem.Format(end - start) + " s apart).",
                        "Use at least " + ValidationProblem.Format(1 / (end - start)) + " frames per second, or give time.steps."));
                    return null;
                }
                end = start + (steps - 1) / time.Fps;
            }
            else if (time.Mode == TimeMode.Monocular && time.Steps == 0) steps = settings.Train.Count;
            else steps = time.Steps;
            var trainSource = settings.Train.Source;
            if (time.Mode == TimeMode.Monocular && trainSource != null && !trainSource.IsFormation && !trainSource.IsVolume)
            {
                // Imported or scene cameras: the split's count is theirs (CameraSourcePlanning.Resolved), which
                // TimeSettingsValidator could not see, so the monocular rule is checked here.
                var cameras = settings.Train.Count;
                if (cameras < 2 || time.Steps > 0 && time.Steps != cameras)
                {
                    problems.Add(new ValidationProblem("splits.train.source", cameras + (cameras == 1 ? " camera" : " cameras"),
                        cameras < 2
                            ? "is fewer than 2 train views; a monocular capture has one train view per time step."
                            : "differ from time.steps (" + time.Steps + "); a monocular capture has exactly one train view per time step.",
                        cameras < 2 ? "Import a file with at least 2 train cameras (D-NeRF's scenes have 50 to 200)." : "Set time.steps to 0 (the cameras decide) or to " + cameras + "."));
                    return null;
                }
            }
            if (steps < 2) return null; // reported by TimeSettingsValidator

            if (time.Mode == TimeMode.Monocular && steps != settings.Train.Count)
            {
                problems.Add(new ValidationProblem("splits.train.count", settings.Train.Count.ToString(CultureInfo.InvariantCulture),
                    "differs from the " + steps + " time steps of time.fps " + ValidationProblem.Format(time.Fps) + " over " +
                    ValidationProblem.Format(start) + "–" + ValidationProblem.Format(time.EndAtClipLength ? clipLength : time.EndSeconds) +
                    " s; a monocular capture has one train view per time step.",
                    "Set splits.train.count to " + steps + ", or give time.steps instead of a frame rate."));
                return null;
            }
            if (time.Mode == TimeMode.MultiView)
                foreach (var split in DatasetSplits.All)
                {
                    var count = settings.Split(split).Count;
                    if ((long)count * steps > DatasetSettings.MaxViews)
                        problems.Add(new ValidationProblem("splits." + DatasetSplits.Name(split) + ".count", count.ToString(CultureInfo.InvariantCulture),
                            "× " + steps + " time steps is " + ((long)count * steps) + " views, more than the " + DatasetSettings.MaxViews + " a split may hold.",
                            "Use fewer cameras or fewer time steps."));
                }
            if (problems.Count > 0) return null;
            return new TimeRange(time.Mode, time.Sources, start, end, steps, time.Fps);
        }

        /// <summary>The views of a split whose formation places <paramref name="cameras"/> cameras (the split's count), in file order.</summary>
        public static IReadOnlyList<Slot> Slots(TimeRange range, DatasetSplit split, int cameras)
        {
            var count = SlotCount(range, cameras);
            var slots = new Slot[count];
            for (var i = 0; i < count; i++) slots[i] = SlotAt(range, split, cameras, i);
            return slots;
        }

        /// <summary>The number of <see cref="Slots"/>: the cameras, times the steps in a multi-view capture.</summary>
        public static int SlotCount(TimeRange range, int cameras) =>
            range != null && range.Mode == TimeMode.MultiView ? range.Steps * cameras : cameras;

        /// <summary>
        /// Slot <paramref name="index"/> of <see cref="Slots"/> alone, in constant time (a plan regenerates its views on
        /// demand): in a multi-view capture view k·C + c is camera c at step k; otherwise view j is camera j.
        /// </summary>
        public static Slot SlotAt(TimeRange range, DatasetSplit split, int cameras, int index)
        {
            if (range == null) return new Slot(index, index, null);
            if (range.Mode == TimeMode.MultiView)
            {
                var k = index / cameras;
                var c = index - k * cameras;
                return new Slot(index, c, range.AtStep(k, c));
            }
            return new Slot(index, index, MonocularTime(range, split, index, cameras));
        }

        static ViewTime MonocularTime(TimeRange range, DatasetSplit split, int j, int views)
        {
            if (split == DatasetSplit.Train || j == 0) return range.AtStep(split == DatasetSplit.Train ? j : 0, -1);
            var gaps = range.Steps - 1;
            var k = (int)Math.Floor((j - 0.5) * gaps / (views - 1));
            if (k > gaps - 1) k = gaps - 1;
            var u = (k + 0.5) / gaps;
            return new ViewTime(u, range.SecondsAt(u), -1, -1);
        }

        /// <summary>The number of views a split holds: its count, times the steps in a multi-view capture.</summary>
        public static int ViewCount(DatasetSettings settings, TimeRange range, DatasetSplit split)
        {
            var count = settings.Split(split).Count;
            return range != null && range.Mode == TimeMode.MultiView ? count * range.Steps : count;
        }
    }
}
