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

        public static void Show(IReadOnlyList<ValidationProblem> problems, MessageType type, bool withField = false)
        {
            foreach (var problem in problems)
                EditorGUILayout.HelpBox(withField ? WindowText.ProblemWithField(problem) : WindowText.Problem(problem), type);
        }
    }
}
