using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A path around the target, like nerf_synthetic's test views: <see cref="Turns"/> turns of azimuth while the
    /// elevation swings once from high to low and back. The swing is sampled at phase 2π(i + ¼)/N: two views share
    /// an elevation only if i + j + ½ is a multiple of N, which no whole numbers satisfy, so no two views ever
    /// coincide whatever N and the turns. (Sampling at i/N, as nerf_synthetic's script does, puts views N/4 and 3N/4
    /// of a two-turn path on the same spot; (i + ½)/N does the same when N ≡ 2 mod 4.)
    /// </summary>
    [Serializable]
    public sealed class OrbitFormation : ICameraFormation, IIndexedFormation
    {
        public OrbitFormation(double turns = 2, double lowElevationDegrees = 15, double highElevationDegrees = 40, double startAzimuthDegrees = 0)
        {
            Turns = turns;
            LowElevationDegrees = lowElevationDegrees;
            HighElevationDegrees = highElevationDegrees;
            StartAzimuthDegrees = startAzimuthDegrees;
        }

        /// <summary>Turns around the target over the whole path, in (0, 100].</summary>
        public double Turns { get; }

        public double LowElevationDegrees { get; }
        public double HighElevationDegrees { get; }
        public double StartAzimuthDegrees { get; }

        public string Kind => "orbit";

        public IReadOnlyList<ValidationProblem> Validate(string fieldPrefix)
        {
            ValidationProblem turns = null;
            if (!(Turns > 0 && Turns <= 100))
                turns = new ValidationProblem("turns", ValidationProblem.Format(Turns), "must be more than 0 and at most 100.",
                    "Use e.g. 1 for one circle or 2 like nerf_synthetic's test path.");
            var low = FormationMath.CheckOpenElevation("lowElevationDegrees", LowElevationDegrees);
            var high = FormationMath.CheckOpenElevation("highElevationDegrees", HighElevationDegrees);
            if (low == null && high == null && LowElevationDegrees > HighElevationDegrees)
                low = new ValidationProblem("lowElevationDegrees", ValidationProblem.Format(LowElevationDegrees),
                    "is above highElevationDegrees (" + ValidationProblem.Format(HighElevationDegrees) + ").",
                    "Make the low elevation lower than or equal to the high one.");
            return FormationMath.Collect(fieldPrefix, turns, low, high,
                ValidationProblem.OutsideRange("startAzimuthDegrees", StartAzimuthDegrees, -360, 360, "degrees"));
        }

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
            var low = LowElevationDegrees * FormationMath.DegToRad;
            var high = HighElevationDegrees * FormationMath.DegToRad;
            var start = StartAzimuthDegrees * FormationMath.DegToRad;
            var t = (index + 0.25) / count;
            var elevation = low + (high - low) * (1 + Math.Cos(2 * Math.PI * t)) / 2;
            var azimuth = FormationMath.WrapRadians(start + 2 * Math.PI * Turns * index / count);
            return new SphericalDirection(azimuth, elevation);
        }
    }
}
