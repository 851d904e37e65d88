using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Views per second and time left for a progress display and the run's provenance. Time is passed in (seconds
    /// since the run started) rather than read from a clock, so the arithmetic is testable and the caller decides
    /// which clock counts (Unity's realtimeSinceStartup, a Stopwatch).
    /// </summary>
    public sealed class ThroughputMeter
    {
        public ThroughputMeter(int total)
        {
            InvalidParameterException.ThrowIfAny(ValidationProblem.OutsideRange(nameof(total), total, 0, int.MaxValue));
            Total = total;
        }

        public int Total { get; }
        public int Done { get; private set; }
        public double ElapsedSeconds { get; private set; }

        /// <summary>Records that <paramref name="done"/> views are finished after <paramref name="elapsedSeconds"/>.</summary>
        public void Update(int done, double elapsedSeconds)
        {
            if (done < 0 || done > Total)
                throw new ArgumentOutOfRangeException(nameof(done), done, $"done must be within [0, {Total}].");
            if (double.IsNaN(elapsedSeconds) || elapsedSeconds < 0)
                throw new ArgumentOutOfRangeException(nameof(elapsedSeconds), elapsedSeconds, "elapsed time must be ≥ 0.");
            Done = done;
            ElapsedSeconds = elapsedSeconds;
        }

        /// <summary>Fraction done in [0, 1]; 1 for an empty run.</summary>
        public double Fraction => Total == 0 ? 1.0 : (double)Done / Total;

        /// <summary>Average views per second since the start; 0 until a view is done and time has passed.</summary>
        public double ViewsPerSecond => Done == 0 || ElapsedSeconds <= 0 ? 0.0 : Done / ElapsedSeconds;

        /// <summary>Estimated seconds left at the average rate so far; null while no rate is known.</summary>
        public double? SecondsLeft
        {
            get
            {
                if (Done == Total) return 0.0;
                var rate = ViewsPerSecond;
                return rate <= 0 ? (double?)null : (Total - Done) / rate;
            }
        }

        /// <summary>"12 / 100 views · 3.4 views/s · 0:26 left", for a progress bar.</summary>
        public string Describe()
        {
            var ci = System.Globalization.CultureInfo.InvariantCulture;
            var left = SecondsLeft;
            var leftText = left.HasValue ? FormatDuration(left.Value) + " left" : "estimating time left";
            return string.Format(ci, "{0} / {1} views · {2:0.0} views/s · {3}", Done, Total, ViewsPerSecond, leftText);
        }

        /// <summary>m:ss under an hour, h:mm:ss above; seconds rounded up so "0:00 left" means done.</summary>
        public static string FormatDuration(double seconds)
        {
            var whole = (long)Math.Ceiling(Math.Max(0, seconds));
            var ci = System.Globalization.CultureInfo.InvariantCulture;
            return whole >= 3600
                ? string.Format(ci, "{0}:{1:00}:{2:00}", whole / 3600, whole / 60 % 60, whole % 60)
                : string.Format(ci, "{0}:{1:00}", whole / 60, whole % 60);
        }
    }
}
