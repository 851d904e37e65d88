using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A way of spreading cameras around a target: it yields unit directions from the target, and
    /// <see cref="CameraRig"/> turns them into poses at an exact distance.
    /// </summary>
    public interface ICameraFormation
    {
        /// <summary>The formation's name in settings files and the window ("halo", "sphere", …).</summary>
        string Kind { get; }

        /// <summary>Every parameter problem, with field names under <paramref name="fieldPrefix"/>; empty when valid.</summary>
        IReadOnlyList<ValidationProblem> Validate(string fieldPrefix);

        /// <summary>
        /// <paramref name="count"/> directions in a fixed order. Throws <see cref="InvalidParameterException"/>
        /// when a parameter or the count is out of range.
        /// </summary>
        IReadOnlyList<SphericalDirection> Directions(int count);
    }
}
