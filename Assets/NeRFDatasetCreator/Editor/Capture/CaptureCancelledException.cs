using System;

namespace NerfDatasetCreator.Editor.Capture
{
    /// <summary>The user cancelled the capture. Nothing is written under the dataset's final name.</summary>
    public sealed class CaptureCancelledException : OperationCanceledException
    {
        public CaptureCancelledException() : base("The capture was cancelled.")
        {
        }
    }
}
