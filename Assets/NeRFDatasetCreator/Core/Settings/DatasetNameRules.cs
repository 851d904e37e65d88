using System;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A dataset name becomes a folder name on any OS the dataset may be copied to, so the rules are Windows'
    /// (the strictest), whatever the machine: no path separators, none of &lt; &gt; : " | ? *, no control
    /// characters, no reserved device names, no trailing dot or space.
    /// </summary>
    public static class DatasetNameRules
    {
        static readonly char[] Forbidden = { '/', '\\', '<', '>', ':', '"', '|', '?', '*' };

        static readonly string[] Reserved =
        {
            "CON", "PRN", "AUX", "NUL",
            "COM1", "COM2", "COM3", "COM4", "COM5", "COM6", "COM7", "COM8", "COM9",
            "LPT1", "LPT2", "LPT3", "LPT4", "LPT5", "LPT6", "LPT7", "LPT8", "LPT9",
        };

        public const int MaxLength = 100;

        /// <summary>The problem with <paramref name="name"/> as a dataset folder name, or null when it is fine.</summary>
        public static ValidationProblem Check(string field, string name)
        {
            const string fix = "Use letters, digits, '-', '_' or '.', e.g. \"lego_800\".";
            var shown = "\"" + (name ?? "") + "\"";
            if (string.IsNullOrWhiteSpace(name))
                return new ValidationProblem(field, shown, "is empty.", fix);
            if (name.IndexOfAny(Forbidden) >= 0)
            {
                var bad = name.First(c => Array.IndexOf(Forbidden, c) >= 0);
                return new ValidationProblem(field, shown,
                    bad == '/' || bad == '\\' ? "contains a path separator '" + bad + "'; it names one folder, not a path." : "contains '" + bad + "', which Windows does not allow in folder names.",
                    bad == '/' || bad == '\\' ? "Put the parent folders in outputFolder and only the last folder's name here." : fix);
            }
            if (name.Any(char.IsControl))
                return new ValidationProblem(field, shown, "contains a control character.", fix);
            if (name == "." || name == "..")
                return new ValidationProblem(field, shown, "is a relative folder reference, not a name.", fix);
            if (name.EndsWith(".", StringComparison.Ordinal) || name.EndsWith(" ", StringComparison.Ordinal) || name.StartsWith(" ", StringComparison.Ordinal))
                return new ValidationProblem(field, shown, "starts or ends with a space or ends with a dot, which Windows strips from folder names.", fix);
            var stem = name.Split('.')[0];
            if (Reserved.Any(r => string.Equals(r, stem, StringComparison.OrdinalIgnoreCase)))
                return new ValidationProblem(field, shown, "is a reserved device name on Windows.", fix);
            if (name.Length > MaxLength)
                return new ValidationProblem(field, shown, "is longer than " + MaxLength + " characters.", "Use a shorter name.");
            return null;
        }
    }
}
