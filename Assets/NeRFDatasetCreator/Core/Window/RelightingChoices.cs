using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What the window's Relighting section (step 5, Outputs; issue 38) shows and how its text fields read: the kind
    /// popup, the rotations field ("0, 90, 180"), new conditions with unique names, and the renders per view.
    /// </summary>
    public static class RelightingChoices
    {
        /// <summary>The settings section ("relighting"); the section shows every "relighting.…" problem.</summary>
        public const string Field = "relighting";

        /// <summary>The kind popup's labels, in <see cref="LightingKind"/> order.</summary>
        public static readonly string[] KindLabels = { "Environment map", "Point light", "Spot light" };

        /// <summary>Rotations as the field shows them: "0, 90, 180".</summary>
        public static string FormatRotations(double[] rotations) =>
            rotations == null ? "" : string.Join(", ", rotations.Select(r => r.ToString("R", CultureInfo.InvariantCulture)));

        /// <summary>
        /// The field's text as rotations: numbers separated by commas or spaces. Null (and the reason) when a part is not
        /// a number; the settings validator then judges the values (integers in [0, 359], unique).
        /// </summary>
        public static double[] ParseRotations(string text, out string problem)
        {
            problem = null;
            var values = new List<double>();
            foreach (var part in (text ?? "").Split(new[] { ',', ' ', ';' }, StringSplitOptions.RemoveEmptyEntries))
            {
                if (!double.TryParse(part, NumberStyles.Float, CultureInfo.InvariantCulture, out var v))
                {
                    problem = "'" + part + "' is not a number of degrees; write the rotations like 0, 90, 180, 270.";
                    return null;
                }
                values.Add(v);
            }
            if (values.Count == 0) problem = "give at least one rotation, e.g. 0.";
            return problem == null ? values.ToArray() : null;
        }

        /// <summary>A new condition of <paramref name="kind"/> named "env-1", "light-2", … not used by <paramref name="existing"/>.</summary>
        public static LightingCondition NewCondition(LightingKind kind, IEnumerable<LightingCondition> existing)
        {
            var names = new HashSet<string>((existing ?? Enumerable.Empty<LightingCondition>()).Where(c => c != null).Select(c => c.Name), StringComparer.Ordinal);
            var stem = kind == LightingKind.Environment ? "env" : "light";
            var n = 1;
            while (names.Contains(stem + "-" + n)) n++;
            var condition = new LightingCondition { Name = stem + "-" + n, Kind = kind };
            if (kind == LightingKind.Spot) condition.Intensity = 30;
            else if (kind == LightingKind.Point) condition.Intensity = 20;
            return condition;
        }

        /// <summary>The extra colour renders each view gets (one per environment rotation, one per point or spot).</summary>
        public static int RendersPerView(RelightingSettings settings) =>
            settings == null || !settings.Enabled ? 0
                : settings.Conditions.Where(c => c != null).Sum(c => c.Kind == LightingKind.Environment ? Math.Max(1, c.Rotations?.Length ?? 1) : 1);
    }
}
