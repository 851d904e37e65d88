using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>shard.json</c>, written by a sharded capture (<c>-nerfShard i/N</c>) at the root of its output folder next
    /// to its partial <c>transforms_*.json</c>. It tells <c>nerf-dataset merge</c> which views this folder was meant
    /// to hold, so that merge can name the shard responsible for any missing view without re-deriving the plan:
    /// <code>
    /// {
    ///   "format": "nerf-dataset-creator/shard", "version": 1,
    ///   "shardIndex": 2, "shardCount": 4, "assignment": "round-robin",
    ///   "viewCounts": { "train": 100, "val": 100, "test": 200 },
    ///   "views": { "train": [2, 6, …], "val": [2, 6, …], "test": [0, 4, …] }
    /// }
    /// </code>
    /// <c>viewCounts</c> are the whole plan's; <c>views</c> the indices within each split that this shard renders.
    /// A capture without <c>-nerfShard</c> writes no shard.json.
    /// </summary>
    public sealed class ShardManifest
    {
        public const string FileName = "shard.json";
        public const string Format = "nerf-dataset-creator/shard";
        public const int Version = 1;
        public const string RoundRobin = "round-robin";

        readonly Dictionary<string, IReadOnlyList<int>> views;

        ShardManifest(ShardSpec shard, ViewCounts counts, string assignment, Dictionary<string, IReadOnlyList<int>> views)
        {
            Shard = shard;
            Counts = counts;
            Assignment = assignment;
            this.views = views;
        }

        public ShardSpec Shard { get; }
        public ViewCounts Counts { get; }
        public string Assignment { get; }

        /// <summary>The indices within <paramref name="split"/> this shard was meant to render, ascending.</summary>
        public IReadOnlyList<int> Views(string split) => views[split];

        /// <summary>The manifest of <paramref name="shard"/> of a plan with <paramref name="counts"/>, by <see cref="ShardAssignment"/>.</summary>
        public static ShardManifest ForShard(ShardSpec shard, ViewCounts counts)
        {
            if (counts == null) throw new ArgumentNullException(nameof(counts));
            var views = ViewCounts.SplitNames.ToDictionary(s => s, s => ShardAssignment.IndicesInSplit(shard, counts, s));
            return new ShardManifest(shard, counts, RoundRobin, views);
        }

        public JObject ToJson()
        {
            var counts = new JObject();
            var views = new JObject();
            foreach (var split in ViewCounts.SplitNames)
            {
                counts[split] = Counts.Of(split);
                views[split] = new JArray(Views(split).Select(i => (object)i).ToArray());
            }
            return new JObject
            {
                ["format"] = Format,
                ["version"] = Version,
                ["shardIndex"] = Shard.Index,
                ["shardCount"] = Shard.Count,
                ["assignment"] = Assignment,
                ["viewCounts"] = counts,
                ["views"] = views,
            };
        }

        /// <summary>Writes <c>shard.json</c> into <paramref name="folder"/> (UTF-8, no BOM, indented).</summary>
        public void Write(string folder)
        {
            var path = Path.Combine(folder, FileName);
            File.WriteAllText(path, ToJson().ToString(Formatting.Indented) + "\n", new System.Text.UTF8Encoding(false));
        }

        /// <summary>Reads <c>shard.json</c> from <paramref name="folder"/>; throws <see cref="InvalidParameterException"/> naming each bad field.</summary>
        public static ShardManifest Read(string folder)
        {
            var path = Path.Combine(folder, FileName);
            var text = MetadataText.Read(path, "does not exist, so this folder is not the output of a sharded capture.",
                "Pass the folders that the batch captures with -nerfShard i/N wrote; each holds a shard.json.", "Check the file's permissions, or recapture this shard.");
            return Parse(text, path);
        }

        /// <summary>Parses a manifest; <paramref name="source"/> (a path) prefixes the field names in problems.</summary>
        public static ShardManifest Parse(string json, string source)
        {
            JObject root;
            try
            {
                root = VerbatimJson.Parse(json) as JObject;
                if (root == null) throw new JsonReaderException("The top level is not a JSON object.");
            }
            catch (JsonException e)
            {
                throw new InvalidParameterException(new[] { new ValidationProblem(source, "(unreadable)", "is not valid JSON: " + e.Message, "Recapture this shard or restore its shard.json.") });
            }

            var problems = new List<ValidationProblem>();
            if (!(root["format"] is JValue format && format.Type == JTokenType.String && (string)format == Format))
                problems.Add(new ValidationProblem(source + ": format", root["format"]?.ToString(Formatting.None) ?? "(missing)", "is not \"" + Format + "\".", "Pass the shard folders written by the NeRF Dataset Creator capture."));
            if (!JsonValues.TryLong(root["version"], out var version) || version != Version)
                problems.Add(new ValidationProblem(source + ": version", root["version"]?.ToString() ?? "(missing)", "is not " + Version + ".", "Merge with the version of the tool that captured the shards."));
            var assignment = root["assignment"];
            if (assignment != null && !(assignment.Type == JTokenType.String && (string)assignment == RoundRobin))
                problems.Add(new ValidationProblem(source + ": assignment", assignment.ToString(Formatting.None), "is not \"" + RoundRobin + "\", the only assignment merge knows.",
                    "Recapture the shards with this plugin's -nerfShard i/N."));
            var index = Integer(root, "shardIndex", source, problems);
            var count = Integer(root, "shardCount", source, problems);
            if (index.HasValue && count.HasValue)
                problems.AddRange(ShardSpec.Validate(index.Value, count.Value, source + ": shardIndex/shardCount"));

            var countsJson = root["viewCounts"] as JObject;
            var viewsJson = root["views"] as JObject;
            if (countsJson == null) problems.Add(Missing(source, "viewCounts"));
            if (viewsJson == null) problems.Add(Missing(source, "views"));
            var perSplit = new Dictionary<string, int>();
            var views = new Dictionary<string, IReadOnlyList<int>>();
            foreach (var split in ViewCounts.SplitNames)
            {
                var n = countsJson == null ? null : Integer(countsJson, split, source + ": viewCounts", problems);
                if (n.HasValue && n.Value < 0)
                    problems.Add(new ValidationProblem(source + ": viewCounts." + split, n.Value.ToString(CultureInfo.InvariantCulture), "is negative.", "Recapture this shard."));
                perSplit[split] = n ?? 0;
                if (viewsJson == null) continue;
                if (!(viewsJson[split] is JArray list))
                {
                    problems.Add(Missing(source, "views." + split));
                    continue;
                }
                var indices = new List<int>();
                foreach (var item in list)
                {
                    if (!JsonValues.TryInt(item, out var view) || view < 0 || (n.HasValue && view >= n.Value))
                        problems.Add(new ValidationProblem(source + ": views." + split, item.ToString(Formatting.None),
                            "is not a view index of the split (0 to viewCounts." + split + " − 1).", "Recapture this shard."));
                    else indices.Add(view);
                }
                indices.Sort();
                views[split] = indices;
            }
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            return new ShardManifest(new ShardSpec(index.Value, count.Value),
                new ViewCounts(perSplit["train"], perSplit["val"], perSplit["test"]),
                RoundRobin, views);
        }

        static int? Integer(JObject o, string key, string source, List<ValidationProblem> problems)
        {
            var token = o[key];
            if (JsonValues.TryInt(token, out var value)) return value;
            problems.Add(new ValidationProblem(source + ": " + key, token?.ToString(Formatting.None) ?? "(missing)", "is not a whole number.", "Recapture this shard or restore its shard.json."));
            return null;
        }

        static ValidationProblem Missing(string source, string key) =>
            new ValidationProblem(source + ": " + key, "(missing)", "is required.", "Recapture this shard or restore its shard.json.");
    }
}
