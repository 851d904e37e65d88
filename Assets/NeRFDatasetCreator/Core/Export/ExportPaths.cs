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
        public static string RelativeTo(string fromDirectory, string rootDirectory, string rootRelativePath)
        {
            var absolute = Path.GetFullPath(Path.Combine(rootDirectory, rootRelativePath));
            return Path.GetRelativePath(Path.GetFullPath(fromDirectory), absolute).Replace('\\', '/');
        }
    }
}
