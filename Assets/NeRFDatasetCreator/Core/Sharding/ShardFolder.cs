using System;
using System.Collections.Generic;
using System.IO;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>One shard folder as merge reads it: its manifest, its transforms files (<see cref="DatasetFolder"/>) and its config, as JSON.</summary>
    sealed class ShardFolder
    {
        public string Folder;
        public ShardManifest Manifest;
        public readonly Dictionary<string, DatasetSplitFile> Transforms = new Dictionary<string, DatasetSplitFile>();
        /// <summary>The shard's dataset_config.json, or null when it has none or it could not be read (a problem then).</summary>
        public DatasetConfig Config;
        public string Name => "shard " + Manifest.Shard + " (" + Folder + ")";

        /// <summary>Reads every folder, sorted by shard index; each unreadable one adds its problems instead.</summary>
        public static List<ShardFolder> ReadAll(IReadOnlyList<string> folders, List<ValidationProblem> problems)
        {
            var shards = new List<ShardFolder>();
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
                var shard = new ShardFolder { Folder = folder };
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
                    var transforms = ReadTransforms(folder, split, problems);
                    if (transforms == null) continue;
                    if (transforms.IsObject) shard.Transforms[split] = transforms;
                    else problems.Add(new ValidationProblem(Path.Combine(folder, ShardMerger.TransformsFileName(split)), transforms.TypeShown, "is not a JSON object.", "Recapture this shard."));
                }
                shard.Config = ReadConfig(folder, problems);
                shards.Add(shard);
            }
            shards.Sort((a, b) => a.Manifest.Shard.Index.CompareTo(b.Manifest.Shard.Index));
            return shards;
        }

        static DatasetConfig ReadConfig(string folder, List<ValidationProblem> problems)
        {
            var config = DatasetConfig.Read(folder);
            switch (config.State)
            {
                case DatasetConfigState.Unreadable:
                    problems.Add(new ValidationProblem(config.Path, "(unreadable)", "cannot be read: " + config.Error, "Check the file's permissions, or recapture this shard."));
                    break;
                case DatasetConfigState.NotJson:
                    problems.Add(new ValidationProblem(config.Path, "(unreadable)", "is not valid JSON: " + config.Error, "Recapture this shard."));
                    break;
                case DatasetConfigState.NotAnObject:
                    problems.Add(new ValidationProblem(config.Path, "(not an object)", "is not a JSON object.", "Recapture this shard."));
                    break;
            }
            return config.Config;
        }

        /// <summary>A shard's split file as the one dataset reader reads it (lenient: merge checks what it needs), or null with the problem.</summary>
        static DatasetSplitFile ReadTransforms(string folder, string split, List<ValidationProblem> problems)
        {
            var path = Path.Combine(folder, ShardMerger.TransformsFileName(split));
            if (!File.Exists(path)) return null;
            try
            {
                return DatasetFolder.ReadSplit(folder, split, DatasetReadMode.Lenient);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                problems.Add(new ValidationProblem(path, "(unreadable)", "cannot be read: " + e.Message, "Check the file's permissions, or recapture this shard."));
                return null;
            }
            catch (SettingsFormatException e)
            {
                problems.Add(new ValidationProblem(path, "(unreadable)", "is not valid JSON: line " + e.Line + ", column " + e.Column + ": " + e.Detail, "Recapture this shard."));
                return null;
            }
        }
    }
}
