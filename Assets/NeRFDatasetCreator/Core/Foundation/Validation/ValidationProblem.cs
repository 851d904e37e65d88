using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One thing wrong with a setting: which field, the value it had, why that is wrong and how to fix it.
    /// Validation collects every problem at once so that a user fixes them in one pass.
    /// </summary>
    [Serializable]
    public sealed class ValidationProblem
    {
        public ValidationProblem(string field, string value, string reason, string fix)
        {
            Field = field ?? throw new ArgumentNullException(nameof(field));
            Value = value ?? "";
            Reason = reason ?? throw new ArgumentNullException(nameof(reason));
            Fix = fix ?? "";
        }

        /// <summary>The setting's path as the user sees it in a config file, e.g. <c>splits.train.halo.elevationDegrees</c>.</summary>
        public string Field { get; }
        public string Value { get; }
        public string Reason { get; }
        public string Fix { get; }

        public override string ToString() =>
            Fix.Length == 0 ? $"{Field} = {Value}: {Reason}" : $"{Field} = {Value}: {Reason} {Fix}";

        /// <summary>Formats a number for a message with the invariant culture, never "1,5".</summary>
        public static string Format(double value) => value.ToString("R", CultureInfo.InvariantCulture);

        /// <summary>A problem when <paramref name="value"/> is NaN, infinite or outside [min, max]; otherwise null.</summary>
        public static ValidationProblem OutsideRange(string field, double value, double min, double max, string unit = "")
        {
            if (!double.IsNaN(value) && !double.IsInfinity(value) && value >= min && value <= max) return null;
            var suffix = unit.Length == 0 ? "" : " " + unit;
            var reason = double.IsNaN(value) || double.IsInfinity(value)
                ? "is not a finite number."
                : $"is outside the valid range [{Format(min)}, {Format(max)}]{suffix}.";
            return new ValidationProblem(field, Format(value), reason, $"Use a value from {Format(min)} to {Format(max)}{suffix}.");
        }

        /// <summary>A problem when <paramref name="value"/> is outside [min, max]; otherwise null.</summary>
        public static ValidationProblem OutsideRange(string field, int value, int min, int max)
        {
            if (value >= min && value <= max) return null;
            return new ValidationProblem(field, value.ToString(CultureInfo.InvariantCulture),
                $"is outside the valid range [{min.ToString(CultureInfo.InvariantCulture)}, {max.ToString(CultureInfo.InvariantCulture)}].",
                $"Use a whole number from {min.ToString(CultureInfo.InvariantCulture)} to {max.ToString(CultureInfo.InvariantCulture)}.");
        }
    }
}
