using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A path around the target, like nerf_synthetic's test views: <see cref="Turns"/> turns of azimuth while the
    /// elevation swings once from high to low and back. The swing is sampled at (i + ½)/N so that, with an even
    /// number of turns, the two passes through the middle elevation never fall on the same spot.
    /// </summary>
    [Serializable]
    public sealed class OrbitFormation : ICameraFormation
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
            var low = LowElevationDegrees * FormationMath.DegToRad;
            var high = HighElevationDegrees * FormationMath.DegToRad;
            var start = StartAzimuthDegrees * FormationMath.DegToRad;
            var directions = new SphericalDirection[count];
            for (var i = 0; i < count; i++)
            {
                var t = (i + 0.5) / count;
                var elevation = low + (high - low) * (1 + Math.Cos(2 * Math.PI * t)) / 2;
                var azimuth = FormationMath.WrapRadians(start + 2 * Math.PI * Turns * i / count);
                directions[i] = new SphericalDirection(azimuth, elevation);
            }
            return directions;
        }
    }
}
