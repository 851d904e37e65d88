using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Which run writes an operation's working folder — the machine, the process and the process's start time, kept in
    /// the journal (<see cref="OperationJournal.Owner"/>) — and whether that run may still be writing it. Recovery and
    /// <c>clean</c> act only on the folders of runs that have provably ended, so that a convert, merge or clean started
    /// while a capture (or another convert) writes the same output never rolls back, finishes or deletes the live run's
    /// files. A run is provably over when its process is gone from this machine, or when the process now under its id
    /// started at another time (the id was reused). Inside one process (the Unity Editor runs a capture and the tools
    /// window side by side) the live operations are registered here, and one not registered is over: a domain reload,
    /// which ends every running capture, clears the register with the rest of the managed state.
    /// </summary>
    public sealed class OperationOwner
    {
        /// <summary>Process start times are read back rounded differently on some platforms; closer than this is the same process.</summary>
        static readonly TimeSpan StartTolerance = TimeSpan.FromSeconds(2);

        static readonly object Gate = new object();
        static readonly HashSet<string> LiveHere = new HashSet<string>(StringComparer.Ordinal);
        static OperationOwner current;

        public OperationOwner(string host, int processId, DateTime? processStart)
        {
            Host = host;
            ProcessId = processId;
            ProcessStart = processStart;
        }

        public string Host { get; }
        public int ProcessId { get; }

        /// <summary>UTC; null when the platform would not say.</summary>
        public DateTime? ProcessStart { get; }

        /// <summary>This process.</summary>
        public static OperationOwner Current
        {
            get
            {
                lock (Gate)
                {
                    if (current != null) return current;
                    var self = Process.GetCurrentProcess();
                    current = new OperationOwner(HostName(), self.Id, StartOf(self));
                    return current;
                }
            }
        }

        /// <summary>Marks the operation writing <paramref name="workingFolder"/> as running in this process.</summary>
        public static void Register(string workingFolder)
        {
            lock (Gate) LiveHere.Add(Key(workingFolder));
        }

        /// <summary>The operation writing <paramref name="workingFolder"/> has ended here (finished, failed or cancelled).</summary>
        public static void Release(string workingFolder)
        {
            lock (Gate) LiveHere.Remove(Key(workingFolder));
        }

        /// <summary>True while an operation of this process writes <paramref name="workingFolder"/> (<see cref="Register"/>).</summary>
        public static bool IsRunningHere(string workingFolder)
        {
            lock (Gate) return LiveHere.Contains(Key(workingFolder));
        }

        /// <summary>What a kill does to this process's runs: <see cref="FileFaultPlan.StoppingAt"/> simulates one.</summary>
        internal static void EndAllHere()
        {
            lock (Gate) LiveHere.Clear();
        }

        /// <summary>
        /// Null when the run that wrote the journal in <paramref name="workingFolder"/> has provably ended (or the journal
        /// predates owners); otherwise why it may still be running, as a clause ("a run on this machine (process 4242,
        /// started …) may still be writing it").
        /// </summary>
        public static string WhyMayBeRunning(OperationOwner owner, string workingFolder)
        {
            if (owner == null) return null;
            var here = Current;
            if (!string.Equals(owner.Host, here.Host, StringComparison.OrdinalIgnoreCase))
                return "it was written by a run on " + Describe(owner.Host) + ", which this machine cannot see (if that run has ended, run clean on that machine, or remove the folder yourself)";
            if (owner.ProcessId == here.ProcessId && SameStart(owner.ProcessStart, here.ProcessStart))
            {
                return IsRunningHere(workingFolder) ? "this process (" + owner.ProcessId + ") is still writing it" : null;
            }
            try
            {
                using (var process = Process.GetProcessById(owner.ProcessId))
                {
                    if (process.HasExited) return null;
                    var started = StartOf(process);
                    // The id belongs to a process started at another time: the writer ended and the id was reused.
                    if (started.HasValue && owner.ProcessStart.HasValue && !SameStart(started, owner.ProcessStart)) return null;
                    return "process " + owner.ProcessId + (owner.ProcessStart.HasValue ? ", started " + owner.ProcessStart.Value.ToString("u", CultureInfo.InvariantCulture) + "," : "") +
                           " may still be writing it (run again when it has finished)";
                }
            }
            catch (ArgumentException)
            {
                return null; // no process has that id: the writer ended
            }
            catch (InvalidOperationException)
            {
                return null; // it exited while being looked at
            }
        }

        /// <summary>
        /// The run as a part of a file name, for what must carry its owner before any file can (a report's temporary file,
        /// a working folder being born): <c>&lt;host&gt;-&lt;pid&gt;-&lt;start&gt;</c>, the host's ASCII letters and digits
        /// (at most 24, "unknown" for none) and the start as <c>yyyyMMddHHmmss</c> UTC ("0" when unknown).
        /// </summary>
        public string NameTag =>
            HostTag(Host) + "-" + ProcessId.ToString(CultureInfo.InvariantCulture) + "-" +
            (ProcessStart?.ToString("yyyyMMddHHmmss", CultureInfo.InvariantCulture) ?? "0");

        /// <summary>A regular expression matching exactly a <see cref="NameTag"/>, with groups host, pid and start.</summary>
        public const string NameTagPattern = @"(?<host>[A-Za-z0-9]{1,24})-(?<pid>[0-9]{1,10})-(?<start>[0-9]{14}|0)";

        /// <summary>The owner a <see cref="NameTagPattern"/> match names, or null when its numbers do not parse.</summary>
        public static OperationOwner FromNameTag(System.Text.RegularExpressions.Match match)
        {
            if (!match.Success || !int.TryParse(match.Groups["pid"].Value, NumberStyles.None, CultureInfo.InvariantCulture, out var pid)) return null;
            DateTime? start = null;
            if (match.Groups["start"].Value != "0")
            {
                if (!DateTime.TryParseExact(match.Groups["start"].Value, "yyyyMMddHHmmss", CultureInfo.InvariantCulture,
                        DateTimeStyles.AssumeUniversal | DateTimeStyles.AdjustToUniversal, out var parsed)) return null;
                start = parsed;
            }
            var host = match.Groups["host"].Value;
            // The tag keeps a shortened host: the same shortening of this machine's name is this machine.
            return new OperationOwner(host == HostTag(Current.Host) ? Current.Host : host, pid, start);
        }

        static string HostTag(string host)
        {
            var kept = new System.Text.StringBuilder();
            foreach (var c in host ?? "")
                if (c < 128 && char.IsLetterOrDigit(c) && kept.Length < 24) kept.Append(c);
            return kept.Length > 0 ? kept.ToString() : "unknown";
        }

        static bool SameStart(DateTime? a, DateTime? b) =>
            !a.HasValue || !b.HasValue || (a.Value - b.Value).Duration() <= StartTolerance;

        static DateTime? StartOf(Process process)
        {
            // Another user's process, or a platform that does not say: unknown, which keeps the folder (never the reverse).
            try
            {
                return process.StartTime.ToUniversalTime();
            }
            catch (Exception e) when (e is InvalidOperationException || e is NotSupportedException || e is System.ComponentModel.Win32Exception || e is UnauthorizedAccessException)
            {
                return null;
            }
        }

        static string HostName()
        {
            try
            {
                return Environment.MachineName;
            }
            catch (InvalidOperationException)
            {
                return "";
            }
        }

        static string Describe(string host) => string.IsNullOrEmpty(host) ? "another machine" : "\"" + host + "\"";

        static string Key(string folder) => Path.GetFullPath(folder).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
    }
}
