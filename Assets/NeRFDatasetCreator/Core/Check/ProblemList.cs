using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The problem lines of <c>check</c> and <c>validate</c>, capped: the first <see cref="ShownPerCheck"/> of each
    /// check (structural problems count as one check), in the order found, then one line per capped check saying how
    /// many more there are. A plan checked as if rendered printed 400 lines of one cause (issue 33); twenty show
    /// the pattern, and the count says how far it goes.
    /// </summary>
    public static class ProblemList
    {
        public const int ShownPerCheck = 20;

        /// <param name="prefix">The start of every line ("problem: ", "warning: ").</param>
        /// <param name="whereAll">Where every one is listed, for the "more" line, e.g. "--json FILE lists every one"; null for nowhere.</param>
        public static IEnumerable<string> Lines(IEnumerable<DatasetProblem> problems, string prefix, string whereAll)
        {
            var shown = new Dictionary<string, int>(System.StringComparer.Ordinal);
            var order = new List<string>();
            foreach (var problem in problems)
            {
                var key = problem.Check ?? "";
                if (!shown.TryGetValue(key, out var n)) order.Add(key);
                shown[key] = n + 1;
                if (n < ShownPerCheck) yield return prefix + problem;
            }
            foreach (var key in order.Where(k => shown[k] > ShownPerCheck))
            {
                var more = shown[key] - ShownPerCheck;
                yield return prefix + "… and " + more + " more" + (key.Length > 0 ? " [" + key + "]" : "") + (more == 1 ? " like it" : " like these") +
                             " (" + shown[key] + " in all" + (whereAll != null ? "; " + whereAll : "") + ").";
            }
        }
    }
}
