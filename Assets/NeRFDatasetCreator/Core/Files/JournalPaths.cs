using System;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A journal (<see cref="OperationJournal"/>) is a file in a folder anyone can write, so recovery acts on none of
    /// its paths before each is proved to lie inside the folders its operation owns: a replace's aside is the output's
    /// own <c>&lt;name&gt;.replaced-&lt;id&gt;~</c>; merge moves only between its working folder and the shard folders it
    /// read (each still holding its <c>shard.json</c>); convert only between its working folder and the output. A path
    /// that is rooted where it should be relative, climbs with "..", or passes a symbolic link is refused too.
    /// </summary>
    public static class JournalPaths
    {
        /// <summary>Null when every path in <paramref name="journal"/> stays inside what its operation owns; otherwise why not, naming the journal.</summary>
        /// <param name="asideOnly">For the journal left inside a finished output, of which recovery only uses the aside.</param>
        public static string WhyRefused(string folder, OperationJournal journal, string output, bool asideOnly = false)
        {
            var why = Check(folder, journal, output, asideOnly);
            return why == null ? null : "its journal " + OperationJournal.PathIn(folder) + " " + why;
        }

        static string Check(string working, OperationJournal journal, string output, bool asideOnly)
        {
            if (journal.Aside != null && !IsAsideOf(journal.Aside, output))
                return "names " + journal.Aside + " as the dataset a replace moved aside, which is not " + output + "'s own <name>.replaced-<id>~ folder";
            if (asideOnly) return null;
            foreach (var move in journal.Moves)
            {
                if (PathSafety.Inside(working, move.Value, out var reason) == null) return "names " + move.Value + ", which " + reason;
                if (OwningShard(journal, move.Key) == null)
                    return "names " + move.Key + ", which is not inside one of the shard folders the merge read" +
                           (journal.Shards.Count == 0 ? " (it lists none)" : " (" + string.Join(", ", journal.Shards) + ", each with its " + ShardManifest.FileName + ")");
            }
            foreach (var file in journal.Files)
            {
                if (PathSafety.Inside(working, file, out var reason) == null) return "names " + file + ", which " + reason;
                if (PathSafety.Inside(output, file, out reason) == null) return "names " + file + ", which " + reason;
            }
            return null;
        }

        /// <summary>True when <paramref name="aside"/> is exactly the name a replace of <paramref name="output"/> moves the old dataset to.</summary>
        public static bool IsAsideOf(string aside, string output)
        {
            try
            {
                return Path.IsPathRooted(aside) && WorkingFolders.KindOf(Path.GetFileName(aside)) == "replaced" && WorkingFolders.SamePath(WorkingFolders.OutputOf(aside), output);
            }
            catch (Exception e) when (e is ArgumentException || e is NotSupportedException || e is PathTooLongException)
            {
                return false;
            }
        }

        /// <summary>The absolute path of <paramref name="from"/> when it lies inside one of the journal's shard folders (a real folder holding shard.json); null otherwise.</summary>
        public static string OwningShard(OperationJournal journal, string from)
        {
            if (string.IsNullOrEmpty(from) || !Path.IsPathRooted(from)) return null;
            foreach (var shard in journal.Shards.Where(s => !string.IsNullOrEmpty(s) && Path.IsPathRooted(s)))
            {
                try
                {
                    var root = Path.GetFullPath(shard).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
                    if (!Directory.Exists(root) || PathSafety.IsLink(root) || !File.Exists(Path.Combine(root, ShardManifest.FileName))) continue;
                    var full = Path.GetFullPath(from);
                    if (!full.StartsWith(root + Path.DirectorySeparatorChar, StringComparison.Ordinal)) continue;
                    var inside = PathSafety.Inside(root, full.Substring(root.Length + 1), out _);
                    if (inside != null) return inside;
                }
                catch (Exception e) when (e is ArgumentException || e is NotSupportedException || e is PathTooLongException)
                {
                }
            }
            return null;
        }
    }
}
