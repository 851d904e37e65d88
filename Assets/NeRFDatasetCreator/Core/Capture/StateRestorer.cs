using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The changes a run made to state it does not own (an editor-wide flag, a lock), each recorded right after it was
    /// made together with the action that puts it back. <see cref="RestoreAll"/> undoes them newest first, each exactly
    /// once, whatever ended the run and however often it is called, and goes on past a restore that throws.
    /// </summary>
    public sealed class StateRestorer
    {
        readonly List<KeyValuePair<string, Action>> _changes = new List<KeyValuePair<string, Action>>();

        /// <summary>Changes not restored yet.</summary>
        public int Pending => _changes.Count;

        /// <summary>Records a change that was just made; <paramref name="restore"/> undoes it.</summary>
        public void Changed(string what, Action restore)
        {
            if (string.IsNullOrEmpty(what)) throw new ArgumentException("Name the change.", nameof(what));
            _changes.Add(new KeyValuePair<string, Action>(what, restore ?? throw new ArgumentNullException(nameof(restore))));
        }

        /// <summary>
        /// Restores every pending change, newest first. Each is removed before its restore runs, so a restore that
        /// ends the run again (a re-entrant call) or a second call never repeats one. Returns the restores that threw,
        /// each wrapped with what it was restoring; the others still ran.
        /// </summary>
        public IReadOnlyList<Exception> RestoreAll()
        {
            var failures = new List<Exception>();
            while (_changes.Count > 0)
            {
                var last = _changes[_changes.Count - 1];
                _changes.RemoveAt(_changes.Count - 1);
                try
                {
                    last.Value();
                }
                catch (Exception e)
                {
                    failures.Add(new InvalidOperationException("Restoring " + last.Key + " failed: " + e.Message, e));
                }
            }
            return failures;
        }
    }
}
