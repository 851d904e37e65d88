using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Golden-ratio (Fibonacci) sampling of the whole sphere with its pole on world up: heights
    /// sin e = 1 − 2(i + ½)/N, which are area-uniform (Archimedes), and azimuths 2π·i/φ. The half offset treats
    /// both poles alike and never puts a camera exactly on one (the original sampled i/N on a horizontal axis).
    /// </summary>
    [Serializable]
    public sealed class SphereFormation : ICameraFormation, IIndexedFormation
    {
        public string Kind => "sphere";

        public IReadOnlyList<ValidationProblem> Validate(string fieldPrefix) => Array.Empty<ValidationProblem>();

        public IReadOnlyList<SphericalDirection> Directions(int count)
        {
            FormationMath.ThrowIfInvalid(this, count);
            var directions = new SphericalDirection[count];
            for (var i = 0; i < count; i++) directions[i] = Direction(i, count);
            return directions;
        }

        /// <summary>Direction <paramref name="index"/> of <paramref name="count"/> alone (a plan regenerates views on demand).</summary>
        public SphericalDirection Direction(int index, int count)
        {
            var height = 1.0 - 2.0 * (index + 0.5) / count;
            var azimuth = FormationMath.WrapRadians(2 * Math.PI * index / FormationMath.GoldenRatio);
            return new SphericalDirection(azimuth, FormationMath.SafeAsin(height));
        }
    }
}
