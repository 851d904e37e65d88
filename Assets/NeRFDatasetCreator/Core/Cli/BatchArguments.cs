using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The plugin's own arguments on a Unity batch-mode command line:
    /// <c>-nerfConfig &lt;file&gt; [-nerfScene &lt;scene&gt;] [-nerfOut &lt;dir&gt;] [-nerfShard i/N]</c>.
    /// <c>Environment.GetCommandLineArgs()</c> also holds Unity's own arguments (-batchmode, -projectPath …), so
    /// unknown arguments are ignored; names are case-insensitive. The shard index is 0-based (0 ≤ i &lt; N), like
    /// a Kubernetes Indexed Job's completion index.
    /// </summary>
    public sealed class BatchArguments
    {
        public string ConfigPath { get; private set; }
        public string Scene { get; private set; }

        /// <summary>The dataset folder, overriding the config's outputFolder and name.</summary>
        public string OutputFolder { get; private set; }

        /// <summary>Which shard this process renders; null for the whole dataset.</summary>
        public int? ShardIndex { get; private set; }
        public int? ShardCount { get; private set; }

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
                else result.ParseShard(arg, value);
            }
            if (string.IsNullOrWhiteSpace(result.ConfigPath) && result.Problems.TrueForAll(p => !string.Equals(p.Field, "-nerfConfig", StringComparison.OrdinalIgnoreCase)))
                result.Problems.Add(new ValidationProblem("-nerfConfig", "", "is missing.", "Pass the settings file: -nerfConfig path/to/settings.json."));
            return result;
        }

        void ParseShard(string arg, string value)
        {
            var parts = value.Split('/');
            if (parts.Length == 2 &&
                int.TryParse(parts[0], NumberStyles.None, CultureInfo.InvariantCulture, out var index) &&
                int.TryParse(parts[1], NumberStyles.None, CultureInfo.InvariantCulture, out var count) &&
                count >= 1 && index < count)
            {
                ShardIndex = index;
                ShardCount = count;
                return;
            }
            Problems.Add(new ValidationProblem(arg, value, "is not a shard i/N with 0 ≤ i < N.", "Write e.g. -nerfShard 0/4 for the first of four shards."));
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
