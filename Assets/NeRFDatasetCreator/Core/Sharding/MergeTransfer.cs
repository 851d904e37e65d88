using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace NerfDatasetCreator
{
    /// <summary>One file merge copies or moves: from a shard folder to a path relative to the merged dataset.</summary>
    sealed class MergeTransfer
    {
        public string Source;
        public string Relative;

        static readonly Regex ViewFilePattern = new Regex(@"^r_(\d+)(?:[^0-9].*)?$", RegexOptions.CultureInvariant);

        /// <summary>
        /// Every file the kept frames need: those their <c>file_path</c> and <c>*_path</c> keys name, and every file of
        /// their split folder named after the view (r_12.png, r_12_depth.exr, r_12_normal_0000.png …). Missing files,
        /// paths leaving the shard and collisions are problems; files of no frame are left behind with a warning.
        /// </summary>
        public static List<MergeTransfer> Plan(List<ShardFolder> shards, List<MergeFrame> frames, List<ValidationProblem> problems, List<string> warnings)
        {
            var transfers = new List<MergeTransfer>();
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
                transfers.Add(new MergeTransfer { Source = source, Relative = relative });
            }

            // Every file in a split folder that belongs to a kept frame (r_12.png, r_12_depth.exr, r_12_normal_0000.png …).
            var byView = new Dictionary<string, List<string>>(StringComparer.Ordinal);
            foreach (var shard in shards)
                foreach (var split in ViewCounts.SplitNames)
                {
                    var dir = Path.Combine(shard.Folder, split);
                    if (!Directory.Exists(dir)) continue;
                    if (PathSafety.IsLink(dir))
                    {
                        problems.Add(new ValidationProblem(dir, "(symbolic link)", "is a link, which may lead outside " + shard.Name + "; merge never follows links.",
                            "Replace the link by the folder it points to (e.g. cp -rL), then merge again."));
                        continue;
                    }
                    foreach (var path in Directory.GetFiles(dir).OrderBy(p => p, StringComparer.Ordinal))
                    {
                        if (PathSafety.IsLink(path))
                        {
                            problems.Add(new ValidationProblem(path, "(symbolic link)", "is a link, which may lead outside " + shard.Name + "; merge never follows links.",
                                "Replace the link by the file it points to, then merge again."));
                            continue;
                        }
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
                // Files the frame names, resolved by the dataset's one path rule (DatasetFile): file_path (".png" appended
                // when extensionless, as the loaders do) and every *_path key.
                var named = new List<DatasetFile>();
                if (frame.Frame.Image != null) named.Add(frame.Frame.Image);
                foreach (var pair in frame.Frame.FileKeys) named.Add(frame.Frame.Named(pair.Key));
                foreach (var file in named)
                {
                    var relative = file.Relative;
                    var where = Path.Combine(frame.Shard.Folder, ShardMerger.TransformsFileName(frame.Split)) + ": " + frame.Split + " r_" + Str(frame.Index) + "." + file.Key;
                    if (relative.Length == 0 || Path.IsPathRooted(relative) || relative.Split('/').Contains(".."))
                    {
                        problems.Add(new ValidationProblem(where, file.Written, "points outside the shard folder.", "Paths in a dataset must be relative and stay inside it."));
                        continue;
                    }
                    if (IsMetadata(relative))
                    {
                        problems.Add(new ValidationProblem(where, file.Written, "names the shard's own metadata file; merge never copies or moves a shard's metadata.",
                            "Correct the key: *_path keys name a view's image files."));
                        continue;
                    }
                    if (!file.IsInside)
                    {
                        problems.Add(new ValidationProblem(where, file.Written, file.Outside + ".", "Paths in a dataset must stay inside it."));
                        continue;
                    }
                    if (!file.Exists)
                    {
                        problems.Add(new ValidationProblem(where, file.Written, "names " + file.FullPath + ", which does not exist.", "Rerun " + owner + "; its capture did not finish."));
                        continue;
                    }
                    Add(file.FullPath, relative, owner);
                }
                if (byView.TryGetValue(key, out var files))
                {
                    foreach (var path in files) Add(path, frame.Split + "/" + Path.GetFileName(path), owner);
                    byView.Remove(key);
                }
            }
            // One point cloud per dataset, written by shard 0: carried over; a second one is a collision, never a silent pick.
            foreach (var shard in shards)
            {
                var cloud = Path.Combine(shard.Folder, TargetPointCloud.FileName);
                if (!File.Exists(cloud)) continue;
                if (PathSafety.IsLink(cloud))
                    problems.Add(new ValidationProblem(cloud, "(symbolic link)", "is a link, which may lead outside " + shard.Name + "; merge never follows links.",
                        "Replace the link by the file it points to, then merge again."));
                else Add(cloud, TargetPointCloud.FileName, shard.Name);
            }
            // The geometry pack, written by shard 0 and recorded in its dataset_config.json (MergeGeometry).
            MergeGeometry.Plan(shards, Add, folder => claimed.Add(folder), problems, warnings);
            foreach (var leftover in byView.Values.SelectMany(v => v))
                warnings.Add(leftover + " belongs to no frame of its shard's transforms and was left in place.");

            var known = new HashSet<string>(ViewCounts.SplitNames.Concat(ViewCounts.SplitNames.Select(ShardMerger.TransformsFileName)).Concat(new[] { ShardManifest.FileName, ShardMerger.ConfigFileName, DatasetLayout.LabelsFileName, EvalProtocolFile.FileName })
                .Concat(ViewCounts.SplitNames.Select(DatasetLayout.LabelsPreviewFileName)), StringComparer.Ordinal);
            foreach (var shard in shards)
                foreach (var entry in Directory.EnumerateFileSystemEntries(shard.Folder).OrderBy(p => p, StringComparer.Ordinal))
                    if (!known.Contains(Path.GetFileName(entry)) && !claimed.Contains(entry))
                        warnings.Add(entry + " is not part of the Blender-format splits and was not merged (per-shard extras such as a nerfstudio transforms.json must be made again from the merged dataset).");
            return transfers;
        }

        /// <summary>The files that describe a shard or a dataset rather than a view: never transferred, whatever a frame's key says.</summary>
        static bool IsMetadata(string relative)
        {
            var name = Path.GetFileName(relative);
            return DatasetSplits.Names.Any(s => string.Equals(name, DatasetLayout.TransformsFileName(s), StringComparison.OrdinalIgnoreCase))
                   || new[] { ShardManifest.FileName, DatasetLayout.ConfigFileName, OperationJournal.FileName, NerfstudioWriter.FileName, EvalProtocolFile.FileName }
                       .Any(m => string.Equals(name, m, StringComparison.OrdinalIgnoreCase));
        }

        static string Str(int value) => value.ToString(CultureInfo.InvariantCulture);
    }
}
