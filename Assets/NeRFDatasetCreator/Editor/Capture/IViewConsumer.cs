namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Receives each captured view on Unity's main thread, in view order. The consumer owns the view from then on and
    /// must call <see cref="CapturedView.Release"/> when it no longer needs the pixels (typically after a worker wrote
    /// the files). Keep <see cref="Consume"/> short: the GPU waits while it runs.
    /// </summary>
    public interface IViewConsumer
    {
        void Consume(CapturedView view);

        /// <summary>Every view was delivered: finish all pending work (wait for writers) and throw if any of it failed.</summary>
        void Finish();

        /// <summary>The capture failed or was cancelled: drop pending work as fast as possible. Must not throw.</summary>
        void Abort();
    }
}
