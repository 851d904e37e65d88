using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>Settings read from a config file, and what was odd but harmless about the file (unknown keys, another schema version).</summary>
    public sealed class SettingsReadResult
    {
        public SettingsReadResult(DatasetSettings settings, IReadOnlyList<ValidationProblem> warnings)
        {
            Settings = settings;
            Warnings = warnings;
        }

        public DatasetSettings Settings { get; }
        public IReadOnlyList<ValidationProblem> Warnings { get; }
    }
}
