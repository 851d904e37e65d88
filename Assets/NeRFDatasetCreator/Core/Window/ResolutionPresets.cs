using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The window's resolution popup: the square sizes of <see cref="DatasetSettings.SizePresets"/> (nerf_synthetic's
    /// 800 and its half and double), then "Custom", which shows free width and height fields.
    /// </summary>
    public static class ResolutionPresets
    {
        /// <summary>The popup entries: one per preset, "Custom" last.</summary>
        public static string[] Labels()
        {
            var presets = DatasetSettings.SizePresets;
            var labels = new string[presets.Length + 1];
            for (var i = 0; i < presets.Length; i++)
            {
                var size = presets[i].ToString(CultureInfo.InvariantCulture);
                labels[i] = size + " × " + size;
            }
            labels[presets.Length] = "Custom";
            return labels;
        }

        /// <summary>The index of the "Custom" entry.</summary>
        public static int CustomIndex => DatasetSettings.SizePresets.Length;

        /// <summary>The preset showing <paramref name="width"/>×<paramref name="height"/>, or <see cref="CustomIndex"/>.</summary>
        public static int IndexOf(int width, int height)
        {
            if (width != height) return CustomIndex;
            var index = Array.IndexOf(DatasetSettings.SizePresets, width);
            return index >= 0 ? index : CustomIndex;
        }

        /// <summary>
        /// The entry the popup shows: "Custom" once the user chose it, even for a square preset size (else the
        /// width and height fields would vanish as soon as they were revealed), otherwise the size's own entry.
        /// </summary>
        public static int Shown(int width, int height, bool customChosen) => customChosen ? CustomIndex : IndexOf(width, height);

        /// <summary>
        /// Applies a popup choice: a preset sets both sides; "Custom" keeps the current size, so choosing it never
        /// changes the dataset, it only reveals the fields.
        /// </summary>
        public static void Apply(int index, DatasetSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            if (index < 0 || index > CustomIndex)
                throw new ArgumentOutOfRangeException(nameof(index), index, "Choose 0 to " + CustomIndex + ".");
            if (index == CustomIndex) return;
            settings.Width = settings.Height = DatasetSettings.SizePresets[index];
        }
    }
}
