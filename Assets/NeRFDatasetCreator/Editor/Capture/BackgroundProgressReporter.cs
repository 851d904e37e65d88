using UnityEditor;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Progress in Unity's Background Tasks window and status bar (the editor stays usable), with its cancel button.
    /// For captures stepped from <c>EditorApplication.update</c> by <see cref="CaptureRunner.RunInBackground"/>.
    /// </summary>
    public sealed class BackgroundProgressReporter : ICaptureProgress
    {
        readonly int _id;
        volatile bool _cancel;
        bool _closed;

        public BackgroundProgressReporter(string name = "NeRF Dataset Creator")
        {
            _id = Progress.Start(name, "Capturing views");
            Progress.RegisterCancelCallback(_id, () =>
            {
                _cancel = true;
                return true;
            });
        }

        public bool CancelRequested => _cancel;

        /// <summary>How the run ended, for the task's final status; set before <see cref="Close"/>.</summary>
        public Progress.Status FinalStatus = Progress.Status.Succeeded;

        public void Report(ThroughputMeter meter)
        {
            if (!_closed && Progress.Exists(_id)) Progress.Report(_id, (float)meter.Fraction, meter.Describe());
        }

        public void Close()
        {
            if (_closed) return;
            _closed = true;
            if (Progress.Exists(_id)) Progress.Finish(_id, _cancel ? Progress.Status.Canceled : FinalStatus);
        }
    }
}
