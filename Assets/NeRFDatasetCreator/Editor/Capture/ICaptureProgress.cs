namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Where a capture reports its progress and learns about a cancel. The window plugs in its own display; the
    /// capture polls <see cref="CancelRequested"/> after every view, so a cancel takes effect within one view's time.
    /// </summary>
    public interface ICaptureProgress
    {
        /// <summary>Called on the main thread after each view and at the end; <paramref name="meter"/> holds done/total, views per second and time left.</summary>
        void Report(ThroughputMeter meter);

        bool CancelRequested { get; }

        /// <summary>The run ended (finished, cancelled or failed): remove any display. Must not throw.</summary>
        void Close();
    }
}
