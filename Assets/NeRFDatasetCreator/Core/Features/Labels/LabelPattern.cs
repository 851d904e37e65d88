namespace NerfDatasetCreator
{
    /// <summary>
    /// The class rules' patterns: <c>*</c> matches any run of characters (also none), <c>?</c> exactly one, everything
    /// else itself, case-sensitively (Unity's tags, layers and names are case-sensitive). The whole text must match:
    /// <c>Car*</c> matches "Car (3)", not "Red Car".
    /// </summary>
    public static class LabelPattern
    {
        public static bool Matches(string pattern, string text)
        {
            pattern = pattern ?? "";
            text = text ?? "";
            // The classic two-pointer wildcard match with one backtrack point: linear in practice, no regex to escape.
            int p = 0, t = 0, star = -1, resume = 0;
            while (t < text.Length)
            {
                if (p < pattern.Length && (pattern[p] == '?' || pattern[p] == text[t]) && pattern[p] != '*')
                {
                    p++;
                    t++;
                }
                else if (p < pattern.Length && pattern[p] == '*')
                {
                    star = p++;
                    resume = t;
                }
                else if (star >= 0)
                {
                    p = star + 1;
                    t = ++resume;
                }
                else return false;
            }
            while (p < pattern.Length && pattern[p] == '*') p++;
            return p == pattern.Length;
        }
    }
}
