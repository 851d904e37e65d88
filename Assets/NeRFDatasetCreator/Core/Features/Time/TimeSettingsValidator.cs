using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The problems of the "time" section that the settings alone show (<see cref="SettingsValidator"/> adds them);
    /// what needs the clip length measured in Unity is <see cref="TimePlanning.Check"/>'s.
    /// </summary>
    public static class TimeSettingsValidator
    {
        public static IReadOnlyList<ValidationProblem> Validate(DatasetSettings settings)
        {
            var problems = new List<ValidationProblem>();
            var time = settings.Time;
            if (time == null || time.Mode == TimeMode.Static) return problems;
            void Add(ValidationProblem p)
            {
                if (p != null) problems.Add(p);
            }
            if (!TimeModes.IsDefined(time.Mode))
            {
                Add(new ValidationProblem("time.mode", ((int)time.Mode).ToString(CultureInfo.InvariantCulture), "is not a time mode.", "Use one of " + TimeModes.NameList() + "."));
                return problems;
            }
            if ((time.Sources & TimeSources.All) == TimeSources.None)
                Add(new ValidationProblem("time.sources", "[]", "is empty, so nothing would move between time steps.",
                    "List what drives time, from " + TimeSourceNames.NameList() + "."));
            Add(ValidationProblem.OutsideRange("time.start", time.StartSeconds, 0, TimeSettings.MaxSeconds, "seconds"));
            if (!time.EndAtClipLength)
            {
                var end = ValidationProblem.OutsideRange("time.end", time.EndSeconds, 0, TimeSettings.MaxSeconds, "seconds");
                Add(end);
                if (end == null && IsFinite(time.StartSeconds) && time.EndSeconds <= time.StartSeconds)
                    Add(new ValidationProblem("time.end", ValidationProblem.Format(time.EndSeconds),
                        "is not after time.start (" + ValidationProblem.Format(time.StartSeconds) + "), so there is no time range to capture.",
                        "Make time.end larger than time.start, or use \"clip\" for the clip's length."));
            }
            Add(ValidationProblem.OutsideRange("time.steps", time.Steps, 0, TimeSettings.MaxSteps));
            Add(ValidationProblem.OutsideRange("time.fps", time.Fps, 0, TimeSettings.MaxFps, "frames per second"));
            if (time.Steps > 0 && time.Fps > 0)
                Add(new ValidationProblem("time.fps", ValidationProblem.Format(time.Fps),
                    "is given together with time.steps (" + time.Steps + "); only one of them may set the time steps.",
                    "Set time.fps to 0 to use the step count, or time.steps to 0 to use the frame rate."));
            if (time.Steps == 1)
                Add(new ValidationProblem("time.steps", "1", "is a single time step: there is no motion to capture.",
                    "Use 2 or more steps, or time.mode \"static\"."));

            var train = settings.Train?.Count ?? 0;
            // Cameras imported from a file or taken from the scene give the split its views; its count is not used
            // (camera-sources.md), so it is checked once the cameras are known (TimePlanning), not here.
            var trainSource = settings.Train?.Source;
            var countUsed = trainSource == null || trainSource.IsFormation || trainSource.IsVolume;
            if (time.Mode == TimeMode.Monocular && countUsed)
            {
                if (train < 2)
                    Add(new ValidationProblem("splits.train.count", train.ToString(CultureInfo.InvariantCulture),
                        "gives fewer than 2 train views; a monocular capture has one train view per time step.",
                        "Give the train split at least 2 views (D-NeRF's scenes have 50 to 200)."));
                else if (time.Steps > 0 && time.Steps != train)
                    Add(new ValidationProblem("time.steps", time.Steps.ToString(CultureInfo.InvariantCulture),
                        "differs from splits.train.count (" + train + "); a monocular capture has exactly one train view per time step.",
                        "Set time.steps to 0 (the train count decides) or to " + train + ", or set splits.train.count to " + time.Steps + "."));
            }
            else if (time.Mode == TimeMode.MultiView && time.Steps == 0 && !(time.Fps > 0))
                Add(new ValidationProblem("time.steps", "0",
                    "leaves the number of time steps open; a multi-view capture renders every camera at each of them.",
                    "Give time.steps (2 or more) or time.fps."));
            return problems;
        }

        static bool IsFinite(double v) => !double.IsNaN(v) && !double.IsInfinity(v);
    }
}
