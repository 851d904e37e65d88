using System;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset flow &lt;dataset&gt;</c>: adds <c>flow/</c> (Documentation~/flow.md) to a dynamic dataset captured
    /// with <c>"geometryPack": "everyStep"</c> — one captured without the <c>flow</c> section, or a merged one (shards get no
    /// flow). Writes only the new folder <c>flow/</c> (refused when it exists); dataset_config.json is left as it is, since
    /// <c>flow/flow.json</c> is the record every reader opens (<see cref="FlowRecord.Read"/>).
    /// </summary>
    public static class FlowCommand
    {
        public static readonly ToolCommand Command = ToolCommand.Of("flow", "flow <dir> [--spans 1[,2,...]] [--no-backward] [--no-scene-flow] [--tracks Q[,Q,...]] [--stride N] [--threads N]",
            "add exact optical flow, scene flow, occlusion and tracks (flow/) to a dynamic dataset with \"geometryPack\": \"everyStep\"",
            Parse, Run, "no-backward", "no-scene-flow").WithOptions(
            "--spans N[,N…]    step spans of the frame pairs (default 1: each step and the next)",
            "--no-backward     no backward pairs (a, a − span)",
            "--no-scene-flow   no scene_flow_<a>_<b>.exr files",
            "--tracks Q[,Q…]   long tracks from these query frames (default none)",
            "--stride N        every Nth pixel of a query frame is a query point (default 8)",
            "--threads N       threads to cast on (default: every core); the files are the same for any count");

        public sealed class Options
        {
            public string DatasetFolder { get; set; }
            public FlowSettings Settings { get; set; } = new FlowSettings { On = true };
            public int Threads { get; set; } = Math.Max(1, Environment.ProcessorCount);
        }

        static Options Parse(ToolArguments arguments)
        {
            arguments.RefuseUnknownOptions("spans", "no-backward", "no-scene-flow", "tracks", "stride", "threads");
            var options = new Options { DatasetFolder = arguments.OnePositional("flow needs exactly one dataset folder.") };
            var s = options.Settings;
            if (arguments.TryGet("spans", out var spans))
                s.Spans = List(arguments, "spans", spans, 1, "a list of step spans of 1 or more, such as 1,2") ?? s.Spans;
            if (arguments.TryGet("tracks", out var tracks))
                s.TrackQueryFrames = List(arguments, "tracks", tracks, 0, "a list of query frames (0 = the first), such as 0,10") ?? s.TrackQueryFrames;
            s.Backward = !arguments.Flag("no-backward");
            s.SceneFlow = !arguments.Flag("no-scene-flow");
            s.TrackStride = arguments.WholeNumber("stride", 1, v => "--stride = " + v + ": is not a whole number of 1 or more (every Nth pixel).") ?? s.TrackStride;
            options.Threads = arguments.WholeNumber("threads", 1, v => "--threads = " + v + ": is not a whole number of 1 or more.") ?? options.Threads;
            return options;
        }

        static int[] List(ToolArguments arguments, string name, string text, int minimum, string what)
        {
            var parts = text.Split(',');
            var values = new int[parts.Length];
            for (var i = 0; i < parts.Length; i++)
                if (!int.TryParse(parts[i], NumberStyles.None, CultureInfo.InvariantCulture, out values[i]) || values[i] < minimum)
                {
                    arguments.Error("--" + name + " = " + text + ": is not " + what + ".");
                    return null;
                }
            if (values.Distinct().Count() != values.Length)
            {
                arguments.Error("--" + name + " = " + text + ": names a value twice; list each once.");
                return null;
            }
            return values;
        }

        public static int Run(Options options, TextWriter stdout, TextWriter stderr)
        {
            var folder = options.DatasetFolder;
            var existed = Directory.Exists(Path.Combine(folder, FlowLayout.Folder));
            try
            {
                if (!Directory.Exists(folder))
                    throw new InvalidParameterException(new[] { new ValidationProblem("dataset", folder, "is not a folder.", "Give the folder of a dataset captured with time and \"geometryPack\": \"everyStep\".") });
                var started = DateTime.UtcNow;
                var record = FlowWriter.Write(folder, options.Settings, null, options.Threads);
                stdout.WriteLine("wrote " + FlowConfigRecord.Summary(record));
                stdout.WriteLine(string.Format(CultureInfo.InvariantCulture, "  in {0:0.0} s on {1} thread{2}; conventions in {3}, Documentation~/flow.md",
                    (DateTime.UtcNow - started).TotalSeconds, options.Threads, options.Threads == 1 ? "" : "s", FlowLayout.RecordFile));
                return ToolExitCodes.Success;
            }
            catch (InvalidParameterException e)
            {
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                stderr.WriteLine("flow refused: nothing was written.");
                return ToolExitCodes.Failure;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is InvalidDataException)
            {
                stderr.WriteLine("error: " + e.Message);
                if (!existed && Directory.Exists(Path.Combine(folder, FlowLayout.Folder)))
                    stderr.WriteLine("flow/ may be incomplete: it was written by this run only; delete it before running flow again.");
                return ToolExitCodes.Failure;
            }
        }
    }
}
