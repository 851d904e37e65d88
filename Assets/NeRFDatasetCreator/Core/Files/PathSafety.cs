using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Keeps reads and moves inside the folder they belong to (a shard, a dataset): a relative path may not be rooted
    /// or climb with "..", and no folder or file on the way may be a symbolic link, whose target could be anywhere —
    /// Core targets .NET Standard 2.1, which cannot resolve a link, so every link is refused rather than followed.
    /// </summary>
    public static class PathSafety
    {
        /// <summary>
        /// The absolute path of <paramref name="relative"/> (forward or back slashes, an optional leading "./") inside
        /// <paramref name="root"/>, or null with <paramref name="reason"/> when it leaves it: rooted, "..", or through a link.
        /// </summary>
        public static string Inside(string root, string relative, out string reason)
        {
            reason = null;
            var normalised = ExportPaths.Normalise(relative ?? "");
            if (normalised.Length == 0 || Path.IsPathRooted(normalised) || System.Array.IndexOf(normalised.Split('/'), "..") >= 0)
            {
                reason = "leaves " + root + " (paths must be relative and stay inside it)";
                return null;
            }
            var rootFull = Path.GetFullPath(root).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            var full = Path.GetFullPath(Path.Combine(rootFull, normalised.Replace('/', Path.DirectorySeparatorChar)));
            if (!full.StartsWith(rootFull + Path.DirectorySeparatorChar, StringComparison.Ordinal))
            {
                reason = "leaves " + rootFull;
                return null;
            }
            var link = LinkOnPath(rootFull, full);
            if (link != null)
            {
                reason = "goes through the symbolic link " + link + ", which may point outside " + rootFull + "; links are never followed (replace it by the files it points to)";
                return null;
            }
            return full;
        }

        /// <summary>The first entry from <paramref name="root"/> (exclusive) down to <paramref name="full"/> (inclusive) that is a symbolic link, or null.</summary>
        public static string LinkOnPath(string root, string full)
        {
            var relative = full.Substring(root.Length).TrimStart(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            var current = root;
            foreach (var part in relative.Split(new[] { Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar }, StringSplitOptions.RemoveEmptyEntries))
            {
                current = Path.Combine(current, part);
                if (IsLink(current)) return current;
            }
            return null;
        }

        /// <summary>True when <paramref name="path"/> exists and is a symbolic link (or a Windows junction).</summary>
        public static bool IsLink(string path)
        {
            try
            {
                var info = new FileInfo(path);
                return info.Exists || Directory.Exists(path) ? (info.Attributes & FileAttributes.ReparsePoint) != 0 : false;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException)
            {
                return false;
            }
        }
    }
}
