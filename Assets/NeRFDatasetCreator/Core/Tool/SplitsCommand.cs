using System;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset splits &lt;dir&gt; [--views 8[,3,…]]</c>: writes the dataset's sparse-view split files
    /// (<see cref="SparseSplitFiles"/>), for any Blender-format dataset — nerf_synthetic itself included. On demand
    /// (and at capture for the config's <c>sparseViews</c>), because a dataset made without them, or downloaded, needs
    /// them too, and because files nobody asked for would be one more thing for merge, shards and clean to carry.
    /// </summary>
    public static class SplitsCommand
    {
        public static readonly ToolCommand Command = ToolCommand.Of("splits", "splits <dir> [--views 8[,3,...]]",
            "write sparse-view split files (splits/sparse_<n>.json: nerf_synthetic's paper lists, else farthest-point views) for evaluate --split",
            Parse, Run).WithOptions(
            "--views N[,N…]   how many train views each split keeps (default 8); nerf_synthetic's rig with 8 gets DietNeRF / FreeNeRF's list");

        public sealed class Options
        {
            public string DatasetFolder { get; set; }
            public int[] Views { get; set; } = { SparseSplitFiles.DefaultViews };
        }

        static Options Parse(ToolArguments arguments)
        {
            arguments.RefuseUnknownOptions("views");
            var options = new Options { DatasetFolder = arguments.OnePositional("splits needs exactly one dataset folder.") };
            if (arguments.TryGet("views", out var views))
            {
                var counts = SparseSplitFiles.ParseCounts(views, out var problem);
                if (problem != null) arguments.Error(problem);
                else options.Views = counts;
            }
            return options;
        }

        public static int Run(Options options, TextWriter stdout, TextWriter stderr)
        {
            try
            {
                foreach (var o in SparseSplitFiles.Write(options.DatasetFolder, options.Views))
                {
                    stdout.WriteLine((o.Unchanged ? "unchanged " : "wrote ") + o.Path + ": train " + string.Join(", ", o.Split.Train) + "; " + o.Split.Test.Count + " test views");
                    stdout.WriteLine("  rule: " + o.Split.Rule + (o.Split.Source != null ? " (" + o.Split.Source + ")" : ""));
                }
                stdout.WriteLine("score renders of the listed test views with: nerf-dataset evaluate " + options.DatasetFolder + " --renders <folder> --split " + SparseSplit.NameOf(options.Views[0]));
                return ToolExitCodes.Success;
            }
            catch (InvalidParameterException e)
            {
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                stderr.WriteLine("splits refused: nothing was written.");
                return ToolExitCodes.Failure;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                stderr.WriteLine("error: " + e.Message);
                return ToolExitCodes.Failure;
            }
        }
    }
}
