using System;
using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset merge --out d [--files copy|move] shard-dir…</c>: joins the folders of a sharded capture with
    /// <see cref="ShardMerger"/> and prints its report. Exit 0 when merged, 1 when refused (nothing changed).
    /// </summary>
    public static class MergeCommand
    {
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
