using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>One clip of a Cinemachine track: the virtual camera it makes live and its time span on the Timeline.</summary>
    public sealed class ShotSpan
    {
        public ShotSpan(string name, double start, double end)
        {
            Name = name ?? "";
            Start = start;
            End = end;
        }

        public string Name { get; }
        public double Start { get; }
        public double End { get; }
    }

    /// <summary>
    /// When a Cinemachine track holds the brain's camera. Timeline makes a clip active at a time t when
    /// start ≤ t &lt; end, compared in whole ticks of 1e-12 s rounded half up (com.unity.timeline
    /// Runtime/Evaluation/IntervalTree.cs <c>Query</c>: <c>value &gt;= entry.intervalStart &amp;&amp; value &lt;
    /// entry.intervalEnd</c>; DiscreteTime <c>k_Tick = 1e-12</c>, <c>DoubleToDiscreteTime</c> = time / k_Tick + 0.5).
    /// Outside every shot the Cinemachine mixer passes no camera and the brain shows its own highest-priority
    /// virtual camera — a camera the Timeline does not choose — so such a time is refused. The end of the last shot
    /// (usually the Timeline's end, where even sampling puts its last view) is evaluated one tick earlier: the limit of
    /// the shot, the pose Timeline shows on its last frame.
    /// </summary>
    public static class CinemachineShots
    {
        /// <summary>Timeline's time resolution in seconds.</summary>
        public const double Tick = 1e-12;

        /// <summary>The Timeline tick of a time, as Timeline rounds it.</summary>
        public static long TickOf(double seconds) => (long)(seconds / Tick + 0.5);

        /// <summary>Whether a shot is active at <paramref name="seconds"/>.</summary>
        public static bool Covers(IReadOnlyList<ShotSpan> shots, double seconds)
        {
            var t = TickOf(seconds);
            return shots.Any(s => t >= TickOf(s.Start) && t < TickOf(s.End));
        }

        /// <summary>
        /// The time to evaluate for a sample at <paramref name="seconds"/>: itself inside a shot, one tick earlier at
        /// the end of a shot that no other shot continues, NaN in a gap.
        /// </summary>
        public static double EvaluationTime(IReadOnlyList<ShotSpan> shots, double seconds)
        {
            if (Covers(shots, seconds)) return seconds;
            var t = TickOf(seconds);
            if (shots.Any(s => TickOf(s.End) == t && TickOf(s.Start) < t)) return (t - 1) * Tick;
            return double.NaN;
        }

        /// <summary>
        /// The evaluation time of every sample, or null with a problem naming the first sample no shot covers.
        /// </summary>
        public static double[] EvaluationTimes(IReadOnlyList<ShotSpan> shots, IReadOnlyList<double> times, string fieldPrefix, string track,
            out ValidationProblem problem)
        {
            problem = null;
            if (shots.Count == 0)
            {
                problem = new ValidationProblem(fieldPrefix + ".camera", track, "has no shot: the Timeline never chooses a virtual camera for the brain.",
                    "Add Cinemachine Shot clips to the track, or unmute it.");
                return null;
            }
            var result = new double[times.Count];
            for (var i = 0; i < times.Count; i++)
            {
                result[i] = EvaluationTime(shots, times[i]);
                if (!double.IsNaN(result[i])) continue;
                var gaps = times.Count(t => double.IsNaN(EvaluationTime(shots, t)));
                problem = new ValidationProblem(fieldPrefix + ".start", Format(times[i]) + " s",
                    "is a sample time no shot of " + track + " covers (" + gaps.ToString(CultureInfo.InvariantCulture) + " of " +
                    times.Count.ToString(CultureInfo.InvariantCulture) + " samples; shots: " + Describe(shots) + "). There the brain shows its " +
                    "highest-priority virtual camera, which the Timeline does not choose.",
                    "Set start and end inside the shots (e.g. start " + Format(shots.Min(s => s.Start)) + ", end " + Format(shots.Max(s => s.End)) +
                    "), or extend a shot over the gap.");
                return null;
            }
            return result;
        }

        /// <summary>"Wide 0–2 s, Close 1.5–4 s" in start order, for messages.</summary>
        public static string Describe(IReadOnlyList<ShotSpan> shots)
        {
            var ordered = shots.OrderBy(s => s.Start).ToList();
            var text = string.Join(", ", ordered.Take(6).Select(s => s.Name + " " + Format(s.Start) + "–" + Format(s.End) + " s"));
            return ordered.Count > 6 ? text + ", …" : text;
        }

        static string Format(double seconds) => seconds.ToString("0.###", CultureInfo.InvariantCulture);
    }
}
