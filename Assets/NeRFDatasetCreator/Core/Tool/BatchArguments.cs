using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The plugin's own arguments on a Unity batch-mode command line:
    /// <c>-nerfConfig &lt;file&gt; [-nerfScene &lt;scene&gt;] [-nerfOut &lt;dir&gt;] [-nerfShard i/N]</c>.
    /// <c>Environment.GetCommandLineArgs()</c> also holds Unity's own arguments (-batchmode, -projectPath …), so
    /// unknown arguments are ignored; names are case-insensitive. The shard is read by <see cref="ShardSpec.TryParse"/>,
    /// the one parser of "i/N" (0-based, 0 ≤ i &lt; N ≤ 10000, like a Kubernetes Indexed Job's completion index).
    /// </summary>
    public sealed class BatchArguments
    {
        /// <summary>The field a shard problem names: the argument as documented, whatever case it was typed in.</summary>
        public const string ShardField = "-nerfShard";

        public string ConfigPath { get; private set; }
        public string Scene { get; private set; }

        /// <summary>The dataset folder, overriding the config's outputFolder and name.</summary>
        public string OutputFolder { get; private set; }

        /// <summary>Which shard this process renders; null for the whole dataset (no <c>-nerfShard</c>).</summary>
        public ShardSpec? Shard { get; private set; }

        /// <summary>Mistakes in the plugin's arguments; the run must stop when there is any.</summary>
        public List<ValidationProblem> Problems { get; } = new List<ValidationProblem>();

        public bool IsValid => Problems.Count == 0;

        public static BatchArguments Parse(IReadOnlyList<string> argv)
        {
            var result = new BatchArguments();
            if (argv == null) argv = Array.Empty<string>();
            for (var i = 0; i < argv.Count; i++)
            {
                var arg = argv[i];
                if (!IsOption(arg, "-nerfConfig") && !IsOption(arg, "-nerfScene") && !IsOption(arg, "-nerfOut") && !IsOption(arg, "-nerfShard"))
                    continue;
                var name = arg.TrimStart('-');
                if (i + 1 >= argv.Count || argv[i + 1].StartsWith("-", StringComparison.Ordinal) && !LooksLikeNegativeNumber(argv[i + 1]))
                {
                    result.Problems.Add(new ValidationProblem(arg, "", "has no value.", "Write the value after it, e.g. " + Example(name) + "."));
                    continue;
                }
                var value = argv[++i];
                if (IsOption(arg, "-nerfConfig")) result.ConfigPath = value;
                else if (IsOption(arg, "-nerfScene")) result.Scene = value;
                else if (IsOption(arg, "-nerfOut")) result.OutputFolder = value;
                else result.ParseShard(value);
            }
            if (string.IsNullOrWhiteSpace(result.ConfigPath) && result.Problems.TrueForAll(p => !string.Equals(p.Field, "-nerfConfig", StringComparison.OrdinalIgnoreCase)))
                result.Problems.Add(new ValidationProblem("-nerfConfig", "", "is missing.", "Pass the settings file: -nerfConfig path/to/settings.json."));
            return result;
        }

        void ParseShard(string value)
        {
            if (ShardSpec.TryParse(value, out var shard, out var problems, ShardField)) Shard = shard;
            else Problems.AddRange(problems);
        }

        static bool IsOption(string arg, string name) => string.Equals(arg, name, StringComparison.OrdinalIgnoreCase);

        static bool LooksLikeNegativeNumber(string s) => s.Length > 1 && s[0] == '-' && char.IsDigit(s[1]);

        static string Example(string name)
        {
            switch (name.ToLowerInvariant())
            {
                case "nerfconfig": return "-nerfConfig settings.json";
                case "nerfscene": return "-nerfScene Assets/Scenes/Sample.unity";
                case "nerfout": return "-nerfOut ../datasets/lego";
                default: return "-nerfShard 0/4";
            }
        }
    }
}
