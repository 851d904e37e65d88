using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Parses <c>nerf-dataset</c>'s arguments. Options take their value as the next argument or after '='
    /// (<c>--out=dir</c>); option names are case-sensitive like most .NET and POSIX tools.
    /// </summary>
    public static class ToolCommandLine
    {
        /// <summary>Options that take no value (<c>--depths</c>).</summary>
        static readonly HashSet<string> Flags = new HashSet<string>(StringComparer.Ordinal) { "depths", "binary" };

        public static ToolInvocation Parse(IReadOnlyList<string> args)
        {
            var result = new ToolInvocation();
            if (args == null || args.Count == 0)
            {
                result.Command = ToolInvocation.HelpCommand;
                result.Errors.Add("no command given.");
                return result;
            }
            var command = args[0];
            if (command == "-h" || command == "--help" || command == "help")
            {
                result.Command = ToolInvocation.HelpCommand;
                return result;
            }
            result.Command = command;
            var positionals = new List<string>();
            var options = new Dictionary<string, string>(StringComparer.Ordinal);
            for (var i = 1; i < args.Count; i++)
            {
                var arg = args[i];
                if (arg == "-h" || arg == "--help")
                {
                    result.Command = ToolInvocation.HelpCommand;
                    return result;
                }
                if (arg == "--" + DryRunFlag)
                {
                    if (options.ContainsKey(DryRunFlag)) result.Errors.Add("--" + DryRunFlag + " is given twice.");
                    options[DryRunFlag] = "";
                    continue;
                }
                if (arg.StartsWith("--", StringComparison.Ordinal))
                {
                    string name, value;
                    var eq = arg.IndexOf('=');
                    if (eq > 0)
                    {
                        name = arg.Substring(2, eq - 2);
                        value = arg.Substring(eq + 1);
                    }
                    else if (Flags.Contains(arg.Substring(2)))
                    {
                        name = arg.Substring(2);
                        value = "true";
                    }
                    else
                    {
                        name = arg.Substring(2);
                        if (i + 1 >= args.Count || args[i + 1].StartsWith("--", StringComparison.Ordinal))
                        {
                            result.Errors.Add("--" + name + " needs a value.");
                            continue;
                        }
                        value = args[++i];
                    }
                    if (options.ContainsKey(name)) result.Errors.Add("--" + name + " is given twice.");
                    options[name] = value;
                }
                else positionals.Add(arg);
            }

            switch (command)
            {
                case ToolInvocation.PlanCommand: Plan(result, options, positionals); break;
                case ToolInvocation.ValidateCommand: Validate(result, options, positionals); break;
                case ToolInvocation.MergeCommand: Merge(result, options, positionals); break;
                case ToolInvocation.ConvertCommand: Convert(result, options, positionals); break;
                case ToolInvocation.CleanCommand: Clean(result, options, positionals); break;
                case ToolInvocation.EvaluateCommand: EvaluateArguments.Parse(result, options, positionals); break;
                case ToolInvocation.CheckCommand: Check(result, options, positionals); break;
                default:
                    result.Errors.Add("unknown command '" + command + "'.");
                    break;
            }
            return result;
        }

        static void Plan(ToolInvocation result, Dictionary<string, string> options, List<string> positionals)
        {
            RefuseUnknownOptions(result, options, "config", "out");
            if (positionals.Count > 0) result.Errors.Add("plan takes no positional argument ('" + positionals[0] + "').");
            options.TryGetValue("config", out var config);
            options.TryGetValue("out", out var output);
            if (string.IsNullOrWhiteSpace(config)) result.Errors.Add("plan needs --config <settings.json>.");
            if (string.IsNullOrWhiteSpace(output)) result.Errors.Add("plan needs --out <dataset-folder>.");
            result.ConfigPath = config;
            result.OutputFolder = output;
        }

        static void Validate(ToolInvocation result, Dictionary<string, string> options, List<string> positionals)
        {
            RefuseUnknownOptions(result, options);
            if (positionals.Count != 1) result.Errors.Add("validate needs exactly one dataset folder.");
            else result.DatasetFolder = positionals[0];
        }

        static void Merge(ToolInvocation result, Dictionary<string, string> options, List<string> positionals)
        {
            RefuseUnknownOptions(result, options, "out", "files");
            options.TryGetValue("out", out var output);
            if (string.IsNullOrWhiteSpace(output)) result.Errors.Add("merge needs --out <dataset-folder>, a folder that does not exist yet.");
            result.OutputFolder = output;
            if (options.TryGetValue("files", out var files))
            {
                if (files == "move") result.MoveFiles = true;
                else if (files != "copy") result.Errors.Add("--files = " + files + ": is not copy or move. Write --files copy (the default, keeps the shards) or --files move (no extra disk space).");
            }
            if (positionals.Count == 0) result.Errors.Add("merge needs the shard folders after the options, e.g. merge --out lego lego-shards/shard-*.");
            result.ShardFolders.AddRange(positionals);
        }

        static void Convert(ToolInvocation result, Dictionary<string, string> options, List<string> positionals)
        {
            RefuseUnknownOptions(result, options, "to", "out", "depths", "binary", "points", "min-track", "object");
            ColmapModelOptions(result, options);
            if (options.TryGetValue("depths", out var depths))
            {
                if (depths != "true") result.Errors.Add("--depths takes no value ('" + depths + "').");
                result.Depths = true;
            }
            if (positionals.Count != 1) result.Errors.Add("convert needs exactly one dataset folder.");
            else result.DatasetFolder = positionals[0];
            if (!options.TryGetValue("to", out var to)) result.Errors.Add("convert needs --to " + string.Join("|", ExportTargets.Names) + ".");
            else
            {
                result.Target = ExportTargets.Parse(to, out var problem);
                if (problem != null) result.Errors.Add(problem.ToString()); // ValidationProblem formats its numbers with the invariant culture
                else if (result.Depths && result.Target != ExportTarget.Colmap)
                    result.Errors.Add("--depths writes 3D Gaussian Splatting's inverse-depth maps, which read a COLMAP source: use it with --to colmap (nerfstudio and ngp exports carry depth on their own).");
            }
            if (options.TryGetValue("object", out var objectName))
            {
                if (string.IsNullOrWhiteSpace(objectName)) result.Errors.Add("--object is empty: give a labelled object's name, hierarchy path or instance id (labels.json).");
                else if (result.Target.HasValue && result.Target != ExportTarget.Nerfstudio)
                    result.Errors.Add("--object writes nerfstudio's per-frame mask_path: use it with --to nerfstudio (--to gaussian-grouping writes masks of every object).");
                else result.ObjectName = objectName;
            }
            if (options.TryGetValue("out", out var output))
            {
                if (string.IsNullOrWhiteSpace(output)) result.Errors.Add("--out is empty; leave it out to write into the dataset folder.");
                else result.OutputFolder = output;
            }
        }

        /// <summary><c>--binary</c>, <c>--points N</c>, <c>--min-track N</c>: the COLMAP model's shape (<see cref="ColmapOptions"/>).</summary>
        static void ColmapModelOptions(ToolInvocation result, Dictionary<string, string> options)
        {
            var given = false;
            if (options.TryGetValue("binary", out var binary))
            {
                if (binary != "true") result.Errors.Add("--binary takes no value ('" + binary + "').");
                result.Binary = true;
                given = true;
            }
            if (options.TryGetValue("points", out var points))
            {
                given = true;
                if (int.TryParse(points, System.Globalization.NumberStyles.None, System.Globalization.CultureInfo.InvariantCulture, out var n) && n >= 1) result.ColmapPoints = n;
                else result.Errors.Add("--points " + points + ": give how many points of points3d.ply the COLMAP model uses, a whole number of at least 1.");
            }
            if (options.TryGetValue("min-track", out var minTrack))
            {
                given = true;
                if (int.TryParse(minTrack, System.Globalization.NumberStyles.None, System.Globalization.CultureInfo.InvariantCulture, out var n)) result.MinTrackLength = n;
                else result.Errors.Add("--min-track " + minTrack + ": give the fewest images a COLMAP point must be seen in, a whole number (0 keeps every point; default " + ColmapOptions.DefaultMinTrackLength + ").");
            }
            if (given && options.TryGetValue("to", out var to) && ExportTargets.Parse(to, out var problem) != ExportTarget.Colmap && problem == null)
                result.Errors.Add("--binary, --points and --min-track shape the COLMAP model: use them with --to colmap.");
        }

        /// <summary>The one option without a value.</summary>
        const string DryRunFlag = "dry-run";

        static void Clean(ToolInvocation result, Dictionary<string, string> options, List<string> positionals)
        {
            RefuseUnknownOptions(result, options, DryRunFlag);
            if (positionals.Count != 1) result.Errors.Add("clean needs exactly one folder: the one holding the datasets (e.g. NeRFDatasets) or a dataset.");
            else result.DatasetFolder = positionals[0];
            result.DryRun = options.ContainsKey(DryRunFlag);
        }

        static void Check(ToolInvocation result, Dictionary<string, string> options, List<string> positionals)
        {
            RefuseUnknownOptions(result, options, "split", "json", "max-views");
            if (positionals.Count != 1) result.Errors.Add("check needs exactly one dataset folder.");
            else result.DatasetFolder = positionals[0];
            if (options.TryGetValue("split", out var split))
            {
                if (!System.Linq.Enumerable.Contains(DatasetSplits.Names, split)) result.Errors.Add("--split " + split + ": is not train, val or test.");
                else result.Split = split;
            }
            if (options.TryGetValue("json", out var json))
            {
                if (string.IsNullOrWhiteSpace(json)) result.Errors.Add("--json is empty; name the report file to write, e.g. --json report.json.");
                else result.JsonReport = json;
            }
            if (options.TryGetValue("max-views", out var max))
            {
                if (!int.TryParse(max, System.Globalization.NumberStyles.None, System.Globalization.CultureInfo.InvariantCulture, out var n) || n < 1)
                    result.Errors.Add("--max-views " + max + ": is not a whole number of at least 1.");
                else result.MaxViews = n;
            }
        }

        internal static void RefuseUnknownOptions(ToolInvocation result, Dictionary<string, string> options, params string[] known)
        {
            foreach (var name in options.Keys)
                if (Array.IndexOf(known, name) < 0)
                    result.Errors.Add(result.Command + " does not know the option --" + name + ".");
        }
    }
}
