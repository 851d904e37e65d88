using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset merge --out d [--files copy|move] shard-dir…</c>: joins the folders of a sharded capture with
    /// <see cref="ShardMerger"/> and prints its report. Exit 0 when merged, 1 when refused (nothing changed).
    /// </summary>
    public static class MergeCommand
    {
        public static readonly ToolCommand Command = ToolCommand.Of("merge", "merge --out <dir> [--files copy|move] <shard-dir>...",
            "join the folders of a sharded capture", Parse, Run).WithOptions(
            "--out <dir>          the merged dataset folder, which must not exist yet",
            "--files copy|move    copy the shards' images (default; the shards stay) or move them (no extra disk space)",
            "<shard-dir>...       the shard folders of one capture, in any order");

        public sealed class Options
        {
            /// <summary><c>--out &lt;dir&gt;</c>: the dataset folder to create.</summary>
            public string OutputFolder { get; set; }

            /// <summary><c>--files move</c>: move the images out of the shard folders instead of copying them.</summary>
            public bool MoveFiles { get; set; }

            /// <summary>The shard folders, in the order given.</summary>
            public List<string> ShardFolders { get; } = new List<string>();
        }

        static Options Parse(ToolArguments arguments)
        {
            arguments.RefuseUnknownOptions("out", "files");
            var options = new Options { OutputFolder = arguments.RequiredPath("out", "merge needs --out <dataset-folder>, a folder that does not exist yet.") };
            if (arguments.TryGet("files", out var files))
            {
                if (files == "move") options.MoveFiles = true;
                else if (files != "copy") arguments.Error("--files = " + files + ": is not copy or move. Write --files copy (the default, keeps the shards) or --files move (no extra disk space).");
            }
            if (arguments.Positionals.Count == 0) arguments.Error("merge needs the shard folders after the options, e.g. merge --out lego lego-shards/shard-*.");
            options.ShardFolders.AddRange(arguments.Positionals);
            return options;
        }

        /// <summary>The command line of the Dataset Tools' Merge button: <c>merge --out &lt;folder&gt; [--files move] &lt;shard&gt;…</c>.</summary>
        public static string[] Arguments(string outputFolder, IEnumerable<string> shardFolders, bool moveFiles = false)
        {
            var args = new List<string> { Command.Name, "--out", ToolArguments.Required(outputFolder) };
            if (moveFiles) args.AddRange(new[] { "--files", "move" });
            args.AddRange(shardFolders ?? Enumerable.Empty<string>());
            return args.ToArray();
        }

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

        public static int Run(Options options, TextWriter stdout, TextWriter stderr) => Run(options.ShardFolders, options.OutputFolder, options.MoveFiles, stdout, stderr);

        public static int Run(IReadOnlyList<string> shardFolders, string outputFolder, bool moveFiles, TextWriter stdout, TextWriter stderr)
        {
            MergeResult result;
            try
            {
                result = ShardMerger.Merge(shardFolders, outputFolder, moveFiles);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                // Reading a shard's files failed before merge wrote anything (its writing step undoes itself).
                stderr.WriteLine("error: " + e.Message);
                stderr.WriteLine("merge refused: a shard folder could not be read; no file was changed.");
                return ToolExitCodes.Failure;
            }
            // A script capturing stdout gets the summary on success; every reason for a refusal goes to stderr.
            var output = result.Succeeded ? stdout : stderr;
            foreach (var line in result.Lines()) output.WriteLine(line);
            return result.Succeeded ? ToolExitCodes.Success : ToolExitCodes.Failure;
        }
    }
}
