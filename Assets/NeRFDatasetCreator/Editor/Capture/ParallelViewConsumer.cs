using System;
using System.IO;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Hands views to an <see cref="IViewWriter"/> on worker threads through a <see cref="BoundedWorkQueue"/>: the
    /// render loop blocks when the writers fall behind, so memory stays flat whatever the number of views. Releases
    /// each view's pooled arrays after it is written. The first writer error stops the queue and surfaces as a
    /// <see cref="CaptureException"/> that says what to do.
    /// </summary>
    public sealed class ParallelViewConsumer : IViewConsumer, IDisposable
    {
        readonly IViewWriter _writer;
        readonly BoundedWorkQueue _queue;

        /// <param name="workerCount">Writer threads; 0 = processor count − 1 (Unity's main thread keeps a core), at least 1, at most 8.</param>
        /// <param name="capacity">Views waiting for a writer; 0 = twice the worker count.</param>
        public ParallelViewConsumer(IViewWriter writer, int workerCount = 0, int capacity = 0)
        {
            _writer = writer ?? throw new ArgumentNullException(nameof(writer));
            if (workerCount <= 0) workerCount = DefaultWorkerCount;
            if (capacity <= 0) capacity = 2 * workerCount;
            _queue = new BoundedWorkQueue(workerCount, capacity, "NeRF Dataset Creator writer");
        }

        /// <summary>The writer threads by default: processor count − 1 (Unity's main thread keeps a core), at least 1, at most 8.</summary>
        public static int DefaultWorkerCount => Math.Max(1, Math.Min(8, Environment.ProcessorCount - 1));

        /// <summary>Views written so far.</summary>
        public int Written => _queue.Completed;

        public void Consume(CapturedView view)
        {
            try
            {
                _queue.Enqueue(() =>
                {
                    try
                    {
                        _writer.Write(view);
                    }
                    finally
                    {
                        view.Release();
                    }
                });
            }
            catch (WorkQueueFailedException e)
            {
                view.Release();
                throw Explain(e.InnerException);
            }
            catch
            {
                view.Release();
                throw;
            }
        }

        public void Finish()
        {
            try
            {
                _queue.WaitForAll();
            }
            catch (WorkQueueFailedException e)
            {
                throw Explain(e.InnerException);
            }
        }

        public void Abort()
        {
            _queue.Cancel();
            _queue.Dispose();
        }

        public void Dispose() => _queue.Dispose();

        /// <summary>A writer's exception as a message for the user: what failed and what to do.</summary>
        public static CaptureException Explain(Exception e)
        {
            switch (e)
            {
                case UnauthorizedAccessException _:
                    return new CaptureException("Writing the dataset was denied: " + e.Message +
                        " Choose an output folder you can write to (outside Assets/, not read-only).", e);
                case PathTooLongException _:
                    return new CaptureException("A dataset path is too long: " + e.Message + " Choose a shorter output folder.", e);
                case IOException _:
                    return new CaptureException("Writing the dataset failed: " + e.Message +
                        " Check that the disk has free space and the output folder is reachable, then capture again.", e);
                case CaptureException capture:
                    return capture;
                default:
                    return new CaptureException("Processing a captured view failed: " + e.Message, e);
            }
        }
    }
}
