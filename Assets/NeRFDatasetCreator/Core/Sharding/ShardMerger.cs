using System.Collections.Generic;
using System.IO;
using System.Linq;

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
        public const string ConfigFileName = DatasetLayout.ConfigFileName;

        /// <summary>
        /// Top-level keys of <c>dataset_config.json</c> that describe one run rather than the dataset (when and
        /// where it ran, what it rendered): they may differ between shards, which merge reports as a warning. Every
        /// other key (settings, seed, distance, target, plugin version) must be identical.
        /// </summary>
        public static readonly IReadOnlyList<string> PerRunConfigKeys = new[] { "createdUtc", GeometryPackRecord.Key, "imagesRendered", "pointCloud", "statistics", "tool", "unityVersion" };

        public static string TransformsFileName(string split) => DatasetLayout.TransformsFileName(split);

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
            var output = Path.GetFullPath(outputFolder).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            var length = PathLimits.Check(output, "output", MergingSuffix);
            if (length != null) return Fail(length, warnings);
            // An earlier merge into this output that was killed is finished or rolled back first (its moved files go back).
            var recovered = Recovery.Run(output);
            var notes = recovered.Select(n => n.Text).ToList();
            if (recovered.Any(n => n.Operation == "merge" && n.Finished) && Directory.Exists(output))
                return MergeResult.FinishedEarlier(output, warnings, notes);
            if (Directory.Exists(output) || File.Exists(output))
                return Fail(new ValidationProblem("output", output, "already exists; merge never writes into or over an existing folder.",
                    "Choose a new folder name, or move the existing one away first."), warnings, notes);
            notes.AddRange(Leftover.Of(output).Select(l => "left over: " + l + (l.Removable ? " `nerf-dataset clean " + Path.GetDirectoryName(output) + "` removes it." : "")));

            var shards = ShardFolder.ReadAll(shardFolders, problems);
            if (problems.Count > 0) return new MergeResult(output, problems, warnings, empty, 0, notes);
            // The real path, every link followed (SafeOutput's one rule): a link into a shard is inside it.
            foreach (var shard in shards.Where(s => SafeOutput.WhyInsideDataset(output, s.Folder) != null))
                warnings.Add("--out " + output + " is inside " + shard.Name + "; the merged dataset will sit in a shard folder (choose a folder beside the shards).");
            MergeChecks.CheckShardSet(shards, problems);
            if (problems.Count > 0) return new MergeResult(output, problems, warnings, empty, 0, notes);

            var counts = shards[0].Manifest.Counts;
            var frames = MergeChecks.CollectFrames(shards, counts, problems, warnings);
            MergeChecks.CheckConsistency(shards, problems, warnings);
            var labels = MergeLabels.Check(shards, problems);
            var protocol = MergeProtocol.Check(shards, problems);
            var transfers = MergeTransfer.Plan(shards, frames, problems, warnings);
            if (problems.Count > 0) return new MergeResult(output, problems, warnings, empty, 0, notes);

            var perSplit = ViewCounts.SplitNames.ToDictionary(s => s, s => frames.Count(f => f.Split == s));
            var failure = MergeStaging.Write(shards, frames, transfers, output, moveFiles, labels, protocol);
            if (failure != null) return Fail(failure, warnings, notes);
            return new MergeResult(output, problems, warnings, perSplit, transfers.Count, notes);
        }

        /// <summary>What the merge's working folder adds to the output's name: "." before it, ".merging-" and 8 hex digits after.</summary>
        const int MergingSuffix = 18;

        static MergeResult Fail(ValidationProblem problem, List<string> warnings, IReadOnlyList<string> notes = null) =>
            new MergeResult(null, new[] { problem }, warnings, new Dictionary<string, int>(), 0, notes);
    }
}
