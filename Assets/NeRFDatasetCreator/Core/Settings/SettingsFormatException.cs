using System;

namespace NerfDatasetCreator
{
    /// <summary>A config file that is not valid JSON or has a value of the wrong type, with the place to look.</summary>
    public sealed class SettingsFormatException : Exception
    {
        public SettingsFormatException(string source, int line, int column, string field, string detail)
            : base(Describe(source, line, column, field, detail))
        {
            FileName = source ?? "";
            Line = line;
            Column = column;
            Field = field ?? "";
            Detail = detail ?? "";
        }

        /// <summary>The file (or "config") the text came from.</summary>
        public string FileName { get; }

        /// <summary>1-based line of the problem, 0 when unknown.</summary>
        public int Line { get; }

        /// <summary>1-based column of the problem, 0 when unknown.</summary>
        public int Column { get; }

        /// <summary>The setting's path (e.g. <c>splits.train.count</c>), empty for a syntax error.</summary>
        public string Field { get; }

        public string Detail { get; }

        static string Describe(string source, int line, int column, string field, string detail)
        {
            var where = (string.IsNullOrEmpty(source) ? "config" : source) + (line > 0 ? "(" + line + "," + column + ")" : "");
            return where + ": " + (string.IsNullOrEmpty(field) ? "" : field + ": ") + detail;
        }
    }
}
