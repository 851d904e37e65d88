using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Seeded uniform random directions on the sphere or on the upper hemisphere, like nerf_synthetic's train and
    /// val views: heights uniform in [−1, 1) or [0, 1) (area-uniform), azimuths uniform.
    /// </summary>
    [Serializable]
    public sealed class RandomFormation : ICameraFormation, IIndexedFormation
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
            var directions = new SphericalDirection[count];
            for (var i = 0; i < count; i++) directions[i] = Direction(i, count);
            return directions;
        }

        /// <summary>
        /// Direction <paramref name="index"/> alone: it uses draws 2i and 2i + 1 of the seed's stream, which SplitMix64
        /// reaches without drawing the ones before (<see cref="SeededRandom.AtDraw"/>), so a plan regenerates any view in
        /// constant time. The count does not matter to this formation.
        /// </summary>
        public SphericalDirection Direction(int index, int count)
        {
            var random = SeededRandom.AtDraw(Seed, 2L * index);
            var lowest = UpperHemisphereOnly ? 0.0 : -1.0;
            var height = lowest + (1.0 - lowest) * random.NextDouble();
            var azimuth = 2 * Math.PI * random.NextDouble();
            return new SphericalDirection(azimuth, FormationMath.SafeAsin(height));
        }
    }
}
