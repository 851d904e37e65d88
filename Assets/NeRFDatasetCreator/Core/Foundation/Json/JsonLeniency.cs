using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Finds what Newtonsoft accepts but JSON does not — comments and trailing commas — so that a config that only
    /// this plugin can read (Python's json, jq and most editors refuse it) is reported instead of accepted silently.
    /// A small scanner: strings are skipped, so a "//" or ",]" inside a value is not counted.
    /// </summary>
    public static class JsonLeniency
    {
        /// <summary>One (line, column, what) per comment or trailing comma, in text order; 1-based.</summary>
        public static IReadOnlyList<(int line, int column, string what)> Find(string text)
        {
            var found = new List<(int, int, string)>();
            if (string.IsNullOrEmpty(text)) return found;
            int line = 1, column = 1;
            (int line, int column)? comma = null;
            for (var i = 0; i < text.Length; i++)
            {
                var c = text[i];
                if (c == '"')
                {
                    comma = null;
                    for (i++, column++; i < text.Length && text[i] != '"'; i++, column++)
                    {
                        if (text[i] == '\\') { i++; column++; }
                        else if (text[i] == '\n') { line++; column = 0; }
                    }
                }
                else if (c == '/' && i + 1 < text.Length && (text[i + 1] == '/' || text[i + 1] == '*'))
                {
                    found.Add((line, column, "a comment"));
                    var block = text[i + 1] == '*';
                    for (i += 2, column += 2; i < text.Length; i++, column++)
                    {
                        if (!block && text[i] == '\n') { line++; column = 1; break; }
                        if (text[i] == '\n') { line++; column = 0; }
                        if (block && text[i] == '*' && i + 1 < text.Length && text[i + 1] == '/') { i++; column += 2; break; }
                    }
                    continue;
                }
                else if (c == ',') comma = (line, column);
                else if ((c == '}' || c == ']') && comma.HasValue)
                {
                    found.Add((comma.Value.line, comma.Value.column, "a trailing comma"));
                    comma = null;
                }
                else if (!char.IsWhiteSpace(c)) comma = null;
                if (c == '\n') { line++; column = 1; }
                else column++;
            }
            return found;
        }
    }
}
