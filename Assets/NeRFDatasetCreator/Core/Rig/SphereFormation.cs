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
    public sealed class SphereFormation : ICameraFormation
    {
        public string Kind => "sphere";

        public IReadOnlyList<ValidationProblem> Validate(string fieldPrefix) => Array.Empty<ValidationProblem>();

        public IReadOnlyList<SphericalDirection> Directions(int count)
        {
            FormationMath.ThrowIfInvalid(this, count);
            var directions = new SphericalDirection[count];
            for (var i = 0; i < count; i++)
            {
                var height = 1.0 - 2.0 * (i + 0.5) / count;
                var azimuth = FormationMath.WrapRadians(2 * Math.PI * i / FormationMath.GoldenRatio);
                directions[i] = new SphericalDirection(azimuth, FormationMath.SafeAsin(height));
            }
            return directions;
        }
    }
}
