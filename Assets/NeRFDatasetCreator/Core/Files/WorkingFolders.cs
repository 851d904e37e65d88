using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The names of the working folders the multi-step operations keep until they are complete, and where to find
    /// those of an output: <c>&lt;name&gt;.partial-&lt;stamp&gt;~</c> (plan, capture) and <c>&lt;name&gt;.replaced-&lt;id&gt;~</c>
    /// (the dataset a replace moves aside) beside the output, <c>.&lt;name&gt;.merging-&lt;id&gt;</c> beside it (merge),
    /// and <c>.convert.partial-&lt;stamp&gt;~</c> inside it (convert). The '~' keeps Unity from importing them.
    /// </summary>
    public static class WorkingFolders
    {
        public const string PartialMarker = ".partial-";
        public const string ReplacedMarker = ".replaced-";
        public const string MergingMarker = ".merging-";
        public const string ConvertPrefix = ".convert" + PartialMarker;

        /// <summary>The longest suffix any working folder adds to an output's name (<c>.partial-yyyyMMdd-HHmmss-xxxxxxxx~</c>).</summary>
        public const int LongestSuffix = 35;

        public static string NewPartial(string output, DateTime now) =>
            output + PartialMarker + Stamp(now) + "~";

        public static string NewReplaced(string output) => output + ReplacedMarker + Id() + "~";

        public static string NewMerging(string output) =>
            Path.Combine(Path.GetDirectoryName(output) ?? ".", "." + Path.GetFileName(output) + MergingMarker + Id());

        public static string NewConvert(string output, DateTime now) => Path.Combine(output, ConvertPrefix + Stamp(now) + "~");

        static string Stamp(DateTime now) => now.ToString("yyyyMMdd-HHmmss", CultureInfo.InvariantCulture) + "-" + Id();

        static string Id() => Guid.NewGuid().ToString("N").Substring(0, 8); // hex digits: culture-independent

        // The exact names the tool writes (Stamp: yyyyMMdd-HHmmss-<8 hex>; Id: 8 hex). A user's folder that merely
        // contains a marker ("photos.partial-2024~", "holiday.replaced-old~") is not a working folder.
        const string StampPattern = @"\d{8}-\d{6}-[0-9a-f]{8}";
        static readonly Regex ConvertName = new Regex(@"^\.convert\.partial-" + StampPattern + @"~\z", RegexOptions.CultureInvariant);
        static readonly Regex PartialName = new Regex(@"^(.+)\.partial-" + StampPattern + @"~\z", RegexOptions.CultureInvariant);
        static readonly Regex ReplacedName = new Regex(@"^(.+)\.replaced-[0-9a-f]{8}~\z", RegexOptions.CultureInvariant);
        static readonly Regex MergingName = new Regex(@"^\.(.+)\.merging-[0-9a-f]{8}\z", RegexOptions.CultureInvariant);

        /// <summary>
        /// Creates the working folder <paramref name="working"/> with <paramref name="journal"/> (naming this run, its
        /// owner) already inside: both are made under a birth name that names the run too,
        /// <c>.&lt;working name&gt;.birth-&lt;host&gt;-&lt;pid&gt;-&lt;start&gt;~</c> (<see cref="OperationOwner.NameTag"/>), and
        /// renamed into place in one step. So no folder under a working folder's name is ever without its owner — a
        /// recovery in another process, which removes a journal-less empty working folder as a run killed at birth, can
        /// never take a live run's new folder for one — and a run killed during its birth leaves a folder whose name
        /// proves whose it is (<see cref="Recovery"/> removes it once that run has ended). The caller registers
        /// <paramref name="working"/> first (<see cref="OperationOwner.Register"/>).
        /// </summary>
        public static void Create(string working, OperationJournal journal)
        {
            var birth = Path.Combine(Path.GetDirectoryName(working) ?? ".", "." + Path.GetFileName(working) + BirthMarker + OperationOwner.Current.NameTag + "~");
            OperationOwner.Register(birth);
            try
            {
                FileOps.CreateDirectory(birth);
                journal.Save(birth);
                FileOps.MoveDirectory(birth, working);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                if (Directory.Exists(birth)) Directory.Delete(birth, true); // only this run's journal is in it
                throw;
            }
            finally
            {
                OperationOwner.Release(birth);
            }
        }

        const string BirthMarker = ".birth-";

        static readonly Regex BirthName = new Regex(@"^\.(?<working>.+)" + Regex.Escape(BirthMarker) + OperationOwner.NameTagPattern + @"~\z", RegexOptions.CultureInvariant);

        /// <summary>The working folder a birth folder's name (<see cref="Create"/>) becomes, or null for any other name.</summary>
        public static string BornAs(string name)
        {
            var match = name == null ? Match.Empty : BirthName.Match(name);
            return match.Success && KindOf(match.Groups["working"].Value) != null ? match.Groups["working"].Value : null;
        }

        /// <summary>The run a birth folder's name names (<see cref="Create"/>), or null for any other name.</summary>
        public static OperationOwner BirthOwner(string name) => BornAs(name) == null ? null : OperationOwner.FromNameTag(BirthName.Match(name));

        /// <summary>The birth folders (<see cref="Create"/>) of <paramref name="output"/>'s working folders: beside it and, for convert, inside it.</summary>
        public static IReadOnlyList<string> BirthsOf(string output)
        {
            var found = new List<string>();
            foreach (var folder in new[] { Path.GetDirectoryName(output), output })
            {
                if (folder == null || !Directory.Exists(folder)) continue;
                foreach (var dir in Directory.EnumerateDirectories(folder))
                {
                    var working = BornAs(Path.GetFileName(dir));
                    if (working == null || PathSafety.IsLink(dir)) continue;
                    var kind = KindOf(working);
                    var belongs = kind == "convert" ? SamePath(folder, output) : !SamePath(folder, output) && SamePath(OutputOf(Path.Combine(folder, working)), output);
                    if (belongs) found.Add(dir);
                }
            }
            found.Sort(StringComparer.Ordinal);
            return found;
        }

        /// <summary>What kind of working folder <paramref name="name"/> is — only for the exact names the tool writes — or null for any other name.</summary>
        public static string KindOf(string name)
        {
            if (name == null) return null;
            if (ConvertName.IsMatch(name)) return "convert";
            if (PartialName.IsMatch(name)) return "write";
            if (ReplacedName.IsMatch(name)) return "replaced";
            if (MergingName.IsMatch(name)) return "merge";
            return null;
        }

        /// <summary>The names the tool gives its working folders, for messages.</summary>
        public const string NameFormats = "<name>.partial-<yyyyMMdd-HHmmss>-<8 hex digits>~, <name>.replaced-<8 hex digits>~, .<name>.merging-<8 hex digits>, .convert.partial-<yyyyMMdd-HHmmss>-<8 hex digits>~";

        /// <summary>
        /// True for a name that contains one of the working folders' markers but is not exactly one the tool writes:
        /// <c>nerf-dataset clean</c> lists such a folder as "not ours" and leaves it alone.
        /// </summary>
        public static bool LooksLikeOne(string name) =>
            name != null && KindOf(name) == null && BornAs(name) == null &&
            (name.IndexOf(PartialMarker, StringComparison.Ordinal) >= 0 || name.IndexOf(ReplacedMarker, StringComparison.Ordinal) >= 0 ||
             name.IndexOf(MergingMarker, StringComparison.Ordinal) >= 0);

        /// <summary>The output a working folder's name belongs to (its journal, when readable, says the same).</summary>
        public static string OutputOf(string workingFolder)
        {
            var name = Path.GetFileName(workingFolder);
            var parent = Path.GetDirectoryName(workingFolder) ?? ".";
            switch (KindOf(name))
            {
                case "convert": return parent;
                case "write": return Path.Combine(parent, PartialName.Match(name).Groups[1].Value);
                case "replaced": return Path.Combine(parent, ReplacedName.Match(name).Groups[1].Value);
                case "merge": return Path.Combine(parent, MergingName.Match(name).Groups[1].Value);
                default: return null;
            }
        }

        /// <summary>Every working folder of <paramref name="output"/> (absolute): beside it and, for convert, inside it.</summary>
        public static IReadOnlyList<string> Of(string output)
        {
            var found = new List<string>();
            var parent = Path.GetDirectoryName(output);
            // A symbolic link is never a working folder (the tool makes none), whatever its name: recovery and clean,
            // which finish, roll back and delete working folders, never act through one.
            if (parent != null && Directory.Exists(parent))
                foreach (var dir in Directory.EnumerateDirectories(parent))
                    if (KindOf(Path.GetFileName(dir)) != null && KindOf(Path.GetFileName(dir)) != "convert" && SamePath(OutputOf(dir), output) && !PathSafety.IsLink(dir))
                        found.Add(dir);
            if (Directory.Exists(output))
                foreach (var dir in Directory.EnumerateDirectories(output))
                    if (KindOf(Path.GetFileName(dir)) == "convert" && !PathSafety.IsLink(dir)) found.Add(dir);
            found.Sort(StringComparer.Ordinal);
            return found;
        }

        /// <summary>True when <paramref name="folder"/> holds no file but perhaps a half-written journal (a working folder killed at birth).</summary>
        public static bool HoldsNoFile(string folder) =>
            Directory.EnumerateFiles(folder, "*", SearchOption.AllDirectories)
                .All(f => Path.GetFileName(f).StartsWith(OperationJournal.FileName, StringComparison.Ordinal));

        /// <summary>Files and bytes under <paramref name="folder"/> (0, 0 when it cannot be read).</summary>
        public static (int files, long bytes) SizeOf(string folder)
        {
            int files = 0;
            long bytes = 0;
            try
            {
                foreach (var file in new DirectoryInfo(folder).EnumerateFiles("*", SearchOption.AllDirectories))
                {
                    files++;
                    bytes += file.Length;
                }
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException) { }
            return (files, bytes);
        }

        /// <summary>"3 files, 1.2 MB".</summary>
        public static string DescribeSize(string folder)
        {
            var (files, bytes) = SizeOf(folder);
            return files.ToString(CultureInfo.InvariantCulture) + (files == 1 ? " file, " : " files, ") + FormatBytes(bytes);
        }

        public static string FormatBytes(long bytes)
        {
            if (bytes < 1000) return bytes.ToString(CultureInfo.InvariantCulture) + " B";
            string[] units = { "kB", "MB", "GB", "TB" };
            double value = bytes;
            var unit = -1;
            do
            {
                value /= 1000;
                unit++;
            } while (value >= 1000 && unit < units.Length - 1);
            return value.ToString(value < 10 ? "0.0" : "0", CultureInfo.InvariantCulture) + " " + units[unit];
        }

        public static bool SamePath(string a, string b) =>
            a != null && b != null && string.Equals(Trim(Path.GetFullPath(a)), Trim(Path.GetFullPath(b)), StringComparison.Ordinal);

        static string Trim(string p) => p.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
    }
}
