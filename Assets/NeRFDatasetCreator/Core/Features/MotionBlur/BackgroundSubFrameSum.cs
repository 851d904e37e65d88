using System;
using System.Threading;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Motion blur's sub-frame sum off the render thread (issue 32, R4-2): the capture renders sub-frame k + 1 while a
    /// worker thread of this object adds sub-frame k into one <see cref="SubFrameAccumulator"/>, so the render thread
    /// (Unity's main thread) pays per sub-frame only its render and the copy of its readback into an input pair. Two
    /// input pairs are allocated once and taken in turn (<see cref="TakeInput"/> waits while the worker still reads
    /// both), the accumulator once per capture: nothing is allocated per sub-frame or per view. Jobs run in the order
    /// given (restart, adds, finish), so the averaged pair is exactly the synchronous accumulator's.
    /// <para>
    /// Protocol, on one calling thread: <see cref="Begin"/> (the view's sub-frame count), then per sub-frame
    /// <see cref="TakeInput"/>, fill the pair, <see cref="Add"/>; then <see cref="Finish"/> with the output arrays, which
    /// returns at once; <see cref="WaitIdle"/> before the outputs are read. A failure on the worker is thrown by the next
    /// call as a <see cref="SubFrameSumException"/>. Without a thread (<c>background: false</c>) every job runs inside the call that gives it: the same code, for
    /// tests and the benchmark.
    /// </para>
    /// </summary>
    public sealed class BackgroundSubFrameSum : IDisposable
    {
        /// <summary>Input pairs: one being filled by the render thread while the worker adds the other.</summary>
        public const int InputPairs = 2;

        struct Job
        {
            public int Kind; // Restart, Add, Finish
            public int Value; // sub-frames for Restart, the sub-frame for Add
            public int Input;
            public ushort[] Black, White;
        }

        const int Restart = 0, AddJob = 1, FinishJob = 2;

        readonly SubFrameAccumulator _sum;
        readonly ushort[][] _black = new ushort[InputPairs][], _white = new ushort[InputPairs][];
        readonly bool[] _taken = new bool[InputPairs];
        readonly Job[] _jobs = new Job[2 * InputPairs + 4];
        readonly object _lock = new object();
        readonly Thread _thread;
        int _first, _queued;
        bool _running, _stop;
        Exception _failure;

        public BackgroundSubFrameSum(int width, int height, double readout, bool gammaEncoded, bool background = true)
        {
            _sum = new SubFrameAccumulator(width, height, 1, readout, gammaEncoded);
            for (var i = 0; i < InputPairs; i++)
            {
                _black[i] = new ushort[width * height * 4];
                _white[i] = new ushort[width * height * 4];
            }
            if (!background) return;
            _thread = new Thread(Work) { IsBackground = true, Name = "NeRF Dataset Creator motion blur" };
            _thread.Start();
        }

        /// <summary>Starts a view of <paramref name="subFrames"/> sub-frames (the sums are cleared on the worker, after the previous view's finish).</summary>
        public void Begin(int subFrames)
        {
            if (subFrames < 1) throw new ArgumentOutOfRangeException(nameof(subFrames), subFrames, "at least one sub-frame");
            Enqueue(new Job { Kind = Restart, Value = subFrames });
        }

        /// <summary>A free input pair (4 halves a sample each) to fill with a sub-frame's readback; returns its number for <see cref="Add"/>.</summary>
        public int TakeInput(out ushort[] overBlack, out ushort[] overWhite)
        {
            lock (_lock)
            {
                while (true)
                {
                    ThrowIfFailed();
                    for (var i = 0; i < InputPairs; i++)
                    {
                        if (_taken[i]) continue;
                        _taken[i] = true;
                        overBlack = _black[i];
                        overWhite = _white[i];
                        return i;
                    }
                    if (_thread == null) throw new InvalidOperationException("Every input pair is taken: call Add with each pair taken.");
                    Monitor.Wait(_lock);
                }
            }
        }

        /// <summary>Adds the filled input pair <paramref name="input"/> as sub-frame <paramref name="subFrame"/>; the pair is free again once added.</summary>
        public void Add(int input, int subFrame)
        {
            if (input < 0 || input >= InputPairs) throw new ArgumentOutOfRangeException(nameof(input), input, "not an input pair of this sum");
            lock (_lock)
                if (!_taken[input]) throw new InvalidOperationException("Input pair " + input + " was not taken.");
            Enqueue(new Job { Kind = AddJob, Value = subFrame, Input = input });
        }

        /// <summary>Writes the view's averaged pair into the arrays given, after the adds before it (see <see cref="WaitIdle"/>).</summary>
        public void Finish(ushort[] overBlack, ushort[] overWhite) => Enqueue(new Job { Kind = FinishJob, Black = overBlack, White = overWhite });

        /// <summary>Waits until every job given so far has run; throws the worker's failure, if any.</summary>
        public void WaitIdle()
        {
            lock (_lock)
            {
                while (_queued > 0 || _running)
                {
                    ThrowIfFailed();
                    Monitor.Wait(_lock);
                }
                ThrowIfFailed();
            }
        }

        void Enqueue(Job job)
        {
            if (_thread == null)
            {
                lock (_lock) ThrowIfFailed();
                Run(job);
                return;
            }
            lock (_lock)
            {
                while (_queued == _jobs.Length)
                {
                    ThrowIfFailed();
                    Monitor.Wait(_lock);
                }
                ThrowIfFailed();
                if (_stop) throw new ObjectDisposedException(nameof(BackgroundSubFrameSum));
                _jobs[(_first + _queued) % _jobs.Length] = job;
                _queued++;
                Monitor.PulseAll(_lock);
            }
        }

        void Work()
        {
            while (true)
            {
                Job job;
                lock (_lock)
                {
                    while (_queued == 0 && !_stop) Monitor.Wait(_lock);
                    if (_stop) return;
                    job = _jobs[_first];
                    _jobs[_first] = default;
                    _first = (_first + 1) % _jobs.Length;
                    _queued--;
                    _running = true;
                }
                try
                {
                    if (_failure == null) Run(job);
                }
                catch (Exception e)
                {
                    lock (_lock) _failure = e;
                }
                finally
                {
                    lock (_lock)
                    {
                        _running = false;
                        Monitor.PulseAll(_lock);
                    }
                }
            }
        }

        void Run(Job job)
        {
            switch (job.Kind)
            {
                case Restart:
                    _sum.Restart(job.Value);
                    break;
                case AddJob:
                    try
                    {
                        _sum.Add(job.Value, _black[job.Input], _white[job.Input]);
                    }
                    finally
                    {
                        lock (_lock) _taken[job.Input] = false;
                    }
                    break;
                default:
                    _sum.Finish(job.Black, job.White);
                    break;
            }
        }

        void ThrowIfFailed()
        {
            if (_failure != null) throw new SubFrameSumException(_failure);
        }

        /// <summary>Stops the worker (a job it is running finishes first).</summary>
        public void Dispose()
        {
            if (_thread == null) return;
            lock (_lock)
            {
                _stop = true;
                Monitor.PulseAll(_lock);
            }
            _thread.Join();
        }
    }
}
