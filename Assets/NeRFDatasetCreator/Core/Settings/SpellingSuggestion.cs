using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// "did you mean …": the known name closest to a misspelled one by edit distance (insertions, deletions,
    /// substitutions and swaps of neighbours, case ignored), when it is close enough to be the likely intent.
    /// </summary>
    public static class SpellingSuggestion
    {
        /// <summary>The closest of <paramref name="known"/>, or null when none is within about a third of its length.</summary>
        public static string Closest(string written, IEnumerable<string> known)
        {
            if (string.IsNullOrEmpty(written) || known == null) return null;
            string best = null;
            var bestDistance = int.MaxValue;
            foreach (var name in known)
            {
                if (string.IsNullOrEmpty(name)) continue;
                var d = Distance(written.ToLowerInvariant(), name.ToLowerInvariant());
                if (d < bestDistance)
                {
                    best = name;
                    bestDistance = d;
                }
            }
            // One edit for short names ("tran" → "train"), two from five letters ("widht" → "width"); never the whole word.
            var allowed = Math.Min(2, Math.Max(1, written.Length / 3));
            // Keys are case-sensitive: "nearclip" for "nearClip" is worth a suggestion too (distance 0 once lowered).
            return best != null && bestDistance <= allowed && !string.Equals(best, written, StringComparison.Ordinal) ? best : null;
        }

        /// <summary>" Did you mean "train"?" — or "" without a close name; for the end of a message.</summary>
        public static string Sentence(string written, IEnumerable<string> known)
        {
            var closest = Closest(written, known);
            return closest == null ? "" : " Did you mean \"" + closest + "\"?";
        }

        /// <summary>Optimal string alignment distance: Levenshtein plus the swap of two neighbours as one edit.</summary>
        public static int Distance(string a, string b)
        {
            var d = new int[a.Length + 1, b.Length + 1];
            for (var i = 0; i <= a.Length; i++) d[i, 0] = i;
            for (var j = 0; j <= b.Length; j++) d[0, j] = j;
            for (var i = 1; i <= a.Length; i++)
            for (var j = 1; j <= b.Length; j++)
            {
                var cost = a[i - 1] == b[j - 1] ? 0 : 1;
                var best = Math.Min(Math.Min(d[i - 1, j] + 1, d[i, j - 1] + 1), d[i - 1, j - 1] + cost);
                if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) best = Math.Min(best, d[i - 2, j - 2] + 1);
                d[i, j] = best;
            }
            return d[a.Length, b.Length];
        }
    }
}
