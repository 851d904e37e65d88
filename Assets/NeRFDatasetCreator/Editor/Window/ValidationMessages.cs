using System.Collections.Generic;
using UnityEditor;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Draws Core's problems as help boxes right under the control they are about.</summary>
    static class ValidationMessages
    {
        /// <summary>The errors, then the warnings, about <paramref name="field"/> (and its parts).</summary>
        public static void For(WindowContext context, string field)
        {
            Show(context.Problems.ErrorsFor(field), MessageType.Error);
            Show(context.Problems.WarningsFor(field), MessageType.Warning);
        }

        /// <summary>
        /// The errors, then the warnings, about <paramref name="field"/> that none of <paramref name="shownElsewhere"/>
        /// covers: a section's own fields show theirs under them, and the rest is listed once, at the section's end.
        /// </summary>
        public static void Rest(WindowContext context, string field, IEnumerable<string> shownElsewhere, bool withField = false)
        {
            var others = new List<string>(shownElsewhere);
            Show(context.Problems.ErrorsFor(field, others), MessageType.Error, withField);
            Show(context.Problems.WarningsFor(field, others), MessageType.Warning, withField);
        }

        public static void Show(IReadOnlyList<ValidationProblem> problems, MessageType type, bool withField = false)
        {
            foreach (var problem in problems)
                EditorGUILayout.HelpBox(withField ? WindowText.ProblemWithField(problem) : WindowText.Problem(problem), type);
        }
    }
}
