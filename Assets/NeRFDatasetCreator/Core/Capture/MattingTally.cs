using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <see cref="MattingDiagnostics"/> of a run: their sum over every view, and the views above
    /// <see cref="MattingDiagnostics.ViewWarningFraction"/> (the first <see cref="MaxListedViews"/> in plan order are
    /// kept by name, all are counted). Thread-safe: the capture's writer threads add views in any order.
    /// </summary>
    public sealed class MattingTally
    {
        /// <summary>At most this many views are kept by name; a capture with a broken renderer would list every view.</summary>
        public const int MaxListedViews = 20;

        readonly object _lock = new object();
        readonly List<(DatasetSplit Split, int Index, MattingDiagnostics Diagnostics)> _views = new List<(DatasetSplit, int, MattingDiagnostics)>();
        MattingDiagnostics _total;
        int _viewsAbove, _viewsCounted;

        public void Add(DatasetSplit split, int index, MattingDiagnostics view)
        {
            lock (_lock)
            {
                _total += view;
                _viewsCounted++;
                if (!view.AboveThreshold) return;
                _viewsAbove++;
                _views.Add((split, index, view));
                if (_views.Count > MaxListedViews)
                {
                    // Keep the first views in plan order, whatever order the threads finished them in.
                    _views.Sort((a, b) => a.Split != b.Split ? a.Split.CompareTo(b.Split) : a.Index.CompareTo(b.Index));
                    _views.RemoveAt(_views.Count - 1);
                }
            }
        }

        /// <summary>The sum over every view added.</summary>
        public MattingDiagnostics Total
        {
            get { lock (_lock) return _total; }
        }

        /// <summary>Views whose counts exceeded the per-view threshold.</summary>
        public int ViewsAboveThreshold
        {
            get { lock (_lock) return _viewsAbove; }
        }

        /// <summary>Views added (those with a colour pair).</summary>
        public int ViewsCounted
        {
            get { lock (_lock) return _viewsCounted; }
        }

        /// <summary>One line per listed view above the threshold, in plan order: "train r_12: 3 of 2560000 samples …".</summary>
        public IReadOnlyList<string> ViewLines()
        {
            lock (_lock)
                return _views.OrderBy(v => v.Split).ThenBy(v => v.Index)
                    .Select(v => DatasetSplits.Name(v.Split) + " r_" + v.Index.ToString(CultureInfo.InvariantCulture) + ": " + v.Diagnostics)
                    .ToList();
        }

        /// <summary>
        /// Writes the figures into a dataset's statistics (dataset_config.json): samples, darker-over-white samples, and
        /// stray background samples when a mask was rendered, and the number of views above the threshold.
        /// </summary>
        public void WriteStatistics(IDictionary<string, double> statistics)
        {
            var total = Total;
            if (total.Samples == 0) return;
            statistics["mattingSamples"] = total.Samples;
            statistics["mattingDarkerOverWhiteSamples"] = total.DarkerOverWhite;
            if (total.BackgroundChecked) statistics["mattingStrayBackgroundSamples"] = total.StrayBackground;
            statistics["mattingViewsAboveThreshold"] = ViewsAboveThreshold;
        }

        /// <summary>
        /// A warning for the log and the window: the totals, the views above the threshold and the likely causes; null
        /// when no view exceeded the threshold (a handful of odd samples in a long run is not worth a warning).
        /// </summary>
        public string Warning()
        {
            var total = Total;
            int above = ViewsAboveThreshold;
            if (above == 0) return null;
            var lines = ViewLines();
            return string.Format(CultureInfo.InvariantCulture,
                       "NeRF Dataset Creator: the matting found renders it cannot explain in {0} of {1} views (over {2:0.#} % of a view's samples): {3}.\n  {4}{5}\n{6}",
                       above, ViewsCounted, 100 * MattingDiagnostics.ViewWarningFraction, total, string.Join("\n  ", lines),
                       above > lines.Count ? "\n  … and " + (above - lines.Count).ToString(CultureInfo.InvariantCulture) + " more." : "",
                       total.LikelyCauses() + " See Documentation~/capture.md, \"Matting diagnostics\".");
        }
    }
}
