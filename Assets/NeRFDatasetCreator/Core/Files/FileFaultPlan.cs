using System;
using System.Collections.Generic;
using System.Threading;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A test's plan for <see cref="FileOps.Faults"/>: count the operations and, at the N-th, either throw an
    /// exception (a failure the code should handle: disk full, permission denied) or stop — the N-th and every later
    /// operation throw <see cref="SimulatedStopException"/>, which no code of the plugin catches as an I/O error,
    /// so nothing is done after the stop, like a <c>kill -9</c>. <see cref="Killing"/> ends the real process instead.
    /// </summary>
    public sealed class FileFaultPlan
    {
        readonly int _at;
        readonly Func<string, string, Exception> _fault;
        readonly bool _stop;
        readonly Action _kill;
        readonly Func<string, bool> _onlyPaths;
        int _count;
        volatile bool _stopped;
        readonly List<string> _operations = new List<string>();

        FileFaultPlan(int at, Func<string, string, Exception> fault, bool stop, Action kill, Func<string, bool> onlyPaths)
        {
            _at = at;
            _fault = fault;
            _stop = stop;
            _kill = kill;
            _onlyPaths = onlyPaths;
        }

        /// <summary>Counts operations and never interferes: a dry run tells a test how many steps an operation has.</summary>
        public static FileFaultPlan Counting() => new FileFaultPlan(0, null, false, null, null);

        /// <summary>Throws <paramref name="fault"/>(operation, path) at operation <paramref name="n"/> (1-based) on the paths <paramref name="onlyPaths"/> accepts; the rest run normally.</summary>
        public static FileFaultPlan FailingAt(int n, Func<string, string, Exception> fault, Func<string, bool> onlyPaths = null) =>
            new FileFaultPlan(n, fault, false, null, onlyPaths);

        /// <summary>Stops at operation <paramref name="n"/>: that one and every later one throw <see cref="SimulatedStopException"/>.</summary>
        public static FileFaultPlan StoppingAt(int n) => new FileFaultPlan(n, null, true, null, null);

        /// <summary>Runs <paramref name="kill"/> (e.g. killing the process) before operation <paramref name="n"/>.</summary>
        public static FileFaultPlan Killing(int n, Action kill) => new FileFaultPlan(n, null, false, kill, null);

        /// <summary>Every operation counted so far as "operation path", in order: lets a test pick the step to stop or kill at by what it does.</summary>
        public IReadOnlyList<string> Operations
        {
            get { lock (_operations) return _operations.ToArray(); }
        }

        /// <summary>Operations counted so far.</summary>
        public int Count => Volatile.Read(ref _count);

        /// <summary>True once a stop plan has stopped.</summary>
        public bool Stopped => _stopped;

        internal void Before(string operation, string path)
        {
            if (_stopped) throw new SimulatedStopException(operation, path);
            if (_onlyPaths != null && !_onlyPaths(path ?? "")) return;
            var n = Interlocked.Increment(ref _count);
            lock (_operations) _operations.Add(operation + " " + path);
            if (n != _at) return;
            if (_kill != null) _kill();
            if (_stop)
            {
                _stopped = true;
                // A killed process takes its runs with it: none of them is in progress any more (OperationOwner).
                OperationOwner.EndAllHere();
                throw new SimulatedStopException(operation, path);
            }
            if (_fault != null) throw _fault(operation, path);
        }
    }

    /// <summary>Thrown by <see cref="FileOps"/> once a test's <see cref="FileFaultPlan.StoppingAt"/> has stopped: the process "died" here.</summary>
    public sealed class SimulatedStopException : Exception
    {
        public SimulatedStopException(string operation, string path)
            : base("simulated stop before " + operation + " " + path) { }
    }
}
