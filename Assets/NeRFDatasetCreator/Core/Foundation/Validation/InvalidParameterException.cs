using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>Thrown by Core when a parameter is out of range; the message names each parameter, its value and the valid range.</summary>
    public sealed class InvalidParameterException : ArgumentException
    {
        public InvalidParameterException(IReadOnlyList<ValidationProblem> problems)
            : base(string.Join(Environment.NewLine, problems.Select(p => p.ToString())))
        {
            Problems = problems;
        }

        public IReadOnlyList<ValidationProblem> Problems { get; }

        /// <summary>Throws when any of <paramref name="problems"/> is not null.</summary>
        public static void ThrowIfAny(params ValidationProblem[] problems)
        {
            var real = problems.Where(p => p != null).ToList();
            if (real.Count > 0) throw new InvalidParameterException(real);
        }
    }
}
