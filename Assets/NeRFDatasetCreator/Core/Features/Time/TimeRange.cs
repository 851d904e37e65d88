using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The resolved time span of a dynamic capture: <see cref="Steps"/> evenly spaced steps from
    /// <see cref="StartSeconds"/> to <see cref="EndSeconds"/>, both included. Step k is at
    /// start + k·(end − start)/(steps − 1) seconds and at normalised time k/(steps − 1); with a frame rate,
    /// end = start + (steps − 1)/fps, so step k is at start + k/fps exactly.
    /// </summary>
    public sealed class TimeRange
    {
        public TimeRange(TimeMode mode, TimeSources sources, double startSeconds, double endSeconds, int steps, double fps)
        {
            if (steps < 2) throw new ArgumentOutOfRangeException(nameof(steps), steps, "a time range has at least 2 steps");
            Mode = mode;
            Sources = sources;
            StartSeconds = startSeconds;
            EndSeconds = endSeconds;
            Steps = steps;
            Fps = fps;
        }

        public TimeMode Mode { get; }
        public TimeSources Sources { get; }
        public double StartSeconds { get; }

        /// <summary>The last step's time (with a frame rate, the last frame at or before the requested end).</summary>
        public double EndSeconds { get; }

        public int Steps { get; }

        /// <summary>The frame rate that set the steps, or 0 when a step count did.</summary>
        public double Fps { get; }

        /// <summary>Step k's normalised time, k/(steps − 1).</summary>
        public double NormalisedOf(int step) => step / (double)(Steps - 1);

        /// <summary>Step k's content time: start + k/fps with a frame rate, else start + (end − start)·k/(steps − 1).</summary>
        public double SecondsOf(int step) => Fps > 0 ? StartSeconds + step / Fps : StartSeconds + (EndSeconds - StartSeconds) * step / (Steps - 1);

        /// <summary>The content time of a normalised time u: start + u·(end − start).</summary>
        public double SecondsAt(double normalised) => StartSeconds + (EndSeconds - StartSeconds) * normalised;

        public ViewTime AtStep(int step, int camera) => new ViewTime(NormalisedOf(step), SecondsOf(step), step, camera);
    }
}
