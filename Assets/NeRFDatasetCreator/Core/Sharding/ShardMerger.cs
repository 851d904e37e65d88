using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.RegularExpressions;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Joins the folders of a sharded capture (each a partial Blender-format dataset with a <see cref="ShardManifest"/>)
    /// into one dataset. Everything is checked before any file is touched: every planned view present exactly once,
    /// every referenced file present, the same camera keys and <c>dataset_config.json</c> in every shard. Only then
    /// are the files copied (or moved) into a hidden sibling of the output folder, the merged
    /// <c>transforms_*.json</c> written there, and the folder renamed into place. An existing output folder is never
    /// written into; on any failure the moves are undone and the partial folder removed, so no data is lost.
    /// Frames are handled as JSON objects and kept key for key, so merge works with whatever the writer puts in them.
    /// </summary>
    public static class ShardMerger
    {
        public const string ConfigFileName = "dataset_config.json";

        /// <summary>
        /// Top-level keys of <c>dataset_config.json</c> that describe one run rather than the dataset (when and
        /// where it ran, what it rendered): they may differ between shards, which merge reports as a warning. Every
        /// other key (settings, seed, distance, target, plugin version) must be identical.
        /// </summary>
        public static readonly IReadOnlyList<string> PerRunConfigKeys = new[] { "createdUtc", "imagesRendered", "statistics", "tool", "unityVersion", "shard" };

        static readonly Regex FilePathPattern = new Regex(@"^(?:\./)?([^/]+)/r_(\d+)(\.[A-Za-z0-9]+)?$", RegexOptions.CultureInvariant);
        static readonly Regex ViewFilePattern = new Regex(@"^r_(\d+)(?:[^0-9].*)?$", RegexOptions.CultureInvariant);

        public static string TransformsFileName(string split) => "transforms_" + split + ".json";

        /// <summary>
        /// Merges <paramref name="shardFolders"/> into <paramref name="outputFolder"/>, which must not exist.
        /// <paramref name="moveFiles"/> moves the images instead of copying them (faster, no extra disk space; the
        /// shard folders then keep only their JSON files).
        /// </summary>
        public static MergeResult Merge(IReadOnlyList<string> shardFolders, string outputFolder, bool moveFiles = false)
        {
            var problems = new List<ValidationProblem>();
            var warnings = new List<string>();
            var empty = new Dictionary<string, int>();
            if (string.IsNullOrWhiteSpace(outputFolder))
                return Fail(new ValidationProblem("output", outputFolder ?? "(missing)", "is empty.", "Name the folder to create for the merged dataset, e.g. --out NeRFDatasets/lego."), warnings);
            var output = Path.GetFullPath(outputFolder);
            if (Directory.Exists(output) || File.Exists(output))
                return Fail(new ValidationProblem("output", output, "already exists; merge never writes into or over an existing folder.",
                    "Choose a new folder name, or move the existing one away first."), warnings);

            var shards = ReadShards(shardFolders, problems);
            if (problems.Count > 0) return new MergeResult(output, problems, warnings, empty, 0);
            CheckShardSet(shards, problems);
            if (problems.Count > 0) return new MergeResult(output, problems, warnings, empty, 0);

            var counts = shards[0].Manifest.Counts;
            var frames = CollectFrames(shards, counts, problems, warnings);
            CheckConsistency(shards, problems, warnings);
            var transfers = PlanTransfers(shards, frames, problems, warnings);
            if (problems.Count > 0) return new MergeResult(output, problems, warnings, empty, 0);

            var perSplit = ViewCounts.SplitNames.ToDictionary(s => s, s => frames.Count(f => f.Split == s));
            var failure = Write(shards, frames, transfers, output, moveFiles);
            if (failure != null) return Fail(failure, warnings);
            return new MergeResult(output, problems, warnings, perSplit, transfers.Count);
        }

        sealed class Shard
        {
            public string Folder;
            public ShardManifest Manifest;
            public readonly Dictionary<string, JObject> Transforms = new Dictionary<string, JObject>();
            public JToken Config;
            public string Name => "shard " + Manifest.Shard + " (" + Folder + ")";
        }

        sealed class Frame
        {
            public string Split;
            public int Index;
            public Shard Shard;
            public JObject Json;
        }

        sealed class Transfer
        {
            public string Source;
            public string Relative;
        }

        static MergeResult Fail(ValidationProblem problem, List<string> warnings) =>
            new MergeResult(null, new[] { problem }, warnings, new Dictionary<string, int>(), 0);

        static List<Shard> ReadShards(IReadOnlyList<string> folders, List<ValidationProblem> problems)
        {
            var shards = new List<Shard>();
            if (folders == null || folders.Count == 0)
            {
                problems.Add(new ValidationProblem("shards", "(none)", "no shard folder was given.", "Pass every folder written by the -nerfShard captures."));
                return shards;
            }
            var seen = new HashSet<string>(StringComparer.Ordinal);
            foreach (var given in folders)
            {
                if (string.IsNullOrWhiteSpace(given))
                {
                    problems.Add(new ValidationProblem("shards", "(empty)", "contains an empty folder name.", "Pass the path of each shard folder."));
                    continue;
                }
                var folder = Path.GetFullPath(given).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
                if (!seen.Add(folder))
                {
                    problems.Add(new ValidationProblem("shards", folder, "is given twice.", "Pass each shard folder once."));
                    continue;
                }
                if (!Directory.Exists(folder))
                {
                    problems.Add(new ValidationProblem("shards", folder, "does not exist.", "Check the path; pass the folders the -nerfShard captures wrote."));
                    continue;
                }
                var shard = new Shard { Folder = folder };
                try
                {
                    shard.Manifest = ShardManifest.Read(folder);
                }
                catch (InvalidParameterException e)
                {
                    problems.AddRange(e.Problems);
                    continue;
                }
                foreach (var split in ViewCounts.SplitNames)
                {
                    var json = ReadJson(Path.Combine(folder, TransformsFileName(split)), problems);
                    if (json is JObject o) shard.Transforms[split] = o;
                    else if (json != null) problems.Add(new ValidationProblem(Path.Combine(folder, TransformsFileName(split)), json.Type.ToString(), "is not a JSON object.", "Recapture this shard."));
                }
                shard.Config = ReadJson(Path.Combine(folder, ConfigFileName), problems);
                shards.Add(shard);
            }
            shards.Sort((a, b) => a.Manifest.Shard.Index.CompareTo(b.Manifest.Shard.Index));
            return shards;
        }

        static JToken ReadJson(string path, List<ValidationProblem> problems)
        {
            if (!File.Exists(path)) return null;
            try
            {
                return ParseVerbatim(File.ReadAllText(path));
            }
            catch (JsonException e)
            {
                problems.Add(new ValidationProblem(path, "(unreadable)", "is not valid JSON: " + e.Message, "Recapture this shard."));
                return null;
            }
        }

        static void CheckShardSet(List<Shard> shards, List<ValidationProblem> problems)
        {
            var first = shards[0];
            foreach (var s in shards.Skip(1))
            {
                if (s.Manifest.Shard.Count != first.Manifest.Shard.Count)
                    problems.Add(new ValidationProblem(s.Folder + ": shardCount", Str(s.Manifest.Shard.Count),
                        "differs from " + first.Name + ", which has " + Str(first.Manifest.Shard.Count) + ": the folders come from different jobs.",
                        "Merge only the shards of one job."));
                if (s.Manifest.Counts.ToString() != first.Manifest.Counts.ToString())
                    problems.Add(new ValidationProblem(s.Folder + ": viewCounts", s.Manifest.Counts.ToString(),
                        "differs from " + first.Name + " (" + first.Manifest.Counts + "): the shards were captured from different plans.",
                        "Recapture the odd shard with the job's config."));
            }
            if (problems.Count > 0) return;
            foreach (var group in shards.GroupBy(s => s.Manifest.Shard.Index).Where(g => g.Count() > 1))
                problems.Add(new ValidationProblem("shard " + Str(group.Key) + "/" + Str(first.Manifest.Shard.Count), string.Join(", ", group.Select(s => s.Folder)),
                    "is given more than once.", "Keep one folder per shard index."));
            var present = new HashSet<int>(shards.Select(s => s.Manifest.Shard.Index));
            var missing = Enumerable.Range(0, first.Manifest.Shard.Count).Where(i => !present.Contains(i)).ToList();
            if (missing.Count > 0)
                problems.Add(new ValidationProblem("shards", Str(shards.Count) + " of " + Str(first.Manifest.Shard.Count),
                    "lack shard(s) " + string.Join(", ", missing.Select(i => i + "/" + first.Manifest.Shard.Count)) + ".",
                    "Rerun those shards (e.g. -nerfShard " + missing[0] + "/" + first.Manifest.Shard.Count + ") and pass their folders too."));
        }

        static List<Frame> CollectFrames(List<Shard> shards, ViewCounts counts, List<ValidationProblem> problems, List<string> warnings)
        {
            var frames = new List<Frame>();
            foreach (var shard in shards)
                foreach (var split in ViewCounts.SplitNames)
                {
                    var file = Path.Combine(shard.Folder, TransformsFileName(split));
                    if (!shard.Transforms.TryGetValue(split, out var transforms))
                    {
                        if (shard.Manifest.Views(split).Count > 0)
                            problems.Add(new ValidationProblem(file, "(missing)", "does not exist, but " + shard.Name + " should hold " + Str(shard.Manifest.Views(split).Count) + " " + split + " views.",
                                "Rerun this shard."));
                        continue;
                    }
                    if (!(transforms["frames"] is JArray list))
                    {
                        problems.Add(new ValidationProblem(file + ": frames", transforms["frames"]?.Type.ToString() ?? "(missing)", "is not a list of frames.", "Rerun this shard."));
                        continue;
                    }
                    var expected = new HashSet<int>(shard.Manifest.Views(split));
                    for (var k = 0; k < list.Count; k++)
                    {
                        var where = file + ": frames[" + Str(k) + "]";
                        var frame = list[k] as JObject;
                        var filePath = frame?["file_path"]?.Type == JTokenType.String ? (string)frame["file_path"] : null;
                        var match = filePath == null ? null : FilePathPattern.Match(filePath.Replace('\\', '/'));
                        if (match == null || !match.Success || match.Groups[1].Value != split
                            || !int.TryParse(match.Groups[2].Value, NumberStyles.None, CultureInfo.InvariantCulture, out var index))
                        {
                            problems.Add(new ValidationProblem(where + ".file_path", filePath ?? "(missing)",
                                "is not of the form ./" + split + "/r_<index>, so the view cannot be identified.", "Rerun this shard."));
                            continue;
                        }
                        if (index >= counts.Of(split))
                        {
                            problems.Add(new ValidationProblem(where + ".file_path", filePath,
                                "is beyond the plan's " + Str(counts.Of(split)) + " " + split + " views.", "Rerun this shard with the job's config."));
                            continue;
                        }
                        if (!expected.Contains(index))
                            warnings.Add(where + ": " + split + " r_" + Str(index) + " was not assigned to " + shard.Name + " but is kept.");
                        frames.Add(new Frame { Split = split, Index = index, Shard = shard, Json = frame });
                    }
                }

            foreach (var split in ViewCounts.SplitNames)
            {
                var bySplit = frames.Where(f => f.Split == split).ToLookup(f => f.Index);
                foreach (var group in bySplit.Where(g => g.Count() > 1).OrderBy(g => g.Key))
                    problems.Add(new ValidationProblem(split + "/r_" + Str(group.Key), "duplicated",
                        "appears " + Str(group.Count()) + " times: in " + string.Join(", ", group.Select(f => f.Shard.Folder + Path.DirectorySeparatorChar + TransformsFileName(split))) + ".",
                        "Remove the extra frames, or merge only one folder per shard index."));
                var missingByShard = Enumerable.Range(0, counts.Of(split)).Where(i => !bySplit.Contains(i))
                    .GroupBy(i => ShardAssignment.ShardOf(counts.OffsetOf(split) + i, shards[0].Manifest.Shard.Count));
                foreach (var group in missingByShard.OrderBy(g => g.Key))
                {
                    var owner = shards.FirstOrDefault(s => s.Manifest.Shard.Index == group.Key);
                    var ownerName = owner != null ? owner.Name : "shard " + group.Key + "/" + shards[0].Manifest.Shard.Count + " (not given)";
                    problems.Add(new ValidationProblem(split + " views", Str(group.Count()) + " missing",
                        "r_" + string.Join(", r_", group.Select(Str)) + " are in no shard; " + ownerName + " should have rendered them.",
                        "Rerun that shard (-nerfShard " + group.Key + "/" + shards[0].Manifest.Shard.Count + ") and merge again."));
                }
            }
            return frames.OrderBy(f => Array.IndexOf(ViewCounts.SplitNames.ToArray(), f.Split)).ThenBy(f => f.Index).ToList();
        }

        static void CheckConsistency(List<Shard> shards, List<ValidationProblem> problems, List<string> warnings)
        {
            foreach (var split in ViewCounts.SplitNames)
            {
                var withFile = shards.Where(s => s.Transforms.ContainsKey(split)).ToList();
                if (withFile.Count < 2) continue;
                var reference = withFile[0];
                foreach (var other in withFile.Skip(1))
                    CompareKeys(reference, other, reference.Transforms[split], other.Transforms[split], TransformsFileName(split), new[] { "frames" }, problems, null);
            }

            var configured = shards.Where(s => s.Config != null).ToList();
            if (configured.Count == 0) return;
            foreach (var s in shards.Where(s => s.Config == null))
                problems.Add(new ValidationProblem(Path.Combine(s.Folder, ConfigFileName), "(missing)", "is missing while " + configured[0].Name + " has one.", "Rerun this shard."));
            foreach (var other in configured.Skip(1))
            {
                if (configured[0].Config is JObject a && other.Config is JObject b)
                    CompareKeys(configured[0], other, a, b, ConfigFileName, PerRunConfigKeys, problems, warnings);
                else if (!JToken.DeepEquals(configured[0].Config, other.Config))
                    problems.Add(new ValidationProblem(Path.Combine(other.Folder, ConfigFileName), "", "differs from " + configured[0].Name + ".", "Capture every shard with the same config."));
            }
        }

        /// <summary>Every key that differs is a problem, except <paramref name="lenient"/> keys: skipped, or a warning when <paramref name="warnings"/> is given.</summary>
        static void CompareKeys(Shard reference, Shard other, JObject a, JObject b, string file, IReadOnlyList<string> lenient,
            List<ValidationProblem> problems, List<string> warnings)
        {
            var keys = a.Properties().Select(p => p.Name).Concat(b.Properties().Select(p => p.Name)).Distinct();
            foreach (var key in keys)
            {
                if (JToken.DeepEquals(a[key], b[key])) continue;
                if (lenient.Contains(key))
                {
                    if (warnings != null && key != "createdUtc" && key != "imagesRendered" && key != "statistics")
                        warnings.Add(Path.Combine(other.Folder, file) + ": " + key + " is " + Show(b[key]) + " but " + Show(a[key]) + " in " + reference.Name + " (allowed: it describes the run, not the dataset).");
                    continue;
                }
                problems.Add(new ValidationProblem(Path.Combine(other.Folder, file) + ": " + key, Show(b[key]),
                    "differs from " + reference.Name + ", which has " + Show(a[key]) + ".",
                    "Every shard must be captured with the same config; rerun this shard with it."));
            }
        }

        static string Show(JToken token)
        {
            if (token == null) return "(missing)";
            var text = token.ToString(Formatting.None);
            return text.Length <= 80 ? text : text.Substring(0, 77) + "...";
        }

        static List<Transfer> PlanTransfers(List<Shard> shards, List<Frame> frames, List<ValidationProblem> problems, List<string> warnings)
        {
            var transfers = new List<Transfer>();
            var destinations = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
            var claimed = new HashSet<string>(StringComparer.Ordinal);

            void Add(string source, string relative, string owner)
            {
                if (!claimed.Add(source)) return;
                if (destinations.TryGetValue(relative, out var previous))
                {
                    problems.Add(new ValidationProblem(relative, source, "would overwrite " + previous + " in the merged dataset.", "Remove one of the two files (" + owner + ")."));
                    return;
                }
                destinations[relative] = source;
                transfers.Add(new Transfer { Source = source, Relative = relative });
            }

            // Every file in a split folder that belongs to a kept frame (r_12.png, r_12_depth.exr, r_12_normal_0000.png …).
            var byView = new Dictionary<string, List<string>>(StringComparer.Ordinal);
            foreach (var shard in shards)
                foreach (var split in ViewCounts.SplitNames)
                {
                    var dir = Path.Combine(shard.Folder, split);
                    if (!Directory.Exists(dir)) continue;
                    foreach (var path in Directory.GetFiles(dir).OrderBy(p => p, StringComparer.Ordinal))
                    {
                        var m = ViewFilePattern.Match(Path.GetFileName(path));
                        var key = m.Success ? shard.Folder + "|" + split + "|" + m.Groups[1].Value.TrimStart('0').PadLeft(1, '0') : null;
                        if (key == null) { warnings.Add(path + " is not a view's file and was left in place."); continue; }
                        if (!byView.TryGetValue(key, out var list)) byView[key] = list = new List<string>();
                        list.Add(path);
                    }
                }

            foreach (var frame in frames)
            {
                var owner = frame.Shard.Name;
                var key = frame.Shard.Folder + "|" + frame.Split + "|" + Str(frame.Index);
                // Files the frame names: file_path (".png" appended when extensionless, as the loaders do) and any *_path key.
                foreach (var property in frame.Json.Properties())
                {
                    if (property.Value.Type != JTokenType.String) continue;
                    if (property.Name != "file_path" && !property.Name.EndsWith("_path", StringComparison.Ordinal)) continue;
                    var relative = ((string)property.Value).Replace('\\', '/');
                    if (relative.StartsWith("./", StringComparison.Ordinal)) relative = relative.Substring(2);
                    if (property.Name == "file_path" && Path.GetExtension(relative).Length == 0) relative += ".png";
                    var where = Path.Combine(frame.Shard.Folder, TransformsFileName(frame.Split)) + ": " + frame.Split + " r_" + Str(frame.Index) + "." + property.Name;
                    if (relative.Length == 0 || Path.IsPathRooted(relative) || relative.Split('/').Contains(".."))
                    {
                        problems.Add(new ValidationProblem(where, (string)property.Value, "points outside the shard folder.", "Paths in a dataset must be relative and stay inside it."));
                        continue;
                    }
                    var source = Path.Combine(frame.Shard.Folder, relative.Replace('/', Path.DirectorySeparatorChar));
                    if (!File.Exists(source))
                    {
                        problems.Add(new ValidationProblem(where, (string)property.Value, "names " + source + ", which does not exist.", "Rerun " + owner + "; its capture did not finish."));
                        continue;
                    }
                    Add(source, relative, owner);
                }
                if (byView.TryGetValue(key, out var files))
                {
                    foreach (var path in files) Add(path, frame.Split + "/" + Path.GetFileName(path), owner);
                    byView.Remove(key);
                }
            }
            foreach (var leftover in byView.Values.SelectMany(v => v))
                warnings.Add(leftover + " belongs to no frame of its shard's transforms and was left in place.");

            var known = new HashSet<string>(ViewCounts.SplitNames.Concat(ViewCounts.SplitNames.Select(TransformsFileName)).Concat(new[] { ShardManifest.FileName, ConfigFileName }), StringComparer.Ordinal);
            foreach (var shard in shards)
                foreach (var entry in Directory.EnumerateFileSystemEntries(shard.Folder).OrderBy(p => p, StringComparer.Ordinal))
                    if (!known.Contains(Path.GetFileName(entry)) && !claimed.Contains(entry))
                        warnings.Add(entry + " is not part of the Blender-format splits and was not merged (per-shard extras such as a point cloud or a nerfstudio transforms.json must be made again from the merged dataset).");
            return transfers;
        }

        /// <summary>Builds the dataset in a hidden sibling folder and renames it into place; returns the problem on failure, after undoing everything.</summary>
        static ValidationProblem Write(List<Shard> shards, List<Frame> frames, List<Transfer> transfers, string output, bool move)
        {
            var parent = Path.GetDirectoryName(output);
            var staging = Path.Combine(parent ?? ".", "." + Path.GetFileName(output) + ".merging-" + Guid.NewGuid().ToString("N").Substring(0, 8));
            var moved = new List<Transfer>();
            try
            {
                Directory.CreateDirectory(staging);
                foreach (var t in transfers)
                {
                    var destination = Path.Combine(staging, t.Relative.Replace('/', Path.DirectorySeparatorChar));
                    Directory.CreateDirectory(Path.GetDirectoryName(destination));
                    if (move)
                    {
                        File.Move(t.Source, destination);
                        moved.Add(t);
                    }
                    else File.Copy(t.Source, destination, false);
                }
                foreach (var split in ViewCounts.SplitNames)
                {
                    var reference = shards.FirstOrDefault(s => s.Transforms.ContainsKey(split));
                    if (reference == null) continue;
                    var merged = new JObject();
                    foreach (var property in reference.Transforms[split].Properties())
                        merged[property.Name] = property.Name == "frames"
                            ? new JArray(frames.Where(f => f.Split == split).Select(f => f.Json.DeepClone()))
                            : property.Value.DeepClone();
                    if (merged["frames"] == null) merged["frames"] = new JArray(frames.Where(f => f.Split == split).Select(f => f.Json.DeepClone()));
                    WriteJson(Path.Combine(staging, TransformsFileName(split)), merged);
                }
                var config = shards.FirstOrDefault(s => s.Config != null);
                if (config != null) WriteJson(Path.Combine(staging, ConfigFileName), MergedConfig(config.Config, shards));
                Directory.Move(staging, output);
                return null;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                var undone = Undo(moved, staging);
                return new ValidationProblem("output", output, "could not be written: " + e.Message,
                    undone ? "Nothing was changed; fix the cause (disk space, permissions, a folder created meanwhile) and merge again."
                           : "Some moved files could not be put back; they are in " + staging + " under the same relative paths. Move them back before retrying.");
            }
        }

        /// <summary>
        /// The first shard's config made to describe the whole dataset: <c>imagesRendered</c> summed over the shards,
        /// and the per-shard <c>statistics</c> and <c>shard</c> entries dropped.
        /// </summary>
        static JToken MergedConfig(JToken first, List<Shard> shards)
        {
            if (!(first.DeepClone() is JObject merged)) return first.DeepClone();
            merged.Remove("statistics");
            merged.Remove("shard");
            var counts = shards.Select(s => (s.Config as JObject)?["imagesRendered"]).ToList();
            if (counts.All(c => c != null && c.Type == JTokenType.Integer))
                merged["imagesRendered"] = counts.Sum(c => (long)c);
            return merged;
        }

        static bool Undo(List<Transfer> moved, string staging)
        {
            var complete = true;
            for (var i = moved.Count - 1; i >= 0; i--)
            {
                try
                {
                    File.Move(Path.Combine(staging, moved[i].Relative.Replace('/', Path.DirectorySeparatorChar)), moved[i].Source);
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    complete = false;
                }
            }
            if (complete && Directory.Exists(staging))
            {
                try { Directory.Delete(staging, true); }
                catch (IOException) { }
                catch (UnauthorizedAccessException) { }
            }
            return complete;
        }

        /// <summary>
        /// Parses JSON keeping strings as written: Newtonsoft's default turns ISO dates into DateTime and writes
        /// them back in another format, which would silently change a frame's or the config's text.
        /// </summary>
        internal static JToken ParseVerbatim(string json)
        {
            using (var reader = new JsonTextReader(new StringReader(json)) { DateParseHandling = DateParseHandling.None })
            {
                var token = JToken.ReadFrom(reader);
                while (reader.Read())
                    if (reader.TokenType != JsonToken.Comment)
                        throw new JsonReaderException("Additional text after the JSON value at line " + reader.LineNumber + ".");
                return token;
            }
        }

        static void WriteJson(string path, JToken json) =>
            File.WriteAllText(path, json.ToString(Formatting.Indented) + "\n", new UTF8Encoding(false));

        static string Str(int value) => value.ToString(CultureInfo.InvariantCulture);
    }
}
