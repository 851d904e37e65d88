using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>Constants and checks shared by the formations.</summary>
    static class FormationMath
    {
        /// <summary>The golden ratio φ = (1 + √5) / 2.</summary>
        public static readonly double GoldenRatio = (1.0 + Math.Sqrt(5.0)) / 2.0;

        public const double DegToRad = Math.PI / 180.0;

        /// <summary>The largest view count a formation accepts: far beyond any real dataset, small enough to plan in memory.</summary>
        public const int MaxViews = 100000;

        public static ValidationProblem CheckCount(int count) =>
            ValidationProblem.OutsideRange("count", count, 0, MaxViews);

        /// <summary>A problem unless −90 &lt; value &lt; 90: a camera exactly on the pole would make all ring cameras coincide.</summary>
        public static ValidationProblem CheckOpenElevation(string field, double degrees)
        {
            if (degrees > -90 && degrees < 90) return null;
            return new ValidationProblem(field, ValidationProblem.Format(degrees),
                double.IsNaN(degrees) || double.IsInfinity(degrees) ? "is not a finite number." : "must be strictly between -90 and 90 degrees.",
                "Use an elevation above -90 and below 90 degrees (0 is level with the target).");
        }

        public static IReadOnlyList<ValidationProblem> Collect(string prefix, params ValidationProblem[] problems) =>
            problems.Where(p => p != null)
                .Select(p => new ValidationProblem(prefix.Length == 0 ? p.Field : prefix + "." + p.Field, p.Value, p.Reason, p.Fix))
                .ToList();

        public static void ThrowIfInvalid(ICameraFormation formation, int count)
        {
            var problems = formation.Validate(formation.Kind).ToList();
            var countProblem = CheckCount(count);
            if (countProblem != null) problems.Add(countProblem);
            if (problems.Count > 0) throw new InvalidParameterException(problems);
        }

        /// <summary>asin clamped to [−1, 1], so rounding can never turn a valid height into NaN.</summary>
        public static double SafeAsin(double x) => Math.Asin(Math.Max(-1.0, Math.Min(1.0, x)));

        public static double WrapRadians(double radians)
        {
            var wrapped = radians % (2 * Math.PI);
            return wrapped < 0 ? wrapped + 2 * Math.PI : wrapped;
        }
    }
}
