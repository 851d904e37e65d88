using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The config key <c>"sparseViews": [8]</c>: the train view counts whose split files a capture or plan writes
    /// (<see cref="SparseSplitFiles.Write(DatasetWriteSession, CapturePlan)"/>). Written only when set, so configs
    /// without it keep their keys; the window's Sparse-view splits field edits it (<see cref="SparseViewsChoices"/>).
    /// </summary>
    public static class SparseViewsSettings
    {
        public const string Key = "sparseViews";

        public static void Write(JsonWriter w, DatasetSettings s)
        {
            if (s.SparseViews == null || s.SparseViews.Length == 0) return;
            w.WritePropertyName(Key);
            w.WriteStartArray();
            foreach (var n in s.SparseViews) w.WriteValue(n);
            w.WriteEndArray();
        }

        /// <summary>Reads the list; <paramref name="readInt"/> and <paramref name="error"/> are the config reader's (line and column in errors).</summary>
        internal static int[] Read(JToken t, string path, Func<JToken, string, int> readInt, Func<JToken, string, string, SettingsFormatException> error)
        {
            if (t.Type != JTokenType.Array) throw error(t, path, "must be a list of train view counts such as [8] or [3, 6, 9].");
            var index = 0;
            return ((JArray)t).Select(item => readInt(item, path + "[" + index++ + "]")).ToArray();
        }

        public static IEnumerable<ValidationProblem> Validate(DatasetSettings s)
        {
            if (s.SparseViews == null) yield break;
            var train = s.Train?.Count ?? 0;
            foreach (var n in s.SparseViews)
                if (n < 1 || n >= train)
                    yield return new ValidationProblem(Key, n.ToString(System.Globalization.CultureInfo.InvariantCulture),
                        "must be at least 1 and fewer than the " + train + " train views (a sparse split leaves views out).",
                        train > 1 ? "Use counts from 1 to " + (train - 1) + ", e.g. [8], or remove it." : "Give the train split more views, or remove it.");
        }
    }
}
