using System;

namespace NerfDatasetCreator
{
    /// <summary>A failure of <see cref="BackgroundSubFrameSum"/>'s worker, thrown to the thread that renders the sub-frames.</summary>
    public sealed class SubFrameSumException : InvalidOperationException
    {
        public SubFrameSumException(Exception failure)
            : base("Averaging the motion-blur sub-frames failed: " + failure.Message, failure)
        {
        }
    }
}
