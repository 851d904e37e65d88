namespace NerfDatasetCreator
{
    /// <summary>
    /// A frame's time keys as read (<see cref="TimeKeys"/>): each value when it is the right type, and whether the key
    /// is there at all, so that a check can tell "missing" from "not a number".
    /// </summary>
    public sealed class FrameTime
    {
        /// <summary>The frame has a <c>time</c> key (of any type).</summary>
        public bool HasTime { get; internal set; }

        /// <summary><c>time</c> when it is a number (NaN and infinities as Python writes them included), else null.</summary>
        public double? Time { get; internal set; }

        /// <summary>The frame has a <c>time_seconds</c> key (of any type).</summary>
        public bool HasSeconds { get; internal set; }

        /// <summary><c>time_seconds</c> when it is a number, else null.</summary>
        public double? Seconds { get; internal set; }

        /// <summary><c>time_step</c> / <c>camera_id</c> when each is a whole number within int, else null.</summary>
        public int? Step { get; internal set; }
        public int? Camera { get; internal set; }

        /// <summary><c>time_step</c> / <c>camera_id</c> as written (the JSON value's text), null when absent: for messages.</summary>
        public string StepText { get; internal set; }
        public string CameraText { get; internal set; }

        /// <summary>Whether the frame has any of the time keys.</summary>
        public bool Any => HasTime || HasSeconds || StepText != null || CameraText != null;

        /// <summary>A frame without time keys.</summary>
        public static readonly FrameTime None = new FrameTime();
    }
}
