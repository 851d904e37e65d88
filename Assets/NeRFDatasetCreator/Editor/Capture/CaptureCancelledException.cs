using System;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The capture was cancelled by the user, or stopped by the editor (Play mode, a script reload, quitting: then
    /// <see cref="Interruption"/> says which). Nothing is written under the dataset's final name.
    /// </summary>
    public sealed class CaptureCancelledException : OperationCanceledException
    {
        public CaptureCancelledException() : base("The capture was cancelled.")
        {
        }

        /// <param name="interruption">Why the editor stopped the capture, e.g. "Unity is entering Play mode".</param>
        public CaptureCancelledException(string interruption) : base("The capture was stopped because " + interruption + ".")
        {
            Interruption = interruption;
        }

        /// <summary>Why the editor stopped the capture; null when the user cancelled it.</summary>
        public string Interruption { get; }
    }
}
