using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>Settings read from a config file, and what was odd but harmless about the file (unknown keys, another schema version).</summary>
    public sealed class SettingsReadResult
    {
        public SettingsReadResult(DatasetSettings settings, IReadOnlyList<ValidationProblem> warnings)
            : this(settings, warnings, null, null)
        {
        }

        public SettingsReadResult(DatasetSettings settings, IReadOnlyList<ValidationProblem> warnings, Newtonsoft.Json.Linq.JObject json, string source)
        {
            Settings = settings;
            Warnings = warnings;
            Json = json;
            Source = source;
        }

        public DatasetSettings Settings { get; }
        public IReadOnlyList<ValidationProblem> Warnings { get; }

        /// <summary>The file as read, with line info (null when the settings did not come from a text).</summary>
        public Newtonsoft.Json.Linq.JObject Json { get; }

        /// <summary>The file's name as the messages give it.</summary>
        public string Source { get; }

        /// <summary>
        /// <paramref name="problem"/> as one line, placed in the file where its setting is ("lego.json(14,18): splits.train.count = 0: …"),
        /// as format errors are; unplaced when the file does not hold it (<see cref="SettingsLines"/>).
        /// </summary>
        public string Placed(ValidationProblem problem)
        {
            var where = SettingsLines.Where(Json, Source, problem.Field);
            return where == null ? problem.ToString() : where + ": " + problem;
        }
    }
}
