using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A split's formation and its parameters. One flat object holds the parameters of every kind so that the
    /// window can switch kinds without losing values; only the parameters of <see cref="Kind"/> are written to a
    /// config file and used.
    /// </summary>
    [Serializable]
    public sealed class FormationSettings
    {
        public FormationKind Kind = FormationKind.SemiSphere;

        // halo
        public double ElevationDegrees = 0;

        // halo and orbit
        public double StartAzimuthDegrees = 0;

        // semisphere
        public double TopElevationDegrees = 90;
        public double BottomElevationDegrees = 0;
        public double SpiralRatio = 0;

        // random (its seed is derived from the dataset seed and the split name)
        public bool UpperHemisphereOnly = true;

        // orbit
        public double Turns = 2;
        public double LowElevationDegrees = 15;
        public double HighElevationDegrees = 40;

        public FormationSettings Clone() => (FormationSettings)MemberwiseClone();

        /// <summary>The config-file names of the parameters that <paramref name="kind"/> uses, in file order.</summary>
        public static IReadOnlyList<string> ParameterNames(FormationKind kind)
        {
            switch (kind)
            {
                case FormationKind.Halo: return new[] { "elevationDegrees", "startAzimuthDegrees" };
                case FormationKind.Sphere: return Array.Empty<string>();
                case FormationKind.SemiSphere: return new[] { "topElevationDegrees", "bottomElevationDegrees", "spiralRatio" };
                case FormationKind.Random: return new[] { "upperHemisphereOnly" };
                case FormationKind.Orbit: return new[] { "turns", "lowElevationDegrees", "highElevationDegrees", "startAzimuthDegrees" };
                default: throw new ArgumentOutOfRangeException(nameof(kind));
            }
        }

        /// <summary>
        /// The formation these settings describe. A random formation's seed is
        /// <c>SeededRandom.Derive(datasetSeed, splitName)</c>, so the splits draw independent views from one seed.
        /// </summary>
        public ICameraFormation ToFormation(long datasetSeed, string splitName)
        {
            switch (Kind)
            {
                case FormationKind.Halo: return new HaloFormation(ElevationDegrees, StartAzimuthDegrees);
                case FormationKind.Sphere: return new SphereFormation();
                case FormationKind.SemiSphere: return new SemiSphereFormation(TopElevationDegrees, BottomElevationDegrees, SpiralRatio);
                case FormationKind.Random: return new RandomFormation(SeededRandom.Derive(datasetSeed, splitName), UpperHemisphereOnly);
                case FormationKind.Orbit: return new OrbitFormation(Turns, LowElevationDegrees, HighElevationDegrees, StartAzimuthDegrees);
                default: throw new ArgumentOutOfRangeException(nameof(Kind), Kind, "not a formation kind");
            }
        }

        /// <summary>
        /// The azimuth step between consecutive cameras in radians, written as nerf_synthetic's <c>rotation</c> key
        /// (which every loader ignores); 0 where the formation has no constant step (sphere, random).
        /// </summary>
        public double AzimuthStepRadians(int count)
        {
            switch (Kind)
            {
                case FormationKind.Halo: return count > 0 ? 2 * Math.PI / count : 0;
                case FormationKind.SemiSphere: return 2 * Math.PI * (SpiralRatio == 0 ? (1 + Math.Sqrt(5)) / 2 : SpiralRatio);
                case FormationKind.Orbit: return count > 0 ? 2 * Math.PI * Turns / count : 0;
                default: return 0;
            }
        }
    }
}
