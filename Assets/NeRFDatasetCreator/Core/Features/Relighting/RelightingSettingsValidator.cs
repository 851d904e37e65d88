using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text.RegularExpressions;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The problems of the "relighting" section (<see cref="SettingsValidator"/> adds them), each naming its key
    /// (<c>relighting.conditions[2].rotations[1]</c>) and the fix.
    /// </summary>
    public static class RelightingSettingsValidator
    {
        /// <summary>A condition's name: it goes into file names (<c>r_0_light_&lt;name&gt;_090.png</c>) and trainers' light lists.</summary>
        public static readonly Regex NamePattern = new Regex("^[a-z0-9][a-z0-9-]{0,31}$", RegexOptions.CultureInvariant);

        public static IReadOnlyList<ValidationProblem> Validate(DatasetSettings settings)
        {
            var problems = new List<ValidationProblem>();
            var r = settings?.Relighting;
            if (r == null || !r.On) return problems;
            if (r.Conditions == null || r.Conditions.Count == 0)
            {
                problems.Add(new ValidationProblem("relighting.conditions", "[]", "is empty, so no view would be relit.",
                    "List the lighting conditions, e.g. [{ \"name\": \"sunset\", \"kind\": \"environment\", \"file\": \"Assets/HDRI/sunset.exr\" }], or remove the \"relighting\" section."));
                return problems;
            }
            if (settings.MotionBlur != null && settings.MotionBlur.Enabled)
                problems.Add(new ValidationProblem("relighting", "with motionBlur", "cannot be combined with motion blur: a relit image would be a sharp render beside a blurred r_<i>.png, with another alpha.",
                    "Remove the \"motionBlur\" section, or capture the relighting set without it."));
            var names = new Dictionary<string, int>(StringComparer.Ordinal);
            for (var i = 0; i < r.Conditions.Count; i++)
            {
                var c = r.Conditions[i];
                var at = "relighting.conditions[" + Text(i) + "]";
                if (c == null)
                {
                    problems.Add(new ValidationProblem(at, "null", "is not a lighting condition.", "Remove it or give { \"name\": …, \"kind\": … }."));
                    continue;
                }
                var name = c.Name ?? "";
                if (!NamePattern.IsMatch(name))
                    problems.Add(new ValidationProblem(at + ".name", "\"" + name + "\"", "is not a usable name: it goes into file names and trainers' light lists.",
                        "Use 1–32 lowercase letters, digits and '-', starting with a letter or digit, e.g. \"sunset\" or \"olat-03\"."));
                else if (names.TryGetValue(name, out var first))
                    problems.Add(new ValidationProblem(at + ".name", "\"" + name + "\"", "is also the name of relighting.conditions[" + Text(first) + "]; each condition's files are named by it.",
                        "Give every condition its own name."));
                else names[name] = i;
                if (!IsFinite(c.Intensity) || c.Intensity < 0)
                    problems.Add(new ValidationProblem(at + ".intensity", ValidationProblem.Format(c.Intensity), "must be a finite number ≥ 0.", "Use 1 for the map or light as it is."));
                if (c.Kind == LightingKind.Environment) Environment(c, at, problems);
                else Light(c, at, problems);
            }
            return problems;
        }

        static void Environment(LightingCondition c, string at, List<ValidationProblem> problems)
        {
            if (string.IsNullOrWhiteSpace(c.File))
                problems.Add(new ValidationProblem(at + ".file", "\"\"", "is required for an environment: the HDR map (cubemap or equirect texture) that lights the scene.",
                    "Give the texture's project path, e.g. \"Assets/HDRI/sunset.exr\"."));
            var rotations = c.Rotations ?? new double[0];
            if (rotations.Length == 0)
                problems.Add(new ValidationProblem(at + ".rotations", "[]", "is empty, so the environment would light no image.", "Use [0] for the map as it is, or e.g. [0, 90, 180, 270]."));
            var seen = new Dictionary<double, int>();
            for (var k = 0; k < rotations.Length; k++)
            {
                var value = rotations[k];
                var key = at + ".rotations[" + Text(k) + "]";
                if (!IsFinite(value) || value != Math.Floor(value) || value < 0 || value > 359)
                    problems.Add(new ValidationProblem(key, ValidationProblem.Format(value), "must be a whole number of degrees from 0 to 359 (it is written in file names as three digits, e.g. sunset_090).",
                        "Use e.g. " + (IsFinite(value) ? Text(((int)Math.Round(value) % 360 + 360) % 360) : "0") + "."));
                else if (seen.TryGetValue(value, out var first))
                    problems.Add(new ValidationProblem(key, ValidationProblem.Format(value), "repeats rotations[" + Text(first) + "]; each rotation is one more image per view.",
                        "Remove the repeated rotation."));
                else seen[value] = k;
            }
        }

        static void Light(LightingCondition c, string at, List<ValidationProblem> problems)
        {
            Vector(c.Position, at + ".position", false, problems);
            if (c.Kind == LightingKind.Spot)
            {
                if (c.Direction != null) Vector(c.Direction, at + ".direction", true, problems);
                if (!IsFinite(c.SpotAngle) || c.SpotAngle <= 0 || c.SpotAngle >= 180)
                    problems.Add(new ValidationProblem(at + ".spotAngle", ValidationProblem.Format(c.SpotAngle), "must be a cone angle in degrees between 0 and 180.", "Use e.g. 30."));
            }
            var colour = c.Colour;
            if (colour == null || colour.Length != 3 || !(IsFinite(colour[0]) && IsFinite(colour[1]) && IsFinite(colour[2])) || colour[0] < 0 || colour[1] < 0 || colour[2] < 0)
                problems.Add(new ValidationProblem(at + ".colour", Vector(colour), "must be three finite linear values ≥ 0.", "Use [1, 1, 1] for white."));
        }

        static void Vector(double[] v, string key, bool direction, List<ValidationProblem> problems)
        {
            if (v == null || v.Length != 3 || !(IsFinite(v[0]) && IsFinite(v[1]) && IsFinite(v[2])))
                problems.Add(new ValidationProblem(key, Vector(v), "must be three finite numbers [x, y, z] in the output world (+Z up).",
                    direction ? "Give where the spot points, e.g. [0, 0, -1], or leave it out to aim at the target." : "Give the light's position, e.g. [0, -3, 3]."));
            else if (direction && v[0] == 0 && v[1] == 0 && v[2] == 0)
                problems.Add(new ValidationProblem(key, Vector(v), "has no length, so it points nowhere.", "Give where the spot points, e.g. [0, 0, -1], or leave it out to aim at the target."));
        }

        static string Vector(double[] v) => v == null ? "null" : "[" + string.Join(", ", Array.ConvertAll(v, ValidationProblem.Format)) + "]";

        static bool IsFinite(double v) => !double.IsNaN(v) && !double.IsInfinity(v);

        static string Text(int value) => value.ToString(CultureInfo.InvariantCulture);
    }
}
