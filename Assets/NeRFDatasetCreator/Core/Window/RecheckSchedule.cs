namespace NerfDatasetCreator
{
    /// <summary>
    /// When the window re-runs the capture's checks (review S3-2). A check (<c>DatasetCapture.Prepare</c>) may copy the
    /// target or the whole scene into a preview scene and step its animations, so it must not run at the window's 10 Hz
    /// tick: it runs <see cref="DebounceSeconds"/> after the last change, once, and scene events that the check's own
    /// copies may raise — while it runs, or delivered just after it (<see cref="OwnEventsSeconds"/>) — are not changes.
    /// Times are the editor's clock in seconds (<c>EditorApplication.timeSinceStartup</c>).
    /// </summary>
    public sealed class RecheckSchedule
    {
        /// <summary>Quiet time after the last change before a check runs: a drag or typing is one check, not one per tick.</summary>
        public const double DebounceSeconds = 0.5;

        /// <summary>
        /// How long after a check scene events are taken as its own: Unity delivers <c>hierarchyChanged</c> and
        /// <c>ObjectChangeEvents.changesPublished</c> from native code on a later editor update (UnityCsReference 2022.3
        /// Editor/Mono/EditorApplication.cs:221-226), so a flag set during the check alone cannot catch them.
        /// </summary>
        public const double OwnEventsSeconds = 0.25;

        bool _pending = true;
        double _lastChange = double.NegativeInfinity;
        double _ownEventsUntil = double.NegativeInfinity;
        bool _checking;

        /// <summary>Something the check reads changed (settings, target, focus, undo): check again once things are quiet.</summary>
        public void Changed(double now)
        {
            _pending = true;
            _lastChange = now;
        }

        /// <summary>
        /// A scene event (hierarchy or object change). Ignored while a check runs and just after one, when it is most
        /// likely the check's own copies; true when it was taken as a change.
        /// </summary>
        public bool SceneChanged(double now)
        {
            if (_checking || now < _ownEventsUntil) return false;
            Changed(now);
            return true;
        }

        /// <summary>Whether a check is due: something changed and nothing has changed for <see cref="DebounceSeconds"/>.</summary>
        public bool Due(double now) => _pending && !_checking && now - _lastChange >= DebounceSeconds;

        /// <summary>Whether a check is running now (its scene events are ignored).</summary>
        public bool Checking => _checking;

        /// <summary>Call before the check.</summary>
        public void Starting() => _checking = true;

        /// <summary>Call after the check, with the time it ended: the changes so far are checked.</summary>
        public void Finished(double now)
        {
            _checking = false;
            _pending = false;
            _ownEventsUntil = now + OwnEventsSeconds;
        }
    }
}
