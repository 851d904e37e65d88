using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The rows of the Exposure section's list mode (<see cref="ExposureSettings.Values"/>): one row per entry, EV and
    /// the R, G, B gains, as <c>exposure.values</c> holds them in a config file. A list may hold up to
    /// <see cref="ExposureSettings.MaxValues"/> entries; the window draws the first <see cref="MaxRows"/> (IMGUI draws
    /// every row on every event) and says where the rest are.
    /// </summary>
    public static class ExposureValueRows
    {
        /// <summary>The most rows the window draws.</summary>
        public const int MaxRows = 64;

        /// <summary>The config field of the whole list.</summary>
        public const string ListField = "exposure.values";

        /// <summary>How many rows the window draws for a list of <paramref name="count"/> entries.</summary>
        public static int Shown(int count) => Math.Max(0, Math.Min(count, MaxRows));

        /// <summary>"exposure.values[3]": where the validator reports entry <paramref name="index"/> (its ev and whiteBalance[c]).</summary>
        public static string Field(int index) => ListField + "[" + index.ToString(CultureInfo.InvariantCulture) + "]";

        /// <summary>The fields of the rows drawn for a list of <paramref name="count"/> entries.</summary>
        public static IReadOnlyList<string> ShownFields(int count)
        {
            var fields = new List<string>();
            for (var i = 0; i < Shown(count); i++) fields.Add(Field(i));
            return fields;
        }

        /// <summary>
        /// The entry "Add value" appends: a copy of the last (a bracket is built by changing one number), or no change
        /// (EV 0, gains 1) for an empty list.
        /// </summary>
        public static ViewExposure Next(IReadOnlyList<ViewExposure> values) =>
            values == null || values.Count == 0 ? ViewExposure.Identity : values[values.Count - 1];

        /// <summary>The line above the rows: how the list is used, and where the entries the window does not draw are.</summary>
        public static string Summary(int count)
        {
            if (count <= 0) return "No values yet: add one per exposure, e.g. EV −1, 0 and +1 for bracketing.";
            var n = count.ToString(CultureInfo.InvariantCulture);
            var text = count == 1
                ? "1 value: every modified view takes it."
                : n + " values: view i of a modified split takes value i mod " + n + ".";
            return count <= MaxRows
                ? text
                : text + " The first " + MaxRows.ToString(CultureInfo.InvariantCulture) + " are shown; edit the rest in a config file (exposure.values).";
        }
    }
}
