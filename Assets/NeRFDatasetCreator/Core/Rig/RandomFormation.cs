using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Seeded uniform random directions on the sphere or on the upper hemisphere, like nerf_synthetic's train and
    /// val views: heights uniform in [−1, 1) or [0, 1) (area-uniform), azimuths uniform.
    /// </summary>
    [Serializable]
    public sealed class RandomFormation : ICameraFormation
    {
        public RandomFormation(long seed, bool upperHemisphereOnly = true)
        {
            Seed = seed;
            UpperHemisphereOnly = upperHemisphereOnly;
        }

        public long Seed { get; }
        public bool UpperHemisphereOnly { get; }

        public string Kind => "random";

        public IReadOnlyList<ValidationProblem> Validate(string fieldPrefix) => Array.Empty<ValidationProblem>();

        public IReadOnlyList<SphericalDirection> Directions(int count)
        {
            FormationMath.ThrowIfInvalid(this, count);
            var random = new SeededRandom(Seed);
            var directions = new SphericalDirection[count];
            var lowest = UpperHemisphereOnly ? 0.0 : -1.0;
            for (var i = 0; i < count; i++)
            {
                var height = lowest + (1.0 - lowest) * random.NextDouble();
                var azimuth = 2 * Math.PI * random.NextDouble();
                directions[i] = new SphericalDirection(azimuth, FormationMath.SafeAsin(height));
            }
            return directions;
        }
    }
}
