using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>Relative paths as the loaders want them: forward slashes, no leading <c>./</c>.</summary>
    public static class ExportPaths
    {
        public static string Normalise(string relativePath)
        {
            var p = relativePath.Replace('\\', '/');
            while (p.StartsWith("./", System.StringComparison.Ordinal)) p = p.Substring(2);
            return p;
        }

        /// <summary>
        /// The path of <paramref name="rootRelativePath"/> (relative to <paramref name="rootDirectory"/>) as seen from
        /// <paramref name="fromDirectory"/>, with forward slashes — every loader resolves paths against the folder of
        /// its JSON file, so a JSON written elsewhere than the root needs e.g. <c>../train/r_0.png</c>.
        /// </summary>
        /// <summary>
        /// The name a training run of an export is given (<c>-m output/&lt;name&gt;</c>): the dataset's folder name for the
        /// format's default place inside it (<c>lego/colmap</c> → lego), else the export folder's own name
        /// (<c>--out exports/lego-gg</c> → lego-gg, never "exports").
        /// </summary>
        public static string RunName(string outDir, string defaultFolderName)
        {
            var full = Path.GetFullPath(outDir).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            var name = Path.GetFileName(full);
            var parent = Path.GetFileName(Path.GetDirectoryName(full) ?? "");
            var run = name == defaultFolderName && parent.Length > 0 ? parent : name;
            return run.Length > 0 ? run : "dataset";
        }

        public static string RelativeTo(string fromDirectory, string rootDirectory, string rootRelativePath)
        {
            var absolute = Path.GetFullPath(Path.Combine(rootDirectory, rootRelativePath));
            return Path.GetRelativePath(Path.GetFullPath(fromDirectory), absolute).Replace('\\', '/');
        }
    }
}
