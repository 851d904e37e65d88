using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>The window's sentences, built from Core values so that they are tested and read the same everywhere.</summary>
    public static class WindowText
    {
        /// <summary>A length for display: three significant digits, invariant culture ("0.866", "12.4", "1250").</summary>
        public static string Length(double value)
        {
            if (double.IsNaN(value) || double.IsInfinity(value)) return value.ToString(CultureInfo.InvariantCulture);
            if (value == 0) return "0";
            var digits = Math.Max(0, 2 - (int)Math.Floor(Math.Log10(Math.Abs(value))));
            return Math.Round(value, Math.Min(digits, 15)).ToString("0.###############", CultureInfo.InvariantCulture);
        }

        /// <summary>
        /// The target line of step 1: the bounding sphere and the distance <see cref="AutoDistanceRule"/> suggests for
        /// the current field of view and image size; what is missing when the target has no bounds.
        /// </summary>
        public static string TargetSummary(PlanTarget target, DatasetSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            if (!target.HasBounds) return "No renderer bounds: the target has nothing to capture, and no distance can be suggested.";
            var text = "Bounding sphere radius " + Length(target.BoundingRadius) + " (diameter " + Length(2 * target.BoundingRadius) + ")";
            var suggested = SuggestedDistance(target, settings);
            return suggested.HasValue
                ? text + "; suggested distance " + Length(suggested.Value) + "."
                : text + "; fix the field of view and size to get a suggested distance.";
        }

        /// <summary>The automatic distance for this target and camera, or null when the target or camera values do not allow one.</summary>
        public static double? SuggestedDistance(PlanTarget target, DatasetSettings settings)
        {
            if (!target.HasBounds || settings?.Camera == null) return null;
            var fov = settings.Camera.VerticalFovDegrees;
            if (!(fov > 0 && fov < 180) || settings.Width <= 0 || settings.Height <= 0) return null;
            var margin = settings.AutoDistanceMargin >= AutoDistanceRule.MinMargin && settings.AutoDistanceMargin <= AutoDistanceRule.MaxMargin
                ? settings.AutoDistanceMargin
                : AutoDistanceRule.DefaultMargin;
            return AutoDistanceRule.Distance(target.BoundingRadius, fov, settings.Width, settings.Height, margin);
        }

        /// <summary>"400 views (train 100 · val 100 · test 200), 800 × 800, supersampling 2×."</summary>
        public static string RunSummary(DatasetSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            var counts = DatasetSplits.All.Select(s => settings.Split(s)?.Count ?? 0).ToList();
            var total = counts.Sum(c => (long)Math.Max(0, c));
            var parts = DatasetSplits.All.Select((s, i) => DatasetSplits.Name(s) + " " + counts[i].ToString(CultureInfo.InvariantCulture));
            var text = total.ToString(CultureInfo.InvariantCulture) + (total == 1 ? " view" : " views") +
                       " (" + string.Join(" · ", parts) + "), " + settings.Width.ToString(CultureInfo.InvariantCulture) + " × " +
                       settings.Height.ToString(CultureInfo.InvariantCulture);
            if (settings.Supersampling > 1) text += ", supersampling " + settings.Supersampling.ToString(CultureInfo.InvariantCulture) + "×";
            return text + ".";
        }

        /// <summary>How a problem reads under its field: the value, why it is wrong and the fix (the field is the control's own label).</summary>
        public static string Problem(ValidationProblem problem)
        {
            if (problem == null) throw new ArgumentNullException(nameof(problem));
            var value = problem.Value.Length == 0 ? "" : problem.Value + " ";
            return value + problem.Reason + (problem.Fix.Length == 0 ? "" : " " + problem.Fix);
        }

        /// <summary>A problem listed away from its field (in a config-load report or at the Create step): with the field's path.</summary>
        public static string ProblemWithField(ValidationProblem problem) => problem.Field + ": " + Problem(problem);

        /// <summary>A config that could not be read, with the place to look.</summary>
        public static string ConfigError(SettingsFormatException error)
        {
            if (error == null) throw new ArgumentNullException(nameof(error));
            var all = error.All;
            if (all.Count > 1)
            {
                // Every wrong value at once, so that one load shows all there is to fix.
                var parts = new System.Collections.Generic.List<string>();
                foreach (var e in all) parts.Add(Where(e) + (e.Field.Length == 0 ? "" : e.Field + ": ") + e.Detail);
                return "Not loaded (" + all.Count.ToString(CultureInfo.InvariantCulture) + " errors in " + System.IO.Path.GetFileName(error.FileName) + "): " +
                       string.Join(" ", parts) + " The window's settings are unchanged.";
            }
            var where = error.Line > 0
                ? "line " + error.Line.ToString(CultureInfo.InvariantCulture) + ", column " + error.Column.ToString(CultureInfo.InvariantCulture)
                : "";
            var field = error.Field.Length == 0 ? "" : error.Field + ": ";
            return "Not loaded (" + (where.Length == 0 ? "" : where + " of ") + System.IO.Path.GetFileName(error.FileName) + "): " + field + error.Detail +
                   " The window's settings are unchanged.";
        }

        static string Where(SettingsFormatException e) =>
            e.Line > 0 ? "(line " + e.Line.ToString(CultureInfo.InvariantCulture) + ", column " + e.Column.ToString(CultureInfo.InvariantCulture) + ") " : "";

        /// <summary>The progress line under the Create button.</summary>
        public static string Progress(int done, int total, double viewsPerSecond)
        {
            var text = done.ToString(CultureInfo.InvariantCulture) + " / " + total.ToString(CultureInfo.InvariantCulture) + " views";
            if (viewsPerSecond > 0) text += ", " + viewsPerSecond.ToString("0.0", CultureInfo.InvariantCulture) + " views/s";
            return text;
        }

        /// <summary>The names of the loaders, for the Output step's hint.</summary>
        public static string Loaders(TargetLoaders loaders)
        {
            var names = TargetLoaderNames.NamesOf(loaders).ToList();
            return names.Count == 0 ? "none" : string.Join(", ", names);
        }

        /// <summary>The formation popup's entries, in <see cref="FormationKinds.All"/> order.</summary>
        public static string[] FormationLabels() => FormationKinds.All.Select(FormationLabel).ToArray();

        public static string FormationLabel(FormationKind kind)
        {
            switch (kind)
            {
                case FormationKind.Halo: return "Halo (one ring)";
                case FormationKind.Sphere: return "Sphere (even, all around)";
                case FormationKind.SemiSphere: return "Semi-sphere (upper half, spiral)";
                case FormationKind.Random: return "Random (seeded)";
                case FormationKind.Orbit: return "Orbit (rising spiral path)";
                default: throw new ArgumentOutOfRangeException(nameof(kind), kind, "not a formation kind");
            }
        }

        /// <summary>The Time step's mode popup, in <see cref="TimeMode"/> order.</summary>
        public static readonly string[] TimeModeLabels =
        {
            "Static (no time)",
            "Monocular (D-NeRF: one train view per step)",
            "Multi-view (every camera at every step)",
        };

        /// <summary>The Time step's source mask, bit i = option i as <see cref="TimeSources"/> numbers them.</summary>
        public static readonly string[] TimeSourceLabels = { "Timeline (PlayableDirector)", "Animator", "Animation (legacy)", "Particles" };

        /// <summary>How the Time step counts steps: a number of steps, or a frame rate.</summary>
        public static readonly string[] TimeStepsLabels = { "Number of steps", "Frame rate" };

        /// <summary>The depth and normal popups' entries, in <see cref="ExtraOutput"/> order.</summary>
        public static readonly string[] ExtraOutputLabels = { "None", "PNG (16-bit / 8-bit)", "EXR (float)", "PNG + EXR" };

        /// <summary>Labels of <see cref="NormalisationMode"/>, in its order.</summary>
        public static readonly string[] NormalisationLabels =
        {
            "None (Unity world units and origin)",
            "Recentre on the target",
            "nerf_synthetic scale (cameras 4 units out)",
            "Fit the target to a radius",
        };

        /// <summary>Joins lines for a help box.</summary>
        public static string Lines(IEnumerable<string> lines) => string.Join("\n", lines);
    }
}
