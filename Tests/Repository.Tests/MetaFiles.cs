using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>What Unity's importer sees in a folder, and the .meta files that belong to it.</summary>
    static class MetaFiles
    {
        static readonly Regex GuidLine = new Regex(@"^guid: (\S*)\s*$", RegexOptions.Multiline);
        static readonly Regex ValidGuid = new Regex("^[0-9a-f]{32}$");

        /// <summary>Unity skips names ending in '~', starting with '.', 'cvs' and '*.tmp' (Manual: special folder names).</summary>
        public static bool IsIgnoredByUnity(string name) =>
            name.EndsWith("~", StringComparison.Ordinal) || name.StartsWith(".", StringComparison.Ordinal) ||
            name.Equals("cvs", StringComparison.OrdinalIgnoreCase) || name.EndsWith(".tmp", StringComparison.OrdinalIgnoreCase);

        /// <summary>Every file and folder below <paramref name="root"/> (not the root itself) that Unity would import.</summary>
        public static IEnumerable<string> ImportedEntries(string root)
        {
            foreach (var entry in Directory.EnumerateFileSystemEntries(root).OrderBy(e => e, StringComparer.Ordinal))
            {
                var name = Path.GetFileName(entry);
                if (IsIgnoredByUnity(name) || name.EndsWith(".meta", StringComparison.Ordinal)) continue;
                yield return entry;
                if (Directory.Exists(entry))
                    foreach (var child in ImportedEntries(entry)) yield return child;
            }
        }

        /// <summary>Every .meta below <paramref name="root"/> that Unity would read (those inside ignored folders are not).</summary>
        public static IEnumerable<string> MetaFilesBelow(string root)
        {
            foreach (var entry in Directory.EnumerateFileSystemEntries(root).OrderBy(e => e, StringComparer.Ordinal))
            {
                var name = Path.GetFileName(entry);
                if (Directory.Exists(entry))
                {
                    if (IsIgnoredByUnity(name)) continue;
                    foreach (var meta in MetaFilesBelow(entry)) yield return meta;
                }
                else if (name.EndsWith(".meta", StringComparison.Ordinal)) yield return entry;
            }
        }

        public static List<string> MissingMetas(string root) =>
            ImportedEntries(root).Where(e => !File.Exists(e + ".meta")).ToList();

        public static List<string> OrphanedMetas(string root) =>
            MetaFilesBelow(root).Where(m =>
            {
                var asset = m.Substring(0, m.Length - ".meta".Length);
                return !File.Exists(asset) && !Directory.Exists(asset) || IsIgnoredByUnity(Path.GetFileName(asset));
            }).ToList();

        /// <summary>The GUID a .meta declares, or null when it has no guid line.</summary>
        public static string GuidOf(string metaPath)
        {
            var match = GuidLine.Match(File.ReadAllText(metaPath));
            return match.Success ? match.Groups[1].Value : null;
        }

        public static bool IsValidGuid(string guid) => guid != null && ValidGuid.IsMatch(guid);
    }
}
