using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The "time" section of the settings: what drives time, which span of it is captured, how finely, and how
    /// the cameras meet it. <see cref="TimeMode.Static"/> (the default) captures no time and writes no time keys, so
    /// static datasets are exactly as before. See <see cref="TimePlanning"/> for the times each view gets.
    /// </summary>
    [Serializable]
    public sealed class TimeSettings
    {
        public const int MaxSteps = 10000;
        public const double MaxSeconds = 24 * 3600;
        public const double MaxFps = 1000;

        public TimeMode Mode = TimeMode.Static;

        public TimeSources Sources = TimeSources.All;

        /// <summary>The content time of the first step, in seconds (the scene at rest is time 0).</summary>
        public double StartSeconds;

        /// <summary>The content time of the last step, in seconds (unless <see cref="EndAtClipLength"/>).</summary>
        public double EndSeconds = 1;

        /// <summary>End at the length of the target's longest clip or Timeline (measured in Unity; the config says "clip").</summary>
        public bool EndAtClipLength;

        /// <summary>
        /// The number of time steps, start and end included; 0 when <see cref="Fps"/> sets them. Monocular captures
        /// have one train view per step, so there it must equal the train count (or be 0: the train count decides).
        /// </summary>
        public int Steps;

        /// <summary>Steps per second instead of a count (0: unused): steps at start + k / fps up to the end.</summary>
        public double Fps;

        /// <summary>True for a dynamic capture (any mode but static).</summary>
        public bool Enabled => Mode != TimeMode.Static;

        public TimeSettings Clone() => (TimeSettings)MemberwiseClone();
    }
}
