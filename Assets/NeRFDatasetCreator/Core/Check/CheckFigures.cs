using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>Order statistics for the checks' figures.</summary>
    public static class CheckFigures
    {
        /// <summary>The value below which <paramref name="fraction"/> of <paramref name="values"/> lie (nearest rank); NaN when empty. Sorts the list.</summary>
        public static double Percentile(List<double> values, double fraction)
        {
            if (values.Count == 0) return double.NaN;
            values.Sort();
            var rank = (int)Math.Ceiling(fraction * values.Count) - 1;
            return values[Math.Max(0, Math.Min(values.Count - 1, rank))];
        }

        public static double Median(List<double> values) => Percentile(values, 0.5);

        public static string Percent(double fraction) =>
            double.IsNaN(fraction) ? "n/a" : double.IsInfinity(fraction) ? "∞ %" : DatasetCheckResult.Number(100 * fraction, "0.##") + " %";

        public static string Degrees(double radians) => DatasetCheckResult.Number(radians * 180 / Math.PI, "0.##") + "°";
    }
}
