using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The current errors and warnings, looked up by the control that shows them (<see cref="WindowFields"/>), so
    /// each message appears next to its field, and none is lost: what no control covers is listed at the Create step.
    /// </summary>
    public sealed class FieldProblems
    {
        public static readonly FieldProblems None = new FieldProblems(null, null);

        public FieldProblems(IEnumerable<ValidationProblem> errors, IEnumerable<ValidationProblem> warnings)
        {
            Errors = (errors ?? Enumerable.Empty<ValidationProblem>()).Where(p => p != null).ToList();
            Warnings = (warnings ?? Enumerable.Empty<ValidationProblem>()).Where(p => p != null).ToList();
        }

        public IReadOnlyList<ValidationProblem> Errors { get; }
        public IReadOnlyList<ValidationProblem> Warnings { get; }
        public bool HasErrors => Errors.Count > 0;

        public IReadOnlyList<ValidationProblem> ErrorsFor(string controlField) => Errors.Where(p => WindowFields.Covers(controlField, p.Field)).ToList();

        public IReadOnlyList<ValidationProblem> WarningsFor(string controlField) => Warnings.Where(p => WindowFields.Covers(controlField, p.Field)).ToList();

        /// <summary>
        /// Errors about <paramref name="controlField"/> that none of <paramref name="shownElsewhere"/> covers: what a
        /// section lists at its end when its own fields (drawn above) show their problems under them.
        /// </summary>
        public IReadOnlyList<ValidationProblem> ErrorsFor(string controlField, IEnumerable<string> shownElsewhere) => Rest(Errors, controlField, shownElsewhere);

        /// <summary>Warnings about <paramref name="controlField"/> that none of <paramref name="shownElsewhere"/> covers.</summary>
        public IReadOnlyList<ValidationProblem> WarningsFor(string controlField, IEnumerable<string> shownElsewhere) => Rest(Warnings, controlField, shownElsewhere);

        static IReadOnlyList<ValidationProblem> Rest(IEnumerable<ValidationProblem> problems, string controlField, IEnumerable<string> shownElsewhere)
        {
            if (shownElsewhere == null) throw new ArgumentNullException(nameof(shownElsewhere));
            var others = shownElsewhere.ToList();
            return problems.Where(p => WindowFields.Covers(controlField, p.Field) && !others.Any(f => WindowFields.Covers(f, p.Field))).ToList();
        }

        /// <summary>Errors and warnings about any of <paramref name="controlFields"/> (e.g. the parameters inside a closed foldout).</summary>
        public IReadOnlyList<ValidationProblem> ErrorsForAny(IEnumerable<string> controlFields)
        {
            var fields = controlFields.ToList();
            return Errors.Where(p => fields.Any(f => WindowFields.Covers(f, p.Field))).ToList();
        }

        /// <summary>Problems (errors, then warnings) that no control among <paramref name="controlFields"/> shows.</summary>
        public IReadOnlyList<ValidationProblem> NotCoveredBy(IEnumerable<string> controlFields)
        {
            if (controlFields == null) throw new ArgumentNullException(nameof(controlFields));
            var fields = controlFields.ToList();
            return Errors.Concat(Warnings).Where(p => !fields.Any(f => WindowFields.Covers(f, p.Field))).ToList();
        }

        public bool StepHasErrors(WindowStep step) => Errors.Any(p => WindowFields.StepOf(p.Field) == step);

        /// <summary>The first step (in the window's order) with an error, or null when everything is valid.</summary>
        public WindowStep? FirstIncompleteStep()
        {
            foreach (WindowStep step in Enum.GetValues(typeof(WindowStep)))
                if (StepHasErrors(step)) return step;
            return null;
        }
    }
}
