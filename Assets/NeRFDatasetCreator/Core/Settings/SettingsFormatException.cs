using System;
using System.Collections.Generic;
using System.Linq;

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

        /// <summary>
        /// Every wrong value of a config at once, as range checks report them: the first is this exception's place and
        /// detail; <see cref="All"/> lists each, and <see cref="Exception.Message"/> holds one line per error.
        /// </summary>
        public SettingsFormatException(IReadOnlyList<SettingsFormatException> errors)
            : base(string.Join("\n", (errors ?? throw new ArgumentNullException(nameof(errors))).Select(e => e.Message)))
        {
            if (errors.Count == 0) throw new ArgumentException("at least one error", nameof(errors));
            var first = errors[0];
            FileName = first.FileName;
            Line = first.Line;
            Column = first.Column;
            Field = first.Field;
            Detail = first.Detail;
            _all = errors.ToList();
        }

        readonly List<SettingsFormatException> _all;

        /// <summary>
        /// For wrong values (not a syntax error): the settings as read, each wrong value left at its default, so that
        /// the range checks can run too and every error of the file is reported at once (issue 33: "config errors come
        /// in two rounds"); null when the text could not be read as a config at all.
        /// </summary>
        public SettingsReadResult Partial { get; internal set; }

        /// <summary>Every error, in the order of the file (just this one for a syntax error).</summary>
        public IReadOnlyList<SettingsFormatException> All => _all ?? new List<SettingsFormatException> { this };

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
