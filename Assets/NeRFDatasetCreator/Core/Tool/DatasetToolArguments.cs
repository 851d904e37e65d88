using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The command lines behind Unity's Dataset Tools buttons, built as a user would type them, so a button and the
    /// terminal run the very same parsing and command (<see cref="ToolTranscript"/>).
    /// </summary>
    public static class DatasetToolArguments
    {
        public static string[] Validate(string datasetFolder) => new[] { ToolInvocation.ValidateCommand, Required(datasetFolder) };

        /// <summary><c>check &lt;dataset&gt;</c>: decodes the images and checks that alpha, masks, depth, normals and poses agree.</summary>
        public static string[] Check(string datasetFolder) => new[] { ToolInvocation.CheckCommand, Required(datasetFolder) };

        /// <summary><c>evaluate &lt;dataset&gt; --renders &lt;folder&gt;</c> with the tool's defaults (test split, layout detected, white background).</summary>
        public static string[] Evaluate(string datasetFolder, string rendersFolder) =>
            new[] { ToolInvocation.EvaluateCommand, Required(datasetFolder), "--renders", Required(rendersFolder) };

        /// <summary><c>convert &lt;dataset&gt; --to &lt;target&gt; [--out &lt;folder&gt;] [--depths]</c>; an empty <paramref name="outputFolder"/> is the format's default place in the dataset.</summary>
        public static string[] Convert(string datasetFolder, ExportTarget target, string outputFolder = null, bool depths = false, string objectName = null)
        {
            var args = new List<string> { ToolInvocation.ConvertCommand, Required(datasetFolder), "--to", ExportTargets.Name(target) };
            if (!string.IsNullOrWhiteSpace(outputFolder)) args.AddRange(new[] { "--out", outputFolder });
            if (depths) args.Add("--depths");
            if (!string.IsNullOrWhiteSpace(objectName)) args.AddRange(new[] { "--object", objectName.Trim() });
            return args.ToArray();
        }

        /// <summary><c>merge --out &lt;folder&gt; [--files move] &lt;shard&gt;…</c>.</summary>
        public static string[] Merge(string outputFolder, IEnumerable<string> shardFolders, bool moveFiles = false)
        {
            var args = new List<string> { ToolInvocation.MergeCommand, "--out", Required(outputFolder) };
            if (moveFiles) args.AddRange(new[] { "--files", "move" });
            args.AddRange(shardFolders ?? Enumerable.Empty<string>());
            return args.ToArray();
        }

        public static string[] Clean(string folder, bool dryRun = false) =>
            dryRun ? new[] { ToolInvocation.CleanCommand, Required(folder), "--dry-run" } : new[] { ToolInvocation.CleanCommand, Required(folder) };

        /// <summary>
        /// The shard folders directly inside <paramref name="parent"/> (those holding a <c>shard.json</c>), in ordinal
        /// order of their names — what <c>merge --out d parent/shard-*</c> passes on a shell; empty when there are none.
        /// </summary>
        public static IReadOnlyList<string> ShardFoldersIn(string parent)
        {
            if (string.IsNullOrWhiteSpace(parent) || !Directory.Exists(parent)) return Array.Empty<string>();
            return Directory.EnumerateDirectories(parent)
                .Where(d => File.Exists(Path.Combine(d, ShardManifest.FileName)))
                .OrderBy(d => Path.GetFileName(d), StringComparer.Ordinal)
                .ToList();
        }

        static string Required(string value) =>
            string.IsNullOrWhiteSpace(value) ? throw new ArgumentException("a folder is needed", nameof(value)) : value;
    }
}
