using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>The result of <see cref="DatasetValidator"/>: problems (the dataset will fail somewhere), warnings, and what was found.</summary>
    public sealed class DatasetValidationReport
    {
        public string Folder { get; internal set; }
        public List<DatasetProblem> Problems { get; } = new List<DatasetProblem>();
        public List<DatasetProblem> Warnings { get; } = new List<DatasetProblem>();

        /// <summary>Frames per split, for the splits whose transforms file could be read.</summary>
        public SortedDictionary<string, int> FrameCounts { get; } = new SortedDictionary<string, int>(System.StringComparer.Ordinal);

        public int ImagesChecked { get; internal set; }
        public int ExtraFilesChecked { get; internal set; }

        /// <summary>The size every colour image shares, when at least one was read.</summary>
        public int? ImageWidth { get; internal set; }
        public int? ImageHeight { get; internal set; }

        public bool IsValid => Problems.Count == 0;

        public string Summary()
        {
            var sb = new StringBuilder();
            sb.Append(Folder).Append(": ");
            if (FrameCounts.Count == 0) sb.Append("no transforms file read; ");
            else
                sb.Append(string.Join(", ", DatasetSplits.Names.Where(FrameCounts.ContainsKey)
                    .Select(s => s + " " + FrameCounts[s].ToString(CultureInfo.InvariantCulture)))).Append(" frames; ");
            sb.Append(ImagesChecked.ToString(CultureInfo.InvariantCulture)).Append(" images");
            if (ImageWidth.HasValue) sb.Append(" (").Append(ImageWidth.Value.ToString(CultureInfo.InvariantCulture)).Append('×').Append(ImageHeight.Value.ToString(CultureInfo.InvariantCulture)).Append(')');
            sb.Append(", ").Append(ExtraFilesChecked.ToString(CultureInfo.InvariantCulture)).Append(" extra files; ");
            sb.Append(Problems.Count.ToString(CultureInfo.InvariantCulture)).Append(Problems.Count == 1 ? " problem, " : " problems, ");
            sb.Append(Warnings.Count.ToString(CultureInfo.InvariantCulture)).Append(Warnings.Count == 1 ? " warning." : " warnings.");
            return sb.ToString(); // every number above was formatted with the invariant culture
        }
    }
}
