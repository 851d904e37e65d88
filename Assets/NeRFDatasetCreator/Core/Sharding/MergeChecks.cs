using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>One frame of one shard's transforms file (as <see cref="DatasetFolder"/> read it), identified by split and view index.</summary>
    sealed class MergeFrame
    {
        public string Split;
        public int Index;
        public ShardFolder Shard;
        public DatasetFrame Frame;
    }

    /// <summary>The checks merge runs before it touches a file: one job per shard set, every view once, same keys.</summary>
    static class MergeChecks
    {
        static readonly Regex FilePathPattern = new Regex(@"^(?:\./)?([^/]+)/r_(\d+)(\.[A-Za-z0-9]+)?$", RegexOptions.CultureInvariant);
        static readonly Dictionary<string, int> SplitOrder = new Dictionary<string, int> { ["train"] = 0, ["val"] = 1, ["test"] = 2 };

        public static void CheckShardSet(List<ShardFolder> shards, List<ValidationProblem> problems)
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

        public static List<MergeFrame> CollectFrames(List<ShardFolder> shards, ViewCounts counts, List<ValidationProblem> problems, List<string> warnings)
        {
            var frames = new List<MergeFrame>();
            foreach (var shard in shards)
                foreach (var split in ViewCounts.SplitNames)
                {
                    var file = Path.Combine(shard.Folder, ShardMerger.TransformsFileName(split));
                    if (!shard.Transforms.TryGetValue(split, out var transforms))
                    {
                        if (shard.Manifest.Views(split).Count > 0)
                            problems.Add(new ValidationProblem(file, "(missing)", "does not exist, but " + shard.Name + " should hold " + Str(shard.Manifest.Views(split).Count) + " " + split + " views.",
                                "Rerun this shard."));
                        continue;
                    }
                    if (!transforms.HasFrameList)
                    {
                        problems.Add(new ValidationProblem(file + ": frames", transforms.FramesShown == "missing" ? "(missing)" : transforms.FramesShown, "is not a list of frames.", "Rerun this shard."));
                        continue;
                    }
                    var expected = new HashSet<int>(shard.Manifest.Views(split));
                    foreach (var frame in transforms.Frames)
                    {
                        var k = frame.Index;
                        var where = file + ": frames[" + Str(k) + "]";
                        var filePath = frame.FilePath;
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
                        frames.Add(new MergeFrame { Split = split, Index = index, Shard = shard, Frame = frame });
                    }
                }

            foreach (var split in ViewCounts.SplitNames)
            {
                var bySplit = frames.Where(f => f.Split == split).ToLookup(f => f.Index);
                foreach (var group in bySplit.Where(g => g.Count() > 1).OrderBy(g => g.Key))
                    problems.Add(new ValidationProblem(split + "/r_" + Str(group.Key), "duplicated",
                        "appears " + Str(group.Count()) + " times: in " + string.Join(", ", group.Select(f => f.Shard.Folder + Path.DirectorySeparatorChar + ShardMerger.TransformsFileName(split))) + ".",
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
            return frames.OrderBy(f => SplitOrder[f.Split]).ThenBy(f => f.Index).ToList();
        }

        public static void CheckConsistency(List<ShardFolder> shards, List<ValidationProblem> problems, List<string> warnings)
        {
            foreach (var split in ViewCounts.SplitNames)
            {
                var withFile = shards.Where(s => s.Transforms.ContainsKey(split)).ToList();
                if (withFile.Count < 2) continue;
                var reference = withFile[0];
                foreach (var other in withFile.Skip(1))
                    CompareKeys(reference, other, reference.Transforms[split].Top, other.Transforms[split].Top, ShardMerger.TransformsFileName(split), new[] { "frames" }, problems, null);
            }

            var configured = shards.Where(s => s.Config != null).ToList();
            if (configured.Count == 0) return;
            foreach (var s in shards.Where(s => s.Config == null))
                problems.Add(new ValidationProblem(Path.Combine(s.Folder, ShardMerger.ConfigFileName), "(missing)", "is missing while " + configured[0].Name + " has one.", "Rerun this shard."));
            foreach (var other in configured.Skip(1))
            {
                CompareKeys(configured[0], other, configured[0].Config.Json, other.Config.Json, ShardMerger.ConfigFileName, ShardMerger.PerRunConfigKeys, problems, warnings);
            }
        }

        /// <summary>Every key that differs is a problem, except <paramref name="lenient"/> keys: skipped, or a warning when <paramref name="warnings"/> is given.</summary>
        static void CompareKeys(ShardFolder reference, ShardFolder other, JObject a, JObject b, string file, IReadOnlyList<string> lenient,
            List<ValidationProblem> problems, List<string> warnings)
        {
            var keys = a.Properties().Select(p => p.Name).Concat(b.Properties().Select(p => p.Name)).Distinct();
            foreach (var key in keys)
            {
                if (JToken.DeepEquals(a[key], b[key])) continue;
                if (lenient.Contains(key))
                {
                    if (warnings != null && key != "createdUtc" && key != "imagesRendered" && key != "statistics" && key != PointCloudRecord.Key && key != GeometryPackRecord.Key)
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

        static string Str(int value) => value.ToString(CultureInfo.InvariantCulture);
    }
}
