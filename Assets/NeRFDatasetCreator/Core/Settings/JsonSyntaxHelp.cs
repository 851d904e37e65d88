using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Turns Newtonsoft.Json's syntax errors into one sentence a user can act on, at the place to edit: a missing
    /// comma is reported at the end of the value it should follow (Newtonsoft reports the start of the next one),
    /// an empty file as empty. Unknown messages keep Newtonsoft's first sentence.
    /// </summary>
    public static class JsonSyntaxHelp
    {
        /// <summary>Newtonsoft's message cut before its " Path '…', line L, position P." tail (the caller reports the place).</summary>
        public static string FirstSentence(string message)
        {
            message = message ?? "";
            var cut = message.IndexOf(" Path '", StringComparison.Ordinal);
            if (cut < 0) cut = message.IndexOf(", line ", StringComparison.Ordinal);
            return cut > 0 ? message.Substring(0, cut) : message;
        }

        /// <summary>
        /// What is wrong and how to fix it, and where (1-based line and column; Newtonsoft's <paramref name="line"/> and
        /// <paramref name="column"/> on entry, the place to edit on return).
        /// </summary>
        /// <param name="emptyAdvice">What an empty file should hold; null for a settings config's advice.</param>
        public static string Explain(string message, string text, ref int line, ref int column, string emptyAdvice = null)
        {
            var first = FirstSentence(message);
            if (string.IsNullOrWhiteSpace(text))
            {
                line = 0;
                column = 0;
                return "the file is empty. " + (emptyAdvice ?? "A config is a JSON object: write {} for the defaults (every key is optional), or save one from the window (Save config for batch…).");
            }
            if (first.StartsWith("After parsing a value an unexpected character was encountered", StringComparison.Ordinal))
            {
                // Newtonsoft stops at the next value's first character; the comma belongs after the previous value.
                var offset = Offset(text, line, column);
                var before = offset - 1;
                while (before >= 0 && char.IsWhiteSpace(text[before])) before--;
                if (before >= 0)
                {
                    Place(text, before, out line, out column);
                    return "a comma is missing after this value (entries of an object or a list are separated by commas). Add a comma at the end of line " + line + ".";
                }
            }
            if (first.StartsWith("Unexpected end", StringComparison.Ordinal))
                return "the file ends before every { and [ is closed. Add the missing } or ] (or the rest of the file, if it was cut off).";
            if (first.StartsWith("Invalid character after parsing property name", StringComparison.Ordinal))
                return "a colon is missing after the key. Write \"key\": value.";
            if (first.StartsWith("Invalid property identifier character", StringComparison.Ordinal))
                return first + ": keys must be in double quotes, as in \"width\": 800 (a comma before a closing } is not JSON either).";
            if (first.StartsWith("Unexpected character encountered while parsing value", StringComparison.Ordinal))
                return first + ": this does not start a JSON value. Put text in double quotes (\"recentre\"), write numbers with a dot (0.5) and true, false, null in lower case.";
            if (first.StartsWith("Additional text encountered after finished reading JSON content", StringComparison.Ordinal) ||
                first.StartsWith("Additional text after the JSON object", StringComparison.Ordinal))
                return "there is more text after the closing } of the config. Remove it, or move it inside the { … }.";
            return "not valid JSON: " + first;
        }

        /// <summary>The offset of Newtonsoft's (line, position): position counts the characters of the line before the offending one.</summary>
        static int Offset(string text, int line, int column)
        {
            var offset = 0;
            for (var l = 1; l < line && offset < text.Length; l++)
            {
                var next = text.IndexOf('\n', offset);
                if (next < 0) return text.Length;
                offset = next + 1;
            }
            return Math.Min(text.Length, offset + Math.Max(0, column));
        }

        static void Place(string text, int offset, out int line, out int column)
        {
            line = 1;
            var lineStart = 0;
            for (var i = 0; i < offset; i++)
                if (text[i] == '\n')
                {
                    line++;
                    lineStart = i + 1;
                }
            column = offset - lineStart + 1;
        }
    }
}
