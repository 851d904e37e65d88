using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The window's Sparse-view splits field (step 5, Outputs): the config's <c>sparseViews</c> as text, "8" or "3, 6, 9"
    /// (empty: none), and back. The field commits on Enter or when it loses focus, so a half-typed list is never read.
    /// </summary>
    public static class SparseViewsChoices
    {
        public const string Label = "Sparse-view splits";

        public const string Tooltip =
            "Train view counts, e.g. 8 or 3, 6, 9: the capture writes splits/sparse_<n>.json for each (nerf_synthetic's rig with 8 gets DietNeRF / FreeNeRF's list, " +
            "any other rig farthest-point views), for nerf-dataset evaluate --split sparse_<n>. Empty: none (nerf-dataset splits writes them later).";

        /// <summary>"8", "3, 6, 9", or "" for none.</summary>
        public static string Text(int[] counts) =>
            counts == null ? "" : string.Join(", ", counts.Select(n => n.ToString(CultureInfo.InvariantCulture)));

        /// <summary>The counts of <paramref name="text"/> (commas or spaces between whole numbers; empty: none), or null when it is not such a list.</summary>
        public static int[] Parse(string text)
        {
            var parts = (text ?? "").Split(new[] { ',', ' ', ';' }, System.StringSplitOptions.RemoveEmptyEntries);
            var counts = new int[parts.Length];
            for (var i = 0; i < parts.Length; i++)
                if (!int.TryParse(parts[i], NumberStyles.None, CultureInfo.InvariantCulture, out counts[i])) return null;
            return counts;
        }
    }
}
