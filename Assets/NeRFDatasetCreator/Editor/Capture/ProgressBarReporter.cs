using UnityEditor;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// A modal cancellable progress bar, for captures that run to the end in one call (the CLI, tests). The bar is
    /// redrawn at most every 100 ms: redrawing it per view would cost more than small views take to render.
    /// </summary>
    public sealed class ProgressBarReporter : ICaptureProgress
    {
        readonly string _title;
        readonly System.Diagnostics.Stopwatch _sinceDraw = System.Diagnostics.Stopwatch.StartNew();
        bool _cancel;
        bool _drawn;

        public ProgressBarReporter(string title = "NeRF Dataset Creator: capturing")
        {
            _title = title;
        }

        public bool CancelRequested => _cancel;

        public void Report(ThroughputMeter meter)
        {
            if (_drawn && meter.Done < meter.Total && _sinceDraw.ElapsedMilliseconds < 100) return;
            _sinceDraw.Restart();
            _drawn = true;
            if (EditorUtility.DisplayCancelableProgressBar(_title, meter.Describe(), (float)meter.Fraction)) _cancel = true;
        }

        public void Close()
        {
            if (_drawn) EditorUtility.ClearProgressBar();
        }
    }
}
