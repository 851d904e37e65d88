namespace NerfDatasetCreator
{
    /// <summary>A frame's exposure keys as read (<see cref="ExposureKeys.Read"/>).</summary>
    public sealed class FrameExposure
    {
        /// <summary>Whether the frame has <c>exposure_ev</c> / <c>white_balance</c> (of any form).</summary>
        public bool HasEv { get; internal set; }
        public bool HasWhiteBalance { get; internal set; }

        /// <summary>Whether the frame records exposure at all (either key).</summary>
        public bool Recorded => HasEv || HasWhiteBalance;

        /// <summary>The values when both keys are usable (finite EV within the settings' range, three gains in [1/16, 16]), else null.</summary>
        public ViewExposure? Values { get; internal set; }

        /// <summary>Why the recorded values are unusable, naming the key and what it holds; null when usable or not recorded.</summary>
        public string Problem { get; internal set; }

        /// <summary>A frame without exposure keys.</summary>
        public static readonly FrameExposure None = new FrameExposure();
    }
}
