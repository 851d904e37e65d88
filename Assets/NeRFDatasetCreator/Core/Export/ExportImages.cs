using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --images copy|link|relative</c>: how an export whose JSON names the dataset's files (nerfstudio's and
    /// instant-ngp's transforms.json: images, depth, masks, the point cloud) reaches them. colmap, gaussian-grouping
    /// and dynamic3dgs always write their own images into the export (renamed or re-encoded), so they take only copy.
    /// </summary>
    public enum ExportImages
    {
        /// <summary>The files are copied into the export under their dataset paths: a self-contained folder. The default outside the dataset.</summary>
        Copy,

        /// <summary>
        /// Hard links under their dataset paths (no second copy on disk; still a self-contained folder: a hard link is
        /// the file itself, which moving or copying the export carries along), or copies where the file system cannot
        /// link (another volume, FAT/exFAT). Never symbolic links, which break when the export moves — the very thing
        /// a self-contained folder is for. Editing a linked file in place edits the dataset's too.
        /// </summary>
        Link,

        /// <summary>The JSON names the dataset's files by relative path (<c>../lego/train/r_0.png</c>): the export works only beside the dataset. The default inside it.</summary>
        Relative,
    }

    public static class ExportImagesModes
    {
        public static readonly string[] Names = { "copy", "link", "relative" };

        public static string Name(ExportImages mode) => Names[(int)mode];

        /// <summary>Parses a <c>--images</c> value (case ignored); null with a problem naming the valid values otherwise.</summary>
        public static ExportImages? Parse(string value, out ValidationProblem problem)
        {
            var index = Array.FindIndex(Names, n => string.Equals(n, value?.Trim(), StringComparison.OrdinalIgnoreCase));
            problem = index >= 0 ? null : new ValidationProblem("--images", value ?? "", "is not copy, link or relative.",
                "Use copy (a self-contained folder), link (the same, by hard links: no extra space) or relative (paths back into the dataset)." + SpellingSuggestion.Sentence(value, Names));
            return index >= 0 ? (ExportImages?)index : null;
        }

        /// <summary>Whether the export of <paramref name="target"/> names the dataset's files from its JSON (and so takes link and relative).</summary>
        public static bool NamesDatasetFiles(ExportTarget target) => target == ExportTarget.Nerfstudio || target == ExportTarget.Ngp;

        /// <summary>
        /// The mode used: the one chosen, else <see cref="ExportImages.Relative"/> for an export inside the dataset
        /// (its default places: the files are beside it anyway) and <see cref="ExportImages.Copy"/> for one elsewhere.
        /// </summary>
        public static ExportImages Resolve(ExportImages? chosen, string datasetRoot, string outDir) =>
            chosen ?? (IsInside(outDir, datasetRoot) ? ExportImages.Relative : ExportImages.Copy);

        /// <summary>Whether <paramref name="path"/> is <paramref name="folder"/> or inside it.</summary>
        public static bool IsInside(string path, string folder)
        {
            var relative = Path.GetRelativePath(Path.GetFullPath(folder), Path.GetFullPath(path));
            return relative == "." || !(relative.StartsWith("..", StringComparison.Ordinal) || Path.IsPathRooted(relative));
        }
    }
}
