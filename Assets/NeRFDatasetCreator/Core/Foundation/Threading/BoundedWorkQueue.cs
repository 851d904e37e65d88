using System;
using System.Collections.Concurrent;
using System.Globalization;
using System.Threading;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Runs jobs on a fixed set of worker threads, holding at most <see cref="Capacity"/> jobs that have not started.
    /// The producer (the capture loop on Unity's main thread) blocks in <see cref="Enqueue"/> while the queue is full,
    /// so memory stays flat however many views a run has: at most Capacity + WorkerCount views' buffers are alive.
    /// The first job that throws stops the queue (a full disk must not be hit ten thousand more times); the
    /// producer learns of it at its next <see cref="Enqueue"/> or at <see cref="WaitForAll"/>.
    /// </summary>
    public sealed class BoundedWorkQueue : IDisposable
    {
        readonly BlockingCollection<Action> _jobs;
        readonly Thread[] _workers;
        readonly CancellationTokenSource _stop = new CancellationTokenSource();
        Exception _failure;
        int _completed;
        bool _disposed;

        public BoundedWorkQueue(int workerCount, int capacity, string threadName = "NeRF Dataset Creator worker")
        {
            InvalidParameterException.ThrowIfAny(
                ValidationProblem.OutsideRange(nameof(workerCount), workerCount, 1, 64),
                ValidationProblem.OutsideRange(nameof(capacity), capacity, 1, 4096));
            Capacity = capacity;
            _jobs = new BlockingCollection<Action>(new ConcurrentQueue<Action>(), capacity);
            _workers = new Thread[workerCount];
            for (var i = 0; i < workerCount; i++)
            {
                // Dedicated background threads: long file writes must not starve the thread pool that Unity's
                // editor also uses, and a background thread never keeps a process alive.
                _workers[i] = new Thread(Work)
                {
                    IsBackground = true,
                    Name = threadName + " " + i.ToString(CultureInfo.InvariantCulture),
                };
                _workers[i].Start();
            }
        }

        public int Capacity { get; }
        public int WorkerCount => _workers.Length;

        /// <summary>Jobs queued and not yet started.</summary>
        public int Pending => _jobs.Count;

        /// <summary>Jobs that ran to the end without throwing.</summary>
        public int Completed => Volatile.Read(ref _completed);

        /// <summary>The first exception a job threw, or null.</summary>
        public Exception Failure => Volatile.Read(ref _failure);

        public bool IsCancelled => _stop.IsCancellationRequested && Failure == null;

        /// <summary>
        /// Queues a job, blocking while <see cref="Capacity"/> jobs are waiting. Throws
        /// <see cref="WorkQueueFailedException"/> when a job has failed and <see cref="OperationCanceledException"/>
        /// after <see cref="Cancel"/>.
        /// </summary>
        public void Enqueue(Action job)
        {
            if (!TryEnqueue(job, Timeout.Infinite))
                throw new InvalidOperationException("The job could not be queued."); // unreachable with an infinite wait
        }

        /// <summary>
        /// Like <see cref="Enqueue"/>, but gives up after <paramref name="millisecondsTimeout"/> and returns false,
        /// so a producer can keep its progress display and cancel button alive while the writers catch up.
        /// </summary>
        public bool TryEnqueue(Action job, int millisecondsTimeout)
        {
            if (job == null) throw new ArgumentNullException(nameof(job));
            ThrowIfStopped();
            try
            {
                return _jobs.TryAdd(job, millisecondsTimeout, _stop.Token);
            }
            catch (OperationCanceledException)
            {
                ThrowIfStopped();
                throw;
            }
            catch (InvalidOperationException) when (_jobs.IsAddingCompleted)
            {
                throw new InvalidOperationException("No job can be queued after WaitForAll.");
            }
        }

        /// <summary>Drops every job that has not started; running jobs finish. Later Enqueue calls throw.</summary>
        public void Cancel()
        {
            if (!_stop.IsCancellationRequested) _stop.Cancel();
        }

        /// <summary>
        /// Accepts no more jobs, waits until the workers have run every queued job (or stopped after a cancel or
        /// a failure) and throws <see cref="WorkQueueFailedException"/> if a job failed.
        /// </summary>
        public void WaitForAll()
        {
            if (!_jobs.IsAddingCompleted) _jobs.CompleteAdding();
            foreach (var worker in _workers) worker.Join();
            var failure = Failure;
            if (failure != null) throw new WorkQueueFailedException(failure);
        }

        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
            Cancel();
            if (!_jobs.IsAddingCompleted) _jobs.CompleteAdding();
            foreach (var worker in _workers) worker.Join();
            _jobs.Dispose();
            _stop.Dispose();
        }

        void ThrowIfStopped()
        {
            var failure = Failure;
            if (failure != null) throw new WorkQueueFailedException(failure);
            if (_stop.IsCancellationRequested) throw new OperationCanceledException("The work queue was cancelled.");
        }

        void Work()
        {
            try
            {
                foreach (var job in _jobs.GetConsumingEnumerable(_stop.Token))
                {
                    try
                    {
                        job();
                        Interlocked.Increment(ref _completed);
                    }
                    catch (Exception e)
                    {
                        Interlocked.CompareExchange(ref _failure, e, null);
                        Cancel();
                        return;
                    }
                }
            }
            catch (OperationCanceledException)
            {
                // Cancel() or another worker's failure: the remaining jobs are dropped on purpose.
            }
        }
    }

    /// <summary>A queued job threw; <see cref="Exception.InnerException"/> is what it threw.</summary>
    public sealed class WorkQueueFailedException : Exception
    {
        public WorkQueueFailedException(Exception inner)
            : base("A background job failed: " + inner.Message, inner)
        {
        }
    }
}
